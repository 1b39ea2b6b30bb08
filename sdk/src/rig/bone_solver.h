// Stage 4: bone rotations relative to the T-pose template, chained parent to child, without spurious spin, with the
// twist that the body shows.
#pragma once
#include <Eigen/Geometry>
#include <array>
#include <optional>

#include "core/frame.h"
#include "core/skeleton.h"

namespace octocap::internal {

using SkeletonJoints = std::array<Eigen::Vector3d, kJointCount>;  // rig frame; NaN where missing

// What the joints cannot say about the head's turn and the palms' roll: the face's across (the ears', else the eyes'
// left minus right) and forward (nose minus the head's centre) directions; each palm's across (index knuckle minus
// little finger knuckle). Rig frame; NaN where the layout or the frame has none.
struct BodyCues {
  Eigen::Vector3d head_across = Eigen::Vector3d::Constant(std::nan(""));
  Eigen::Vector3d head_forward = Eigen::Vector3d::Constant(std::nan(""));
  Eigen::Vector3d r_palm_across = Eigen::Vector3d::Constant(std::nan(""));
  Eigen::Vector3d l_palm_across = Eigen::Vector3d::Constant(std::nan(""));
};

// The root's orientation comes from the hip line, its up between the world's (Y) and the spine's. A bone's direction
// is always exactly its measured one; what differs between bones is how its roll about that direction is decided:
// - upper arms and thighs: from the plane the bent elbow or knee spans, so that forearm and shin turn about their
//   hinge axis (the T-pose's vertical for the elbows, its left-right axis for the knees); as the limb straightens
//   that plane vanishes and the roll hands over smoothly to the one it had (held, decaying slowly toward the
//   smallest rotation), so a straight limb never flips;
// - the torso: from the shoulder line (the chest's twist against the hips);
// - the head: from the ears or eyes, else the nose (yaw, pitch, roll), held the same way when the face is not seen;
// - the feet (ankle to toes): from the plane of ankle, toes and heel, held the same way when the heel is not seen;
// - the hands (wrist to knuckles): from the palm's across (index to little finger), held the same way; the forearm's
//   twist is the hand's roll against it (an engine's humanoid rig spreads it over its twist bones);
// - every other bone (shoulders, forearms, shins): the smallest rotation that turns its template direction into its
//   measured direction in its parent's frame, the paper's anti-spin correction in closed form (no roll of its own).
// A bone whose joints or parent are missing is invalid (identity rotation) and so are its descendants.
class BoneSolver {
 public:
  SkeletonPose solve(const SkeletonJoints& joints, const BodyCues& cues = {});
  void reset() { previous_ = {}; }

 private:
  std::array<std::optional<Eigen::Quaterniond>, kBoneCount> previous_;  // last global rotation, for holding a roll
};

// One frame on its own (no roll to hold): BoneSolver{}.solve(joints).
SkeletonPose solve_bones(const SkeletonJoints& joints);

// The paper's uncorrected frame (x' along the bone, y' = x' x ref, z' = x' x y'): its roll depends on where
// the bone points relative to `ref` and flips when it passes near it. Kept to show and test what the
// correction prevents.
Eigen::Matrix3d naive_bone_frame(const Eigen::Vector3d& direction, const Eigen::Vector3d& ref);

// Twist angle (radians, in (-pi, pi]) of rotation q about `axis` (swing-twist decomposition).
double twist_angle(const Eigen::Quaterniond& q, const Eigen::Vector3d& axis);

}  // namespace octocap::internal
