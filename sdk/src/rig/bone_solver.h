// Stage 4: bone rotations relative to the T-pose template, chained parent to child, without spin.
#pragma once
#include <Eigen/Geometry>
#include <array>

#include "core/frame.h"
#include "core/skeleton.h"

namespace octocap {

using SkeletonJoints = std::array<Eigen::Vector3d, kJointCount>;  // rig frame; NaN where missing

// The root's orientation comes from the hip line and the world's up axis (Y); every other bone takes the
// smallest rotation that turns its template direction into its measured direction, expressed in its parent's
// frame. That "smallest rotation" is the paper's anti-spin correction in closed form: it has no component
// about the bone's own axis, so a bone cannot roll however its direction moves. A bone whose joints or
// parent are missing is invalid (identity rotation) and so are its descendants.
SkeletonPose solve_bones(const SkeletonJoints& joints);

// The paper's uncorrected frame (x' along the bone, y' = x' x ref, z' = x' x y'): its roll depends on where
// the bone points relative to `ref` and flips when it passes near it. Kept to show and test what the
// correction prevents.
Eigen::Matrix3d naive_bone_frame(const Eigen::Vector3d& direction, const Eigen::Vector3d& ref);

// Twist angle (radians, in (-pi, pi]) of rotation q about `axis` (swing-twist decomposition).
double twist_angle(const Eigen::Quaterniond& q, const Eigen::Vector3d& axis);

}  // namespace octocap
