// Software sync: which of each camera's newest pictures make one frame set. Pure logic on timestamps, so it is tested
// with known ones; the live engine feeds it, per camera, the newest two pictures not used yet (a camera running at
// its own phase always has one of them within half a frame period of any moment between them).
#pragma once
#include <cstdint>
#include <vector>

namespace octocap::internal {

struct FrameSetOptions {
  int64_t tolerance_us = 16667;     // pictures within this of the set's time belong to it (default: half a frame at 30 Hz)
  int64_t max_wait_us = 33333;      // a camera silent this long is not waited for (default: a frame at 30 Hz)
  std::vector<int64_t> offsets_us;  // per camera, subtracted from its grab times (a camera known to deliver late)
};

struct Picture {
  uint64_t sequence = 0;  // 0: none
  int64_t time_us = 0;    // capture time (monotonic, µs): grab, or a remote camera's capture stamp
  int64_t arrival_us = 0; // when it reached the engine (0: at time_us; later for remote cameras, which detect first)
  int64_t arrived() const { return arrival_us ? arrival_us : time_us; }
};

struct Candidate {
  Picture newest;         // the newest picture not used yet (sequence 0: none)
  Picture previous;       // the one before it, if not used yet
  int64_t last_us = 0;    // capture time of the camera's newest picture, used or not (0: it never delivered one)
  int64_t last_arrival_us = 0;  // when that picture arrived (0: at last_us)
  int64_t last_arrived() const { return last_arrival_us ? last_arrival_us : last_us; }
};

struct FrameSetDecision {
  bool emit = false;
  std::vector<uint64_t> take;  // per camera: the picture in this set (0: the camera is left out)
  int64_t time_us = 0;         // the set's time (corrected clock)
};

// The set's time is the oldest of the cameras' newest pictures (cameras silent for max_wait aside): every camera
// has a picture at or after it, and each takes its picture nearest to it, if within the tolerance. Emits when every
// camera is in, or when the cameras left out are not about to deliver (silent for max_wait: stalled, dropped,
// reconnecting). Silence is judged on arrival times, so a camera that delivers late (a capture node detects before
// it sends) is awaited as one that delivers on time. A camera that delivers is waited for at most one of its frame periods, so no set waits without
// bound and a dead camera never holds the others back.
FrameSetDecision decide_frame_set(const std::vector<Candidate>& cameras, int64_t now_us, const FrameSetOptions& options);

}  // namespace octocap::internal
