// Where a session's solved frames go besides its caller (a DDS stream, a VMC receiver, the live engine's queue).
// The session feeds sinks without knowing what they are, so pipeline/ depends on no output's headers but the
// ones it builds, and a build without DDS simply has fewer sinks.
#pragma once
#include <cstdint>

#include "core/frame.h"

namespace octocap::internal {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Called on the solving thread once per frame; must not block it (queue and return).
  virtual void publish(const FrameResult& frame) = 0;
  // Blocks until everything published has left (a clean end of a recording).
  virtual void flush() {}
  // Receivers currently connected, where the sink knows (0 otherwise).
  virtual uint32_t receivers() const { return 0; }
};

}  // namespace octocap::internal
