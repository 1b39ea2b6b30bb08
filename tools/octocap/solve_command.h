#pragma once
#include <string>

#include "detect_command.h"
#include "output_options.h"

struct SolveOptions {
  std::string calibration, keypoints, output, csv, bvh, ground_truth, sync;
  std::string images, debug_images;  // --images: detect first (the detector options below)
  unsigned max_frames = 0;
  DetectorOptions detector;
  std::string method = "auto";
  std::string filter = "oneeuro";
  std::string layout = "auto";
  std::string up = "auto";
  unsigned sigma = 0;
  double delta_mm = 10.0;
  double rate_hz = 0;  // 0: the videos' own rate with --images, else 30
  unsigned threads = 0;
  bool quiet = false;
  OutputOptions out;  // DDS and VMC, paced at --rate
  unsigned start_frame = 0;
  double linger_s = 0.5;
  unsigned wait_subscribers = 0;
  bool foot_lock = true;     // --no-foot-lock: joints as solved (planted feet are held by default)
  std::string people = "1";  // "auto" or N: several people, one TRC (and BVH) per person, a CSV with a person column
};

int run_solve(const SolveOptions& options);
int run_layouts();
