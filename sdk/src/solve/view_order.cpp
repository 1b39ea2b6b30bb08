#include "solve/view_order.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace octocap::internal {
namespace {

// People compared per view: several people multiply the work by this cubed; the first two are enough to tell.
constexpr size_t kPeoplePerView = 2;
// Transfers per frame a 6-view rig of one person costs with every keypoint (6^5 camera and view choices): the budget
// larger rigs and several people keep to by using every stride-th keypoint, a different one each frame.
constexpr double kTransferBudget = 6.0 * 6 * 6 * 6 * 6;
// A transfer carries the noise of three detections: on Pose2Sim's real 1088x1920 take the right order lands 13 % of
// its transfers within 15 px, 52 % within 30 and 95 % within 60, a swapped one 0.1, 0.6 and 2 %. Detector noise
// grows with the picture, so the tolerance does too: this share of the image's diagonal, or the given one if larger.
constexpr double kToleranceOfDiagonal = 0.025;

using Points = std::vector<Eigen::Vector3d>;  // per keypoint; NaN where there is none

// One person's confident keypoints of one view as seen through one camera: world rays.
Points rays_through(const Camera& cam, const Person2D& person, double min_conf, size_t stride, size_t phase) {
  Points out(person.size(), Eigen::Vector3d::Constant(std::nan("")));
  for (size_t k = phase; k < person.size(); k += stride)
    if (person[k].confidence >= min_conf) out[k] = cam.pixel_to_world_ray({person[k].x, person[k].y});
  return out;
}

// Where two rays meet, when they pass within each camera's tolerance of each other in its image, in front of both
// cameras; NaN otherwise.
Eigen::Vector3d meet(const Camera& ca, const Eigen::Vector3d& da, double tol_a, const Camera& cb,
                     const Eigen::Vector3d& db, double tol_b) {
  const Eigen::Vector3d none = Eigen::Vector3d::Constant(std::nan(""));
  if (!da.allFinite() || !db.allFinite()) return none;
  const Eigen::Vector3d w = ca.center() - cb.center();
  const double b = da.dot(db), d = da.dot(w), e = db.dot(w);
  const double denom = 1 - b * b;
  if (denom < 1e-9) return none;  // parallel rays: no point to agree on
  const double s = (b * e - d) / denom, u = (e - b * d) / denom;  // along da from ca, along db from cb
  if (s <= 0 || u <= 0) return none;
  const Eigen::Vector3d pa = ca.center() + s * da, pb = cb.center() + u * db;
  const double gap = (pa - pb).norm();
  if (gap * ca.focal() / s > tol_a || gap * cb.focal() / u > tol_b) return none;
  return 0.5 * (pa + pb);
}

std::string percent(double share) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.0f %%", 100 * share);
  return buf;
}

}  // namespace

ViewOrderCheck::ViewOrderCheck(Calibration calib, double min_confidence, double tolerance_px, size_t frames)
    : calib_(std::move(calib)), n_(calib_.size()), min_conf_(min_confidence),
      frames_wanted_(std::max<size_t>(frames, 1)) {
  for (const Camera& cam : calib_)
    tolerance_.push_back(std::max(tolerance_px, kToleranceOfDiagonal * std::hypot(cam.width, cam.height)));
  if (n_ >= 3 && n_ <= kMaxViews) {
    agree_.assign(n_ * n_ * n_ * n_ * n_ * n_, 0);
    tested_.assign(n_ * n_ * n_, 0);
  }
  best_.resize(n_);
  std::iota(best_.begin(), best_.end(), 0);
}

