#include "solve/subdivision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace octocap::internal {
namespace {

struct Cube {
  Eigen::Vector3d lo;
  int support = 0;
  double score = 0;  // summed squared angular distance of the centre to the supporting rays (lower is better)
  uint64_t mask = 0;
};

struct PreparedRay {
  Eigen::Vector3d origin, dir, inv_dir;
  double tol_angle;  // pixel tolerance as an angle
  int view;
};

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

bool ray_meets_box(const Eigen::Vector3d& origin, const Eigen::Vector3d& inv_dir, const Eigen::Vector3d& lo,
                   const Eigen::Vector3d& hi, double margin) {
  double tmin = 0.0, tmax = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double t1 = (lo[k] - margin - origin[k]) * inv_dir[k];
    double t2 = (hi[k] + margin - origin[k]) * inv_dir[k];
    if (t1 > t2) std::swap(t1, t2);
    tmin = std::max(tmin, t1);
    tmax = std::min(tmax, t2);
    if (tmin > tmax) return false;
  }
  return true;
}

bool hull_contains_detection(const Camera& cam, const Eigen::AlignedBox3d& cube, const Eigen::Vector2d& normalized) {
  std::vector<Eigen::Vector2d> pts;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d corner = cube.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
    const Eigen::Vector3d p = cam.to_camera(corner);
    if (p.z() <= 1e-9) {
      // A corner behind the camera has no image; the ray statement is the one that still holds.
      const Eigen::Vector3d d = cam.R.transpose() * Eigen::Vector3d(normalized.x(), normalized.y(), 1.0);
      return ray_meets_box(cam.center(), d.cwiseInverse(), cube.min(), cube.max(), 0.0);
    }
    pts.emplace_back(p.x() / p.z(), p.y() / p.z());
  }
  // Andrew's monotone chain.
  std::sort(pts.begin(), pts.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Eigen::Vector2d> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross2(hull[k - 2], hull[k - 1], pts[i - 1]) <= 0) --k;
    hull[k++] = pts[i - 1];
  }
  hull.resize(k - 1);  // counter-clockwise, last point repeats the first
  for (size_t i = 0; i < hull.size(); ++i)
    if (cross2(hull[i], hull[(i + 1) % hull.size()], normalized) < 0) return false;
  return true;
}

namespace {

// One descent with a fixed support requirement. Returns false when no cube of the volume is supported, or
// when the descent stopped (N_cube < need everywhere) while the cubes were still coarser than `converged`:
// the mean of such cubes would be a guess, not a measurement.
bool descend(const std::vector<PreparedRay>& prepared, const SubdivisionParams& params, int need,
             double tolerance_scale, Eigen::Vector3d& position, uint64_t& mask) {
  const int n = static_cast<int>(prepared.size());
  std::vector<Cube> current{{params.volume.min(), 0, 0, 0}}, next;
  Eigen::Vector3d size = params.volume.sizes();
  bool first_level = true;
  while (first_level || size.maxCoeff() >= params.delta) {
    const Eigen::Vector3d half = size * 0.5;
    next.clear();
    for (const Cube& parent : current) {
      for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d lo = parent.lo + Eigen::Vector3d((c & 1) * half.x(), (c >> 1 & 1) * half.y(),
                                                               (c >> 2 & 1) * half.z());
        const Eigen::Vector3d hi = lo + half;
        const Eigen::Vector3d centre = lo + 0.5 * half;
        Cube cube{lo, 0, 0.0, 0};
        for (int i = 0; i < n; ++i) {
          if (cube.support + (n - i) < need) break;  // cannot reach sigma any more
          const PreparedRay& r = prepared[i];
          const Eigen::Vector3d oc = centre - r.origin;
          const double depth = oc.dot(r.dir);
          const double margin = tolerance_scale * r.tol_angle * std::max(depth, 0.0);
          if (!ray_meets_box(r.origin, r.inv_dir, lo, hi, margin)) continue;
          ++cube.support;
          cube.mask |= uint64_t{1} << r.view;
          const double perp2 = (oc - depth * r.dir).squaredNorm();
          cube.score += perp2 / std::max(depth * depth, 1e-12);
        }
        if (cube.support >= need) next.push_back(cube);
      }
    }
    if (next.empty()) {
      if (first_level) return false;  // no cube of the volume is supported
      break;                          // N_cube < sigma everywhere: the previous level's cubes are the answer
    }
    if (next.size() > static_cast<size_t>(params.max_candidates)) {
      std::partial_sort(next.begin(), next.begin() + params.max_candidates, next.end(),
                        [](const Cube& a, const Cube& b) {
                          return a.support != b.support ? a.support > b.support : a.score < b.score;
                        });
      next.resize(params.max_candidates);
    }
    current.swap(next);
    size = half;
    first_level = false;
  }
  if (size.maxCoeff() >= 4 * params.delta) return false;

