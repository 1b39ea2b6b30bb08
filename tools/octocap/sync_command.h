#pragma once
#include <string>

struct SyncOptions {
  std::string calibration, keypoints, output;
  double rate_hz = 30;
  double max_offset_s = 4;
};

int run_sync(const SyncOptions& options);