bool ViewOrderCheck::add(const std::vector<std::vector<Person2D>>& all_people) {
  // Two views cannot be outvoted: a swap there fails to solve, visibly.
  if (decided_ || agree_.empty() || all_people.size() != n_) return false;
  std::vector<std::vector<Person2D>> people(n_);
  size_t views = 0, most = 1;
  for (size_t v = 0; v < n_; ++v) {
    const size_t p = std::min(all_people[v].size(), kPeoplePerView);
    people[v].assign(all_people[v].begin(), all_people[v].begin() + static_cast<std::ptrdiff_t>(p));
    views += p > 0;
    most = std::max(most, p);
  }
  if (views < 3) return false;
  const double cost = std::pow(static_cast<double>(n_), 5) * std::pow(static_cast<double>(most), 3);
  const size_t stride = static_cast<size_t>(std::ceil(cost / kTransferBudget)), phase = frames_ % stride;

  // rays[view][camera][person]
  std::vector<std::vector<std::vector<Points>>> rays(n_, std::vector<std::vector<Points>>(n_));
  for (size_t v = 0; v < n_; ++v)
    for (size_t c = 0; c < n_; ++c)
      for (const Person2D& p : people[v]) rays[v][c].push_back(rays_through(calib_[c], p, min_conf_, stride, phase));
  auto confident = [&](const Person2D& p, size_t k) { return k < p.size() && p[k].confidence >= min_conf_; };

  std::vector<std::vector<Points>> points, pixels;  // [pa][pb]: triangulated; then projected into one camera
  for (size_t a = 0; a < n_; ++a)
    for (size_t b = a + 1; b < n_; ++b) {
      if (people[a].empty() || people[b].empty()) continue;
      const size_t K = std::max(people[a][0].size(), people[b][0].size());
      for (size_t c = 0; c < n_; ++c) {
        if (c == a || c == b || people[c].empty()) continue;
        double tested = 0;
        for (const Person2D& pa : people[a])
          for (const Person2D& pb : people[b])
            for (const Person2D& pc : people[c]) {
              double common = 0;
              for (size_t k = phase; k < K; k += stride)
                common += confident(pa, k) && confident(pb, k) && confident(pc, k);
              tested = std::max(tested, common);
            }
        tested_[(a * n_ + b) * n_ + c] += tested;
      }
      for (size_t ca = 0; ca < n_; ++ca)
        for (size_t cb = 0; cb < n_; ++cb) {
          if (ca == cb) continue;
          points.assign(people[a].size(), std::vector<Points>(people[b].size()));
          for (size_t pa = 0; pa < people[a].size(); ++pa)
            for (size_t pb = 0; pb < people[b].size(); ++pb) {
              const Points& ra = rays[a][ca][pa];
              const Points& rb = rays[b][cb][pb];
              Points& x = points[pa][pb];
              x.assign(std::min(ra.size(), rb.size()), Eigen::Vector3d::Constant(std::nan("")));
              for (size_t k = phase; k < x.size(); k += stride)
                x[k] = meet(calib_[ca], ra[k], tolerance_[ca], calib_[cb], rb[k], tolerance_[cb]);
            }
          for (size_t cc = 0; cc < n_; ++cc) {
            if (cc == ca || cc == cb) continue;
            pixels = points;
            for (auto& row : pixels)
              for (Points& x : row)
                for (size_t k = phase; k < x.size(); k += stride) {
                  if (!x[k].allFinite()) continue;
                  if (calib_[cc].to_camera(x[k]).z() <= 0) {
                    x[k] = Eigen::Vector3d::Constant(std::nan(""));
                    continue;
                  }
                  const Eigen::Vector2d px = calib_[cc].project(x[k]);
                  x[k] = {px.x(), px.y(), 0};
                }
            for (size_t c = 0; c < n_; ++c) {
              if (c == a || c == b || people[c].empty()) continue;
              double best = 0;
              for (const auto& row : pixels)
                for (const Points& x : row)
                  for (const Person2D& pc : people[c]) {
                    double landed = 0;
                    for (size_t k = phase; k < x.size() && k < pc.size(); k += stride)
                      landed += x[k].allFinite() && pc[k].confidence >= min_conf_ &&
                                std::hypot(x[k].x() - pc[k].x, x[k].y() - pc[k].y) <= tolerance_[cc];
                    best = std::max(best, landed);
                  }
              agree_[at(a, b, c, ca, cb, cc)] += best;
            }
          }
        }
    }
  if (++frames_ < frames_wanted_) return false;
  decide();
  return true;
}

void ViewOrderCheck::decide() {
  decided_ = true;
  const double tested = std::accumulate(tested_.begin(), tested_.end(), 0.0);
  if (tested <= 0) return;
  auto score = [&](const std::vector<int>& p) {
    double s = 0;
    for (size_t a = 0; a < n_; ++a)
      for (size_t b = a + 1; b < n_; ++b)
        for (size_t c = 0; c < n_; ++c)
          if (c != a && c != b)
            s += agree_[at(a, b, c, static_cast<size_t>(p[a]), static_cast<size_t>(p[b]), static_cast<size_t>(p[c]))];
    return s;
  };
  std::vector<int> order(n_);
  std::iota(order.begin(), order.end(), 0);
  const double given = score(order);
  double best = given;
  std::vector<int> best_order = order;
  while (std::next_permutation(order.begin(), order.end())) {
    const double s = score(order);
    if (s > best) best = s, best_order = order;
  }
  given_share_ = given / tested;
  best_share_ = best / tested;
  best_ = best_order;
  // A right order lands most transfers (detector noise and occlusion cost some); a wrong one loses every transfer
  // through a view it misplaces. Another order must explain clearly more, not a few transfers of noise.
  if (best_share_ < 1.5 * given_share_ || best_share_ - given_share_ < 0.15) {
    std::iota(best_.begin(), best_.end(), 0);
    best_share_ = given_share_;
    return;
  }
  std::vector<size_t> moved;
  for (size_t v = 0; v < n_; ++v)
    if (best_[v] != static_cast<int>(v)) moved.push_back(v);
  const std::string shares = " (" + percent(given_share_) +
                             " of keypoints triangulated from two views land on a third's as given, " +
                             percent(best_share_) +
                             " so); check the order of the views against the calibration's cameras";
  if (moved.size() == 2 && best_[moved[0]] == static_cast<int>(moved[1])) {
    verdict_ = "cameras " + calib_[moved[0]].name + " and " + calib_[moved[1]].name +
               " look swapped: each one's pictures fit the other's calibration" + shares;
    return;
  }
  verdict_ = "the views look out of the calibration's order:";
  for (size_t i = 0; i < moved.size(); ++i)
    verdict_ += std::string(i ? "," : "") + " the pictures given as " + calib_[moved[i]].name + " fit " +
                calib_[static_cast<size_t>(best_[moved[i]])].name;
  verdict_ += shares;
}

}  // namespace octocap::internal
