#include "core/frame.h"

#include <atomic>
#include <cmath>
#include "core/skeleton.h"

namespace octocap::internal {

const std::array<const char*, kJointCount>& joint_names() {
  static const std::array<const char*, kJointCount> names = {
      "head", "neck", "r_shoulder", "r_elbow", "r_hand", "l_shoulder", "l_elbow", "l_hand",
      "r_hip", "r_knee", "r_foot", "l_hip", "l_knee", "l_foot", "root",
      "r_toe", "l_toe", "r_heel", "l_heel", "r_knuckles", "l_knuckles"};
  return names;
}

const std::array<BoneDef, kBoneCount>& bone_table() {
  // METHOD.md's bones, plus ROOT (global pelvis orientation) so that the legs hang from the pelvis, not the torso.
  static const std::array<BoneDef, kBoneCount> bones = {{
      {"root", -1, kRoot, kLHip},  // points at the left hip: its length is half the hip width
      {"torso", kBoneRoot, kRoot, kNeck},
      {"head", kBoneTorso, kNeck, kHead},
      {"r_shoulder", kBoneTorso, kNeck, kRShoulder},
      {"r_upper_arm", kBoneRShoulder, kRShoulder, kRElbow},
      {"r_lower_arm", kBoneRUpperArm, kRElbow, kRHand},
      {"l_shoulder", kBoneTorso, kNeck, kLShoulder},
      {"l_upper_arm", kBoneLShoulder, kLShoulder, kLElbow},
      {"l_lower_arm", kBoneLUpperArm, kLElbow, kLHand},
      {"r_upper_leg", kBoneRoot, kRHip, kRKnee},
      {"r_lower_leg", kBoneRUpperLeg, kRKnee, kRFoot},
      {"l_upper_leg", kBoneRoot, kLHip, kLKnee},
      {"l_lower_leg", kBoneLUpperLeg, kLKnee, kLFoot},
      // The foot from the ankle (the joint the paper calls foot) to the toes; the heel gives its roll.
      {"r_foot", kBoneRLowerLeg, kRFoot, kRToe},
      {"l_foot", kBoneLLowerLeg, kLFoot, kLToe},
      // The hand from the wrist (the paper's hand joint) to the knuckles; the palm's across gives its roll.
      {"r_hand", kBoneRLowerArm, kRHand, kRKnuckles},
      {"l_hand", kBoneLLowerArm, kLHand, kLKnuckles},
  }};
  return bones;
}

const std::array<Eigen::Vector3d, kBoneCount>& tpose_directions() {
  static const Eigen::Vector3d kFootRest(0, -std::sin(20 * M_PI / 180), std::cos(20 * M_PI / 180));
  // The four template frame kinds of the paper: up (torso, head), left (+X), right (-X), down (legs);
  // the root points at the left hip (+X); a foot forward (+Z) and 20 deg down, as it stands flat (toes 16 cm ahead
  // of the ankle, 6 cm below it), so that a standing foot is near identity and so is an avatar's foot at rest.
  static const std::array<Eigen::Vector3d, kBoneCount> dirs = {
      Eigen::Vector3d(1, 0, 0),  Eigen::Vector3d(0, 1, 0),  Eigen::Vector3d(0, 1, 0),
      Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(-1, 0, 0),
      Eigen::Vector3d(1, 0, 0),  Eigen::Vector3d(1, 0, 0),  Eigen::Vector3d(1, 0, 0),
      Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, -1, 0),
      Eigen::Vector3d(0, -1, 0), kFootRest,                 kFootRest,
      Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, 0, 0)};  // hands along the arms, palms down
  return dirs;
}

}  // namespace octocap::internal

namespace octocap::internal {

uint32_t next_definition_counter() {
  static std::atomic<uint32_t> counter{0};
  uint32_t n = ++counter;
  if (n == 0) n = ++counter;  // wrapped: 0 means "none" to consumers
  return n;
}

}  // namespace octocap::internal
