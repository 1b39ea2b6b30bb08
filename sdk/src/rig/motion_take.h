// A motion file ready for playback: its joints and the bone poses solved over the whole take, frame by frame as a
// session would give them. The C ABI's octocap_motion_t wraps one; the viewer and the engines play it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/frame.h"
#include "rig/motion_source.h"

namespace octocap::internal {

class MotionTake {
 public:
  // Loads the file (load_skeleton_motion's errors) and solves each person's bones once, one BoneSolver per person so
  // that its rolls carry across frames as in a live take.
  explicit MotionTake(const std::string& path);

  uint32_t frame_count() const { return static_cast<uint32_t>(motion_.frames.size()); }
  double rate_hz() const { return motion_.rate_hz; }
  // Frame `index` (Error(invalid_argument) beyond the take): each person with a pose, timed index / rate, joints in
  // the rig frame; the first person's blank when nobody is there.
  FrameResult frame(uint32_t index) const;

 private:
  SkeletonMotion motion_;
  std::vector<std::vector<SkeletonPose>> bones_;  // [person][frame]
  uint32_t definition_counter_;
};

}  // namespace octocap::internal
