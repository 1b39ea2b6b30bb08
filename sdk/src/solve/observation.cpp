#include "solve/observation.h"

namespace octocap {

ViewRay make_view_ray(const Camera& cam, int view, const Eigen::Vector2d& pixel, double confidence) {
  ViewRay r;
  r.view = view;
  r.pixel = pixel;
  r.normalized = cam.pixel_to_normalized(pixel);
  r.origin = cam.center();
  r.direction = (cam.R.transpose() * Eigen::Vector3d(r.normalized.x(), r.normalized.y(), 1.0)).normalized();
  r.confidence = confidence;
  return r;
}

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

}  // namespace octocap
