// What a camera feed reports, and how it is run: plain data, free of OpenCV, for the engine's and the C ABI's use.
#pragma once
#include <cstdint>
#include <string>

#include "capture/camera_spec.h"

namespace octocap::internal {

enum class FeedState : int { stopped = 0, connecting = 1, streaming = 2, reconnecting = 3, ended = 4, failed = 5 };

struct FeedStatus {
  FeedState state = FeedState::stopped;
  uint64_t grabbed = 0;     // pictures read from the source
  uint64_t used = 0;        // taken by the consumer
  uint64_t dropped = 0;     // replaced by a newer one before the consumer took them
  uint64_t reconnects = 0;  // times a live source was reopened after a break
  uint64_t bad_pictures = 0;  // received but undecodable (corrupt, not a JPEG): skipped
  double fps = 0;           // pictures per second read, smoothed
  double nominal_fps = 0;   // what the source says it delivers (0: it does not say)
  // Remote cameras: how far behind their capture time (less the node's own processing) keypoints arrive, the least
  // of the last few hundred: network transit plus how far the node's clock is behind this host's. Frame sets are
  // matched on capture times corrected by it. 0 for local cameras.
  double clock_offset_ms = 0;
  // Live cameras: the last picture's capture time came from the stream's own clock (trusted once steady), not from
  // when the host grabbed it.
  bool stream_clock = false;
  std::string last_error;
};

struct FeedOptions {
  SourceOptions source;
  int reconnect_min_ms = 100;   // first back-off; doubles up to the max
  int reconnect_max_ms = 2000;
  bool pace_files = true;       // play files and folders at their own rate, as a camera would deliver them
  // Throws Error(invalid_argument) naming the first value out of range: timeouts 1 ms to 10 minutes, the back-off
  // 100 ms (from reconnect_min_ms) to 10 minutes, a folder's rate 0.01 to 1000 pictures a second.
  void validate() const;
};

}  // namespace octocap::internal
