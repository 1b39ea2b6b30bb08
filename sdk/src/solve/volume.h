// The capture volume the subdivision starts from, when the config does not give one.
#pragma once
#include <Eigen/Geometry>

#include "core/camera.h"

namespace octocap::internal {

// The bounding box of the space seen by at least two cameras (all of them with two cameras), within
// `max_range` metres of the rig, sampled on a grid. Empty when the cameras share no view.
Eigen::AlignedBox3d derive_capture_volume(const Calibration& calib, double max_range = 8.0);

}  // namespace octocap::internal
