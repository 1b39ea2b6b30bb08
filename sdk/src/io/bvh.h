// BVH motion files (Biovision hierarchy): skeleton, channels, frames, and forward kinematics.
#pragma once
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace octocap::internal {

struct BvhJoint {
  std::string name;          // end sites are named "<parent>_end"
  int parent = -1;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  std::vector<int> channels;  // 0..2 = X/Y/Z position, 3..5 = X/Y/Z rotation, in file order
  int first_channel = 0;      // index of this joint's first value in a frame row
  bool end_site = false;
};

struct BvhMotion {
  std::vector<BvhJoint> joints;  // parents before children
  std::vector<std::vector<double>> frames;
  double frame_time = 1.0 / 30;

  int find(const std::string& name) const;  // -1 when absent
  // Global position and rotation of every joint at `frame`, in file units.
  void pose(size_t frame, std::vector<Eigen::Vector3d>& positions, std::vector<Eigen::Matrix3d>& rotations) const;
};

// Throws Error(io / parse) naming the file and line.
BvhMotion read_bvh(const std::string& path);

}  // namespace octocap::internal
