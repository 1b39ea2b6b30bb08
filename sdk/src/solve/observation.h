// What the 3D solvers take in (one keypoint seen by several views) and give back.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/camera.h"

namespace octocap {

// One view's detection of one keypoint, prepared once per frame: the undistorted ray and its pixel.
struct ViewRay {
  int view = 0;
  Eigen::Vector2d pixel;       // as detected (distorted image)
  Eigen::Vector2d normalized;  // undistorted normalised coordinates
  Eigen::Vector3d origin;      // camera centre, world
  Eigen::Vector3d direction;   // unit ray, world
  double confidence = 0;
};

struct PointResult {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  bool valid = false;
  double confidence = 0;
  double reprojection_error_px = 0;
  uint32_t views_used = 0;
  uint64_t view_mask = 0;  // bit v set when view v supported the point
};

ViewRay make_view_ray(const Camera& cam, int view, const Eigen::Vector2d& pixel, double confidence);

// Fills views_used / reprojection error / confidence of `r` from the views in `mask`.
void score_point(const Calibration& calib, const std::vector<ViewRay>& rays, uint64_t mask, PointResult& r);

}  // namespace octocap
