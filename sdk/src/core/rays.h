// Camera rays of 2D detections and their linear triangulation: geometry that calibration and the 3D solve share.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/camera.h"

namespace octocap::internal {

// One view's detection of one keypoint, prepared once per frame: the undistorted ray and its pixel.
struct ViewRay {
  int view = 0;
  Eigen::Vector2d pixel;       // as detected (distorted image)
  Eigen::Vector2d normalized;  // undistorted normalised coordinates
  Eigen::Vector3d origin;      // camera centre, world
  Eigen::Vector3d direction;   // unit ray, world
  double confidence = 0;
};

ViewRay make_view_ray(const Camera& cam, int view, const Eigen::Vector2d& pixel, double confidence);

// Weighted DLT over the views in `mask` (undistorted normalised coordinates). Returns false when degenerate.
bool triangulate_dlt(const Calibration& calib, const std::vector<ViewRay>& rays, uint64_t mask, bool weighted,
                     Eigen::Vector3d& out);

}  // namespace octocap::internal
