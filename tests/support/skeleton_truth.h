// Skeleton joints from a layout's true 3D keypoints, by the layout's own definition (NaN where it has no source).
#pragma once
#include <vector>

#include "core/layout.h"
#include "rig/bone_solver.h"

namespace testing {

inline octocap::internal::SkeletonJoints skeleton_from_keypoints(const std::vector<Eigen::Vector3d>& kps,
                                                       octocap::internal::LayoutId id) {
  const octocap::internal::KeypointLayout& l = octocap::internal::layout(id);
  octocap::internal::SkeletonJoints j;
  for (int i = 0; i < octocap::internal::kJointCount; ++i) {
    if (l.joint_sources[i].empty()) {
      j[i] = Eigen::Vector3d::Constant(std::nan(""));
      continue;
    }
    const auto& alt = l.joint_sources[i].front();
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int k : alt) s += kps[k];
    j[i] = s / static_cast<double>(alt.size());
  }
  return j;
}

// Joints rebuilt from bone rotations and lengths alone, chained from the root's position.
inline octocap::internal::SkeletonJoints rebuild_from_bones(const octocap::internal::SkeletonPose& pose, const Eigen::Vector3d& root) {
  using namespace octocap::internal;
  SkeletonJoints j;
  j.fill(Eigen::Vector3d::Constant(std::nan("")));
  j[kRoot] = root;
  const auto& dirs = tpose_directions();
  const BonePose& r = pose[kBoneRoot];
  j[kLHip] = root + r.global * (dirs[kBoneRoot] * r.length);
  j[kRHip] = root - r.global * (dirs[kBoneRoot] * r.length);
  for (int b = 1; b < kBoneCount; ++b) {
    const BoneDef& d = bone_table()[b];
    j[d.tail] = j[d.head] + pose[b].global * (dirs[b] * pose[b].length);
  }
  return j;
}

}  // namespace testing
