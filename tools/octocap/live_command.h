#pragma once
#include <string>
#include <vector>

#include "detect_command.h"

struct LiveOptions {
  std::vector<std::string> cameras;  // in calibration order
  std::string calibration, output, csv, bvh;
  double duration_s = 0;             // 0: until the cameras end (files) or Ctrl-C
  double picture_rate_hz = 30;
  DetectorOptions detector;
  std::string method = "auto";
  std::string filter = "oneeuro";
  bool quiet = false;
  bool publish = false;
  std::string publish_qos = "live";
  unsigned domain = 0;
  std::string topic = "octocap";
  unsigned source_id = 1;
  unsigned vmc_port = 0;
  std::string vmc_host = "127.0.0.1";
};

int run_live(const LiveOptions& options);
