#pragma once
#include <string>
#include <vector>

#include "detect_command.h"
#include "output_options.h"

struct LiveOptions {
  std::vector<std::string> cameras;  // in calibration order
  std::string camera_file;           // --cameras: more, from a file (camera_file.h)
  std::string calibration, output, csv, bvh;
  std::string record;                // a folder: pictures, 2D keypoints, times (octocap solve reads it again)
  double duration_s = 0;             // 0: until the cameras end (files) or Ctrl-C
  double picture_rate_hz = 30;
  double rate_hz = 0;                // TRC and BVH rows; 0: the take's own mean set rate
  DetectorOptions detector;
  std::string method = "auto";
  std::string filter = "oneeuro";
  bool quiet = false;
  OutputOptions out;
  bool foot_lock = true;     // as octocap solve --foot-lock / --no-foot-lock
  std::string people = "1";  // as octocap solve --people
  std::string quality = "governed";  // or "max" (octocap_live_quality_t)
  double target_fps = 0;             // 0: the slowest camera's rate
  unsigned latency_budget_ms = 100;
};

int run_live(const LiveOptions& options);