  // Clustering: mean of the surviving candidates' centres. Only the best-supported ones are averaged, so a
  // stray pair of rays (a wrong detection meeting a right one) cannot pull the mean when sigma is low.
  int best = 0;
  for (const Cube& c : current) best = std::max(best, c.support);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  mask = 0;
  for (const Cube& c : current) {
    if (c.support != best) continue;
    sum += c.lo + 0.5 * size;
    mask |= c.mask;
    ++count;
  }
  position = sum / count;
  return true;
}

}  // namespace

PointResult solve_subdivision(const Calibration& calib, const std::vector<ViewRay>& rays,
                              const SubdivisionParams& params) {
  PointResult result;
  const int n = static_cast<int>(rays.size());
  if (n < params.min_views || n == 0 || params.volume.isEmpty()) return result;

  // Most confident views first: a cube that fails them is culled before the weak views are tested.
  std::vector<const ViewRay*> order;
  for (const auto& r : rays) order.push_back(&r);
  std::stable_sort(order.begin(), order.end(),
                   [](const ViewRay* a, const ViewRay* b) { return a->confidence > b->confidence; });
  std::vector<PreparedRay> prepared;
  prepared.reserve(rays.size());
  for (const ViewRay* r : order) {
    Eigen::Vector3d d = r->direction;
    for (int k = 0; k < 3; ++k)
      if (std::abs(d[k]) < 1e-30) d[k] = 1e-30;
    prepared.push_back({r->origin, r->direction, d.cwiseInverse(),
                        params.pixel_tolerance / calib[r->view].focal(), r->view});
  }

  // sigma as configured (clamped to the views that saw the joint). Real detections of one joint disagree
  // across views by more than a few pixels now and then (a hip is not a crisp point), so a descent that
  // stalls is retried with a doubled tolerance, up to the outlier threshold. When wrong detections leave no
  // cube with that support, one fewer view is asked for, down to min_views. Below that the joint is
  // reported missing.
  const double max_scale = params.pixel_tolerance > 0
                               ? std::max(1.0, 1.1 * params.max_reprojection_error_px / params.pixel_tolerance)
                               : 1.0;
  for (int need = std::clamp(params.sigma, params.min_views, n); need >= params.min_views; --need) {
    for (double scale = 1.0; scale <= max_scale; scale *= 2) {
      Eigen::Vector3d position;
      uint64_t mask = 0;
      if (!descend(prepared, params, need, scale, position, mask)) continue;
      // Views that supported only some of the averaged cubes and disagree with the answer are not counted.
      int kept = 0;
      for (const ViewRay& ray : rays) {
        if (!(mask >> ray.view & 1u)) continue;
        // Written as "not within": a NaN reprojection (a degenerate camera) rejects the view too.
        if (!((calib[ray.view].project(position) - ray.pixel).norm() <= params.max_reprojection_error_px))
          mask &= ~(uint64_t{1} << ray.view);
        else
          ++kept;
      }
      if (kept < need) continue;
      PointResult r;
      r.position = position;
      r.valid = true;
      score_point(calib, rays, mask, r);
      return r;
    }
  }
  return result;
}

}  // namespace octocap::internal
