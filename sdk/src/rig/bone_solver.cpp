#include "rig/bone_solver.h"

#include <cmath>

namespace octocap {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

}  // namespace

SkeletonPose solve_bones(const SkeletonJoints& j) {
  SkeletonPose pose;
  const auto& bones = bone_table();
  const auto& rest = tpose_directions();

  // Root: x toward the left hip (the template's left is +X), y as close to world up as the hips allow.
  BonePose& root = pose[kBoneRoot];
  if (finite(j[kRoot]) && finite(j[kLHip]) && finite(j[kRHip])) {
    const Eigen::Vector3d across = j[kLHip] - j[kRHip];
    Eigen::Vector3d x = across.normalized();
    Eigen::Vector3d z = x.cross(Eigen::Vector3d::UnitY());
    // Finite inputs can still overflow (coordinates near 1e308): only finite rotations are valid.
    if (std::isfinite(across.norm()) && across.norm() > 1e-6 && z.norm() > 1e-6) {
      z.normalize();
      const Eigen::Vector3d y = z.cross(x);
      Eigen::Matrix3d R;
      R << x, y, z;
      root.global = Eigen::Quaterniond(R).normalized();
      root.local = root.global;
      root.head = j[kRoot];
      root.length = (j[kLHip] - j[kRoot]).norm();
      root.valid = true;
    }
  }

  for (int b = 1; b < kBoneCount; ++b) {
    const BoneDef& def = bones[b];
    const BonePose& parent = pose[def.parent];
    BonePose& bone = pose[b];
    if (!parent.valid || !finite(j[def.head]) || !finite(j[def.tail])) continue;
    const Eigen::Vector3d d = j[def.tail] - j[def.head];
    const double len = d.norm();
    if (!(len >= 1e-6) || !std::isfinite(len)) continue;
    const Eigen::Vector3d in_parent = parent.global.conjugate() * (d / len);
    const Eigen::Quaterniond local = Eigen::Quaterniond::FromTwoVectors(rest[b], in_parent).normalized();
    if (!local.coeffs().allFinite()) continue;
    bone.local = local;
    bone.global = (parent.global * bone.local).normalized();
    bone.head = j[def.head];
    bone.length = len;
    bone.valid = true;
  }
  return pose;
}

Eigen::Matrix3d naive_bone_frame(const Eigen::Vector3d& direction, const Eigen::Vector3d& ref) {
  const Eigen::Vector3d x = direction.normalized();
  const Eigen::Vector3d y = x.cross(ref).normalized();
  const Eigen::Vector3d z = x.cross(y);
  Eigen::Matrix3d R;
  R << x, y, z;
  return R;
}

double twist_angle(const Eigen::Quaterniond& q, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d a = axis.normalized();
  const double p = q.vec().dot(a);
  return 2.0 * std::atan2(p, q.w());
}

}  // namespace octocap
