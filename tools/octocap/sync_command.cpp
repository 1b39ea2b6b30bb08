// octocap sync: each camera's time offset from the person's own motion, written as a sync TOML for `solve --sync`.
#include "sync_command.h"

#include "command_main.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "octocap/octocap.hpp"

namespace {

int estimate_offsets(const SyncOptions& o) {
  octocap_set_log_callback(print_library_log, OCTOCAP_LOG_WARNING, nullptr);
  // What the options mean, checked here in their own words (the library would name its max_offset_frames).
  check_rate_option(o.rate_hz, false);
  if (!std::isfinite(o.max_offset_s) || o.max_offset_s <= 0)
    throw std::runtime_error("--max-offset-s must be a positive number of seconds");
  const double max_offset_frames = o.max_offset_s * o.rate_hz;
  if (max_offset_frames < 1)
  {
    char text[160];
    std::snprintf(text, sizeof text, "--max-offset-s %g at --rate %g Hz is less than one frame: no offset could be "
                  "found", o.max_offset_s, o.rate_hz);
    throw std::runtime_error(text);
  }
  if (max_offset_frames > 100000)
    throw std::runtime_error("--max-offset-s at --rate is more than 100000 frames");
  const octocap::Calibration calib = octocap::Calibration::load(o.calibration);
  octocap::Recording rec(o.keypoints);
  const uint32_t n = calib.camera_count();
  std::vector<double> offsets(n);
  std::vector<float> residual(n);
  octocap::check(octocap_recording_estimate_sync(rec.get(), calib.get(), max_offset_frames, offsets.data(),
                                                 residual.data(), n),
                 "estimating the offsets");
  octocap::check(octocap_sync_save(o.output.c_str(), o.rate_hz, calib.get(), offsets.data(), n), o.output);
  std::printf("octocap sync: %u cameras, %u frames at %.1f Hz\n", n, rec.frame_count(), o.rate_hz);
  for (uint32_t c = 0; c < n; ++c)
    std::printf("  %-12s offset %+8.2f frames (%+8.1f ms), median epipolar distance %.1f px\n", calib.camera(c).name,
                offsets[c], 1000.0 * offsets[c] / o.rate_hz, residual[c]);
  std::printf("  wrote %s\n", o.output.c_str());
  return 0;
}

}  // namespace

int run_sync(const SyncOptions& options) { return run_reporting_errors("sync", options, estimate_offsets); }
