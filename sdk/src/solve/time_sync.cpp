#include "solve/time_sync.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/stats.h"

namespace octocap::internal {
namespace {

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

}  // namespace

SyncEstimate estimate_time_offsets(const Calibration& calib,
                                   const std::vector<std::vector<std::vector<Person2D>>>& frames, const SyncOptions& o) {
  const size_t V = calib.size(), F = frames.size();
  if (!(o.max_offset_frames >= 0 && o.max_offset_frames <= 100000))  // NaN fails too
    throw Error(Errc::invalid_argument, "max_offset_frames must be 0 .. 100000");
  for (const auto& f : frames)
    if (f.size() != V)
      throw Error(Errc::invalid_argument, "a frame has " + std::to_string(f.size()) + " views, the calibration has " +
                                              std::to_string(V) + " cameras");
  SyncEstimate out;
  out.offset_frames.assign(V, 0);
  out.residual_px.assign(V, 0);
  if (F == 0 || V < 2) return out;
  // Normalised coordinates once: distortion is undone per keypoint, not per offset tried.
  std::vector<std::vector<std::vector<std::vector<Eigen::Vector2d>>>> norm(
      F, std::vector<std::vector<std::vector<Eigen::Vector2d>>>(V));
  for (size_t f = 0; f < F; ++f)
    for (size_t v = 0; v < V; ++v)
      for (const Person2D& p : frames[f][v]) {
        std::vector<Eigen::Vector2d> n;
        for (const Keypoint2D& k : p)
          n.push_back(k.confidence >= o.min_confidence ? calib[v].pixel_to_normalized({k.x, k.y})
                                                       : Eigen::Vector2d::Constant(std::nan("")));
        norm[f][v].push_back(std::move(n));
      }
  const int max_shift = static_cast<int>(std::min<double>(o.max_offset_frames, static_cast<double>(F) / 2));
  // cost[a][b][shift]: camera b's frame f + shift against camera a's frame f. Per frame the pair of people (one per
  // view) that agrees best counts (bystanders and wrong picks never beat the right pair); the median over frames.
  auto pair_cost = [&](size_t a, size_t b, int shift) {
    const PairGeometry g = pair_geometry(calib[a], calib[b]);
    std::vector<double> per_frame, d;
    size_t pairs = 0;
    for (size_t f = 0; f < F; ++f) {
      const long fb = static_cast<long>(f) + shift;
      if (fb < 0 || fb >= static_cast<long>(F)) continue;
      double best = kInf;
      size_t best_n = 0;
      for (const auto& pa : norm[f][a])
        for (const auto& pb : norm[static_cast<size_t>(fb)][b]) {
          d.clear();
          for (size_t k = 0; k < std::min(pa.size(), pb.size()); ++k)
            if (pa[k].allFinite() && pb[k].allFinite()) d.push_back(epipolar_px(g, pa[k], pb[k]));
          if (d.size() < 5) continue;
          const double m = median_or_inf(d);
          if (m < best) best = m, best_n = d.size();
        }
      if (best_n == 0) continue;
      per_frame.push_back(best);
      pairs += best_n;
    }
    return pairs >= kMinPairs ? median_or_inf(per_frame) : kInf;
  };
  struct Relative {
    double shift = 0;   // b's frame f + shift shows a's frame f
    double cost = kInf;
  };
  // The whole-frame minimum, refined by fitting a symmetric V through it and its neighbours: the cost grows with
  // the time error on either side, and unlike interpolating keypoints (which also averages their noise away and so
  // favours half frames) the fit is unbiased.
  auto relative = [&](size_t a, size_t b) {
    std::vector<double> c(static_cast<size_t>(2 * max_shift + 1));
    for (int s = -max_shift; s <= max_shift; ++s) c[static_cast<size_t>(s + max_shift)] = pair_cost(a, b, s);
    Relative r;
    size_t at = 0;
    for (size_t i = 0; i < c.size(); ++i)
      if (c[i] < r.cost) r.cost = c[i], at = i;
    r.shift = static_cast<double>(at) - max_shift;
    if (at > 0 && at + 1 < c.size() && std::isfinite(c[at - 1]) && std::isfinite(c[at + 1])) {
      const double rise = std::max(c[at - 1], c[at + 1]) - c[at];
      if (rise > 1e-9) r.shift += std::clamp((c[at - 1] - c[at + 1]) / (2 * rise), -0.5, 0.5);
    }
    return r;
  };
  // Cameras are placed one by one, each against the placed camera it agrees with best: a pair that sees the person
  // badly (near an epipole, a short baseline) does not decide an offset another pair decides better.
  std::vector<bool> placed(V, false);
  placed[0] = true;
  std::vector<std::vector<Relative>> rel(V, std::vector<Relative>(V));
  for (size_t a = 0; a < V; ++a)
    for (size_t b = a + 1; b < V; ++b) {
      rel[a][b] = relative(a, b);
      rel[b][a] = {-rel[a][b].shift, rel[a][b].cost};
    }
  for (size_t n = 1; n < V; ++n) {
    size_t best_a = 0, best_b = 0;
    double best = kInf;
    for (size_t a = 0; a < V; ++a)
      for (size_t b = 0; b < V; ++b)
        if (placed[a] && !placed[b] && rel[a][b].cost < best) best = rel[a][b].cost, best_a = a, best_b = b;
    if (!std::isfinite(best)) {
      size_t missing = 0;
      while (placed[missing]) ++missing;
      throw Error(Errc::not_enough_views, "camera " + calib[missing].name + " never shares " +
                                              std::to_string(kMinPairs) + " confident keypoints with another camera at "
                                              "any offset: it cannot be placed in time");
    }
    // b's frame f + shift shows a's frame f: b's frame i was taken at i - shift on a's clock.
    out.offset_frames[best_b] = out.offset_frames[best_a] - rel[best_a][best_b].shift;
    out.residual_px[best_b] = best;
    placed[best_b] = true;
  }
  // Every pair measured an offset difference: all of them, weighted by how well the pair agrees (1 / cost^2), fix
  // the offsets together by least squares, so no single chain of pairs carries its errors to the end. Pairs whose
  // difference disagrees with the placement by more than 1.5 frames (a flat or wrong minimum) are left out.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(V - 1), static_cast<Eigen::Index>(V - 1));
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(V - 1));
  for (size_t a = 0; a < V; ++a)
    for (size_t b = a + 1; b < V; ++b) {
      const Relative& r = rel[a][b];
      if (!std::isfinite(r.cost)) continue;
      const double measured = -r.shift;  // o_b - o_a
      if (std::abs(out.offset_frames[b] - out.offset_frames[a] - measured) > 1.5) continue;
      const double w = 1.0 / std::max(r.cost * r.cost, 1e-6);
      // w (o_b - o_a - measured)^2, o_0 fixed at 0.
      const Eigen::Index ia = static_cast<Eigen::Index>(a) - 1, ib = static_cast<Eigen::Index>(b) - 1;
      if (ia >= 0) A(ia, ia) += w, rhs(ia) -= w * measured;
      if (ib >= 0) A(ib, ib) += w, rhs(ib) += w * measured;
      if (ia >= 0 && ib >= 0) A(ia, ib) -= w, A(ib, ia) -= w;
    }
  const Eigen::VectorXd x = A.ldlt().solve(rhs);
  if (x.allFinite() && (A * x - rhs).norm() <= 1e-6 * (1 + rhs.norm()))
    for (size_t c = 1; c < V; ++c) out.offset_frames[c] = x(static_cast<Eigen::Index>(c - 1));
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

}  // namespace octocap::internal
