// Bundle adjustment over camera poses and 3D points with Ceres (intrinsics and distortion held fixed).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "core/camera.h"

namespace octocap::internal {

struct BaObservation {
  int camera;
  int point;
  Eigen::Vector2d pixel;
};

struct BaResult {
  int iterations = 0;
  double initial_rms_px = 0, final_rms_px = 0;
};

// Refines calib[c].R/t for every camera with `adjust[c]` and every point, minimising the robust (Huber,
// `huber_px`) reprojection error in pixels through the full distortion model. Camera `fixed_camera` is held
// to fix the gauge (its pose defines the frame; scale stays free and is set by the caller).
BaResult bundle_adjust(Calibration& calib, const std::vector<bool>& adjust, int fixed_camera,
                       std::vector<Eigen::Vector3d>& points, const std::vector<BaObservation>& observations,
                       double huber_px, int max_iterations);

}  // namespace octocap::internal
