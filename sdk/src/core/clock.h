// The host's monotonic clock in microseconds: every captured frame is stamped with it, every latency measured on it.
#pragma once
#include <chrono>
#include <cstdint>

namespace octocap {

inline int64_t monotonic_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace octocap
