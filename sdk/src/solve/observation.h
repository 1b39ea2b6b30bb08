// What the 3D solvers take in (one keypoint seen by several views) and give back.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "core/frame.h"
#include "core/rays.h"

namespace octocap::internal {

// Fills views_used / reprojection error / confidence of `r` from the views in `mask`.
void score_point(const Calibration& calib, const std::vector<ViewRay>& rays, uint64_t mask, PointResult& r);

}  // namespace octocap::internal
