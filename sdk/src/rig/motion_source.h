// Motion files as skeleton joints for playback (the viewer, engines): a TRC or CSV of keypoints (octocap's own
// output, Pose2Sim's) or a BVH (CMU, Mixamo-style and octocap's own joint names).
#pragma once
#include <string>
#include <vector>

#include "core/layout.h"
#include "rig/bone_solver.h"

namespace octocap::internal {

// Frames 1 / rate_hz apart: a file whose frames came unevenly (a live take's CSV says when each set happened) is
// resampled onto that grid at its mean rate, joints interpolated (missing across a stretch of over a quarter second).
struct SkeletonMotion {
  std::vector<uint32_t> ids{1};                     // the people, in increasing id order (a per-person CSV: several)
  std::vector<std::vector<SkeletonJoints>> frames;  // [frame][person]: rig frame, Y up, metres; NaN where missing
  double rate_hz = 30;
  std::string source_kind;                          // "TRC (COCO_17)", "BVH", ...
};

// Throws Error(io / parse / invalid_argument) naming the file: unknown extension, no recognisable skeleton.
SkeletonMotion load_skeleton_motion(const std::string& path);

// The skeleton's joints from one frame of layout keypoints (the layout's joint sources; NaN when absent).
SkeletonJoints joints_from_keypoints(const KeypointLayout& layout, const std::vector<Eigen::Vector3d>& keypoints);

}  // namespace octocap::internal
