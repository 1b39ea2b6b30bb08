#include "solve/time_sync.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace octocap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr size_t kMinPairs = 30;  // fewer shared keypoints than this cannot place a camera in time

struct PairGeometry {
  Eigen::Matrix3d E;  // essential matrix a -> b (normalised coordinates)
  double focal_a, focal_b;
};

PairGeometry pair_geometry(const Camera& a, const Camera& b) {
  const Eigen::Matrix3d R = b.R * a.R.transpose();
  const Eigen::Vector3d t = b.t - R * a.t;
  Eigen::Matrix3d tx;
  tx << 0, -t.z(), t.y(), t.z(), 0, -t.x(), -t.y(), t.x(), 0;
  return {tx * R, 0.5 * (a.K(0, 0) + a.K(1, 1)), 0.5 * (b.K(0, 0) + b.K(1, 1))};
}

// Symmetric epipolar distance in pixels of one correspondence (normalised coordinates in, focal lengths scale).
double epipolar_px(const PairGeometry& g, const Eigen::Vector2d& na, const Eigen::Vector2d& nb) {
  const Eigen::Vector3d xa(na.x(), na.y(), 1), xb(nb.x(), nb.y(), 1);
  const Eigen::Vector3d lb = g.E * xa, la = g.E.transpose() * xb;
  const double nb2 = std::hypot(lb.x(), lb.y()), na2 = std::hypot(la.x(), la.y());
  if (nb2 < 1e-12 || na2 < 1e-12) return kInf;
  const double e = xb.dot(lb);
  return 0.5 * (std::abs(e) / nb2 * g.focal_b + std::abs(e) / na2 * g.focal_a);
}

double median(std::vector<double>& v) {
  if (v.empty()) return kInf;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

// The people of view v at a fractional frame of its own clock: paired by order between the two nearest frames when
// both hold as many, else the nearer frame's.
static std::vector<Person2D> people_at(const std::vector<std::vector<std::vector<Person2D>>>& frames, size_t v, double frame,
                                double min_conf) {
  if (!(frame >= 0) || frame > static_cast<double>(frames.size() - 1)) return {};
  const size_t f0 = static_cast<size_t>(std::floor(frame));
  const size_t f1 = std::min(f0 + 1, frames.size() - 1);
  const double w = frame - static_cast<double>(f0);
  const auto& a = frames[f0][v];
  const auto& b = frames[f1][v];
  if (w < 1e-9 || a.size() != b.size()) return w < 0.5 ? a : b;
  std::vector<Person2D> out;
  for (size_t p = 0; p < a.size(); ++p) out.push_back(interpolate_person(a[p], b[p], w, min_conf));
  return out;
}

SyncEstimate estimate_time_offsets(const Calibration& calib,
                                   const std::vector<std::vector<std::vector<Person2D>>>& frames, const SyncOptions& o) {
  const size_t V = calib.size(), F = frames.size();
  for (const auto& f : frames)
    if (f.size() != V)
      throw Error(Errc::invalid_argument, "a frame has " + std::to_string(f.size()) + " views, the calibration has " +
                                              std::to_string(V) + " cameras");
  SyncEstimate out;
  out.offset_frames.assign(V, 0);
  out.residual_px.assign(V, 0);
  if (F == 0) return out;
  // The first camera's keypoints as normalised coordinates once; distortion is undone per keypoint.
  auto normalise = [&](size_t v, const Person2D& p) {
    std::vector<Eigen::Vector2d> n;
    for (const Keypoint2D& k : p)
      n.push_back(k.confidence >= o.min_confidence ? calib[v].pixel_to_normalized({k.x, k.y})
                                                   : Eigen::Vector2d::Constant(std::nan("")));
    return n;
  };
  std::vector<std::vector<std::vector<Eigen::Vector2d>>> first(F);
  for (size_t f = 0; f < F; ++f)
    for (const Person2D& p : frames[f][0]) first[f].push_back(normalise(0, p));
  for (size_t c = 1; c < V; ++c) {
    const PairGeometry g = pair_geometry(calib[0], calib[c]);
    std::vector<std::vector<std::vector<Eigen::Vector2d>>> other(F);
    for (size_t f = 0; f < F; ++f)
      for (const Person2D& p : frames[f][c]) other[f].push_back(normalise(c, p));
    // Per frame, the pair of people (one per view) that agrees best: bystanders and wrong picks never win over the
    // right pair, and a take with one person is the plain case. The cost is the median over frames.
    auto cost = [&](double shift, bool whole) {
      std::vector<double> per_frame;
      size_t pairs = 0;
      std::vector<double> d;
      for (size_t f = 0; f < F; ++f) {
        if (first[f].empty()) continue;
        const double fc = static_cast<double>(f) + shift;
        if (fc < 0 || fc > static_cast<double>(F - 1)) continue;
        std::vector<std::vector<Eigen::Vector2d>> candidates;
        if (whole) {
          candidates = other[static_cast<size_t>(std::llround(fc))];
        } else {
          for (const Person2D& p : people_at(frames, c, fc, o.min_confidence)) candidates.push_back(normalise(c, p));
        }
        double best = kInf;
        size_t best_n = 0;
        for (const auto& a : first[f])
          for (const auto& b : candidates) {
            d.clear();
            for (size_t k = 0; k < std::min(a.size(), b.size()); ++k)
              if (a[k].allFinite() && b[k].allFinite()) d.push_back(epipolar_px(g, a[k], b[k]));
            if (d.size() < 5) continue;
            const double m = median(d);
            if (m < best) best = m, best_n = d.size();
          }
        if (best_n == 0) continue;
        per_frame.push_back(best);
        pairs += best_n;
      }
      return pairs >= kMinPairs ? median(per_frame) : kInf;
    };
    const int max_shift = static_cast<int>(std::min<double>(o.max_offset_frames, static_cast<double>(F) / 2));
    double best = kInf;
    int best_shift = 0;
    for (int s = -max_shift; s <= max_shift; ++s) {
      const double e = cost(s, true);
      if (e < best) best = e, best_shift = s;
    }
    if (!std::isfinite(best))
      throw Error(Errc::not_enough_views, "camera " + calib[c].name + " never shares " + std::to_string(kMinPairs) +
                                              " confident keypoints with camera " + calib[0].name +
                                              " at any offset: it cannot be placed in time");
    double fine = static_cast<double>(best_shift), fine_cost = kInf;
    for (double s = best_shift - 1.0; s <= best_shift + 1.0 + 1e-9; s += 0.02) {
      const double e = cost(s, false);
      if (e < fine_cost) fine_cost = e, fine = s;
    }
    // Camera c's frame f + shift shows camera 0's frame f: its frame i was taken at i - shift on camera 0's clock.
    out.offset_frames[c] = -fine;
    out.residual_px[c] = fine_cost;
  }
  return out;
}

SyncEstimate estimate_recording_offsets(const Calibration& calib, const OpenPoseRecording& rec, const SyncOptions& o) {
  if (rec.view_count() != calib.size())
    throw Error(Errc::camera_mismatch, "the recording has " + std::to_string(rec.view_count()) +
                                           " views, the calibration " + std::to_string(calib.size()) + " cameras");
  OpenPoseRecording raw = rec;
  raw.set_time_offsets({});
  std::vector<std::vector<std::vector<Person2D>>> frames;
  for (size_t f = 0; f < raw.frame_count(); ++f) frames.push_back(raw.read_frame(f));
  return estimate_time_offsets(calib, frames, o);
}

}  // namespace octocap
