// Ground-truth 3D keypoints in octocap's CSV format, for reporting accuracy (MPJPE).
#pragma once
#include <array>
#include <string>
#include <vector>

struct GroundTruth {
  std::vector<std::string> names;
  std::vector<std::vector<std::array<double, 3>>> frames;  // NaN where unknown
};

// Reads `frame,NAME_x,NAME_y,NAME_z,...`; throws std::runtime_error naming the file and line.
GroundTruth read_ground_truth_csv(const std::string& path);
