// The solved animation as BVH, the format every animation tool imports: one joint per octocap bone (at the
// bone's head, carrying its local rotation), offsets from the median bone lengths of the take, root position
// per frame. Units: centimetres; rig frame (Y up).
#pragma once
#include <string>
#include <vector>

#include "rig/bone_solver.h"

namespace octocap::internal {

// BVH joint name of each octocap bone (Mixamo/Unity-style names, so retargeting tools map them).
const char* bvh_joint_name(int bone);

// Writes `frames` (missing bones keep their previous rotation; the first frame's missing ones are identity).
void write_bvh(const std::string& path, const std::vector<SkeletonPose>& frames, double rate_hz);

}  // namespace octocap::internal
