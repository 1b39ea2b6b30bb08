#include "rig/motion_take.h"

#include <cmath>

#include "core/error.h"

namespace octocap::internal {

MotionTake::MotionTake(const std::string& path)
    : motion_(load_skeleton_motion(path)), bones_(motion_.ids.size()), definition_counter_(next_definition_counter()) {
  for (size_t p = 0; p < bones_.size(); ++p) {
    BoneSolver solver;
    bones_[p].reserve(motion_.frames.size());
    for (const auto& people : motion_.frames) bones_[p].push_back(solver.solve(people[p]));
  }
}

FrameResult MotionTake::frame(uint32_t index) const {
  if (index >= motion_.frames.size())
    throw Error(Errc::invalid_argument, "frame " + std::to_string(index) + " out of range (" +
                                            std::to_string(motion_.frames.size()) + " frames)");
  FrameResult f;
  f.info.frame_index = index;
  f.info.timestamp_us = std::llround(static_cast<double>(index) * 1e6 / motion_.rate_hz);
  f.rig_frame_joints = true;
  f.definition_counter = definition_counter_;
  // Joints and bones only; a per-person CSV holds several people (its ids), every other file one (id 1).
  for (size_t i = 0; i < motion_.ids.size(); ++i) {
    const SkeletonJoints& j = motion_.frames[index][i];
    PersonResult p;
    p.id = motion_.ids[i];
    for (int k = 0; k < kJointCount; ++k) {
      p.joints[k].valid = j[k].allFinite();
      if (p.joints[k].valid) p.joints[k].position = j[k];
    }
    p.bones = bones_[i][index];
    if (p.has_pose()) f.people.push_back(p);
    else if (i == 0) f.blank = p;
  }
  return f;
}

}  // namespace octocap::internal
