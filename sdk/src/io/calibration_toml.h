// The anipose / Pose2Sim calibration TOML: one [cam_N] table per camera, in file order.
#pragma once
#include <string>

#include "core/camera.h"

namespace octocap::internal {

// Throws Error(io) when the file cannot be read and Error(parse) naming the file, the table and the fault.
Calibration read_calibration_toml(const std::string& path);
void write_calibration_toml(const Calibration& calib, const std::string& path);

}  // namespace octocap::internal
