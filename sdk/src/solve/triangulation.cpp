#include "solve/triangulation.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace octocap::internal {
namespace {

// Largest reprojection error (px) over the views in mask; infinity if the point is behind a camera.
double worst_error(const Calibration& calib, const std::vector<ViewRay>& rays, uint64_t mask,
                   const Eigen::Vector3d& X, int* worst_view) {
  double worst = 0;
  for (const ViewRay& r : rays) {
    if (!(mask >> r.view & 1u)) continue;
    const Eigen::Vector2d p = calib[r.view].project(X);
    const double e = p.allFinite() ? (p - r.pixel).norm() : std::numeric_limits<double>::infinity();
    if (e >= worst) {
      worst = e;
      if (worst_view) *worst_view = r.view;
    }
  }
  return worst;
}

int popcount(uint64_t m) {
  int n = 0;
  for (; m; m &= m - 1) ++n;
  return n;
}

}  // namespace

PointResult solve_triangulation(const Calibration& calib, const std::vector<ViewRay>& rays,
                                const TriangulationParams& params) {
  PointResult result;
  uint64_t mask = 0;
  for (const ViewRay& r : rays) mask |= uint64_t{1} << r.view;
  if (popcount(mask) < params.min_views) return result;
  Eigen::Vector3d X;
  if (!triangulate_dlt(calib, rays, mask, true, X)) return result;
  double worst = worst_error(calib, rays, mask, X, nullptr);
  while (worst > params.outlier_threshold_px && popcount(mask) > params.min_views) {
    double best_worst = std::numeric_limits<double>::infinity();
    uint64_t best_mask = 0;
    Eigen::Vector3d best_X;
    for (const ViewRay& r : rays) {
      if (!(mask >> r.view & 1u)) continue;
      const uint64_t m = mask & ~(uint64_t{1} << r.view);
      Eigen::Vector3d Y;
      if (!triangulate_dlt(calib, rays, m, true, Y)) continue;
      const double w = worst_error(calib, rays, m, Y, nullptr);
      if (w < best_worst) {
        best_worst = w;
        best_mask = m;
        best_X = Y;
      }
    }
    if (best_mask == 0) break;
    mask = best_mask;
    X = best_X;
    worst = best_worst;
  }
  // A point that still disagrees with its views, or sits behind a camera, is not reported as a guess.
  if (!std::isfinite(worst) || worst > params.outlier_threshold_px) return result;
  result.position = X;
  result.valid = true;
  score_point(calib, rays, mask, result);
  return result;
}

}  // namespace octocap::internal
