// The time offsets of a take's cameras on disk:
//   rate = 30.0
//   [offsets_frames]   # camera c's frame i was captured at (i + offset_c) / rate on the first camera's clock
//   cam01 = 0.0
#pragma once
#include <string>
#include <vector>

namespace octocap::internal {

struct SyncFile {
  double rate_hz = 30;
  std::vector<std::string> cameras;  // calibration names
  std::vector<double> offsets_frames;
};

void write_sync_toml(const std::string& path, const SyncFile& sync);
// Throws Error(io / parse) naming the file and what is wrong (a missing table, a non-number, a bad rate).
SyncFile read_sync_toml(const std::string& path);

}  // namespace octocap::internal
