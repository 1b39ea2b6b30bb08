// The host's monotonic clock in microseconds: every captured frame is stamped with it, every latency measured on it.
#pragma once
#include <chrono>
#include <cstdint>

namespace octocap::internal {

inline int64_t monotonic_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace octocap::internal

namespace octocap::internal {

// Wall clock (µs since 1970): the one clock two machines can share (NTP, PTP). Only for stamps that travel.
inline int64_t wall_clock_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// A monotonic stamp of this host as wall-clock time, and back (the offset read now: both clocks tick alike).
inline int64_t monotonic_to_wall_us(int64_t mono_us) { return mono_us + (wall_clock_us() - monotonic_us()); }
inline int64_t wall_to_monotonic_us(int64_t wall_us) { return wall_us - (wall_clock_us() - monotonic_us()); }

}  // namespace octocap::internal
