// Calibration as OpenCV YAML (cv::FileStorage), for tools that read OpenCV's format.
#pragma once
#include <string>

#include "core/camera.h"

namespace octocap::internal {

// Per camera `cam_N`: name, image_width, image_height, camera_matrix, distortion_coefficients, fisheye,
// rvec (Rodrigues), rotation_matrix, tvec (world -> camera, metres); plus camera_count.
void write_calibration_opencv_yaml(const Calibration& calib, const std::string& path);

}  // namespace octocap::internal
