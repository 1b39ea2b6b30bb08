#pragma once
#include <string>

#include "detect_command.h"

struct SolveOptions {
  std::string calibration, keypoints, output, csv, bvh, ground_truth;
  std::string images, debug_images;  // --images: detect first (the detector options below)
  unsigned max_frames = 0;
  DetectorOptions detector;
  std::string method = "auto";
  std::string filter = "oneeuro";
  std::string layout = "auto";
  std::string up = "auto";
  unsigned sigma = 0;
  double delta_mm = 10.0;
  double rate_hz = 30.0;
  unsigned threads = 0;
  bool quiet = false;
  // Streaming (DDS): publish every frame, paced at --rate.
  bool publish = false;
  std::string publish_qos = "live";
  unsigned domain = 0;
  std::string topic = "octocap";
  unsigned source_id = 1;
  unsigned start_frame = 0;
  double linger_s = 0.5;
  unsigned wait_subscribers = 0;
  unsigned vmc_port = 0;
  std::string vmc_host = "127.0.0.1";
};

int run_solve(const SolveOptions& options);
int run_layouts();
