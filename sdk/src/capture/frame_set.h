// Software sync: which cameras' newest pictures make one frame set. Pure logic on timestamps, so it is tested
// with known ones; the live engine feeds it each camera's newest unused picture.
#pragma once
#include <cstdint>
#include <vector>

namespace octocap {

struct FrameSetOptions {
  int64_t tolerance_us = 16667;      // pictures within this of the set's time belong to it (default: half a frame at 30 Hz)
  int64_t max_wait_us = 33333;       // a camera silent this long is not waited for (default: a frame at 30 Hz)
  std::vector<int64_t> offsets_us;   // per camera, subtracted from its grab times (a camera known to deliver late)
};

struct Candidate {
  bool present = false;  // the camera has a picture not used yet
  int64_t time_us = 0;   // its grab time (monotonic, µs)
  int64_t last_us = 0;   // grab time of its newest picture, used or not (0: it never delivered one)
};

struct FrameSetDecision {
  bool emit = false;
  std::vector<bool> take;      // per camera: in this set
  std::vector<bool> discard;   // per camera: too old for this set and any later one (counted as dropped)
  int64_t time_us = 0;         // the set's time: the mean of its pictures' corrected times
};

// Emits when every camera has a picture within tolerance of the newest one, or when the cameras missing from the set
// are not about to deliver (silent for max_wait: stalled, dropped, reconnecting): those are left out of that set.
// A camera that delivers keeps being waited for at most one of its frame periods, so no set waits without bound,
// and a dead camera never holds the others back.
FrameSetDecision decide_frame_set(const std::vector<Candidate>& cameras, int64_t now_us, const FrameSetOptions& options);

}  // namespace octocap
