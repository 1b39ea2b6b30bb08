#include "solve/observation.h"

namespace octocap::internal {

void score_point(const Calibration& calib, const std::vector<ViewRay>& rays, uint64_t mask, PointResult& r) {
  double err = 0, conf = 0;
  uint32_t n = 0;
  for (const ViewRay& ray : rays) {
    if (!(mask >> ray.view & 1u)) continue;
    const Eigen::Vector2d p = calib[ray.view].project(r.position);
    err += (p - ray.pixel).norm();
    conf += ray.confidence;
    ++n;
  }
  r.view_mask = mask;
  r.views_used = n;
  r.reprojection_error_px = n ? err / n : 0;
  r.confidence = n ? conf / n : 0;
}

}  // namespace octocap::internal
