// The skeleton: the paper's 14 joints + a root, then toes and heels, then the hands' knuckles (appended: indices never
// move), its bones and the T-pose template.
#pragma once
#include <Eigen/Core>
#include <array>

namespace octocap::internal {

constexpr int kJointCount = 21;
constexpr int kBoneCount = 17;
// The 1.0 skeleton's counts: joints and bones are only ever appended, so every consumer knows at least these.
constexpr int kFirstJointCount = 15;
constexpr int kFirstBoneCount = 13;

enum Joint : int {
  kHead = 0, kNeck, kRShoulder, kRElbow, kRHand, kLShoulder, kLElbow, kLHand,
  kRHip, kRKnee, kRFoot, kLHip, kLKnee, kLFoot, kRoot,
  kRToe, kLToe, kRHeel, kLHeel,  // feet, where the layout has them (BODY_25, BODY_25B, HALPE_26, BLAZEPOSE_33)
  kRKnuckles, kLKnuckles          // between the index and little fingers' knuckles, where the layout has them
};

enum Bone : int {
  kBoneRoot = 0, kBoneTorso, kBoneHead, kBoneRShoulder, kBoneRUpperArm, kBoneRLowerArm,
  kBoneLShoulder, kBoneLUpperArm, kBoneLLowerArm, kBoneRUpperLeg, kBoneRLowerLeg,
  kBoneLUpperLeg, kBoneLLowerLeg, kBoneRFoot, kBoneLFoot, kBoneRHand, kBoneLHand
};

struct BoneDef {
  const char* name;
  int parent;  // parent bone, -1 for the root
  int head;    // joint the bone starts at
  int tail;    // joint it ends at (the root ends at the left hip)
};

const std::array<const char*, kJointCount>& joint_names();
const std::array<BoneDef, kBoneCount>& bone_table();

// The T-pose template in the rig frame (right-handed, Y up, facing +Z; the character's left is +X).
// Rest directions of every bone, unit length.
const std::array<Eigen::Vector3d, kBoneCount>& tpose_directions();

}  // namespace octocap::internal
