#pragma once
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "octocap/octocap.h"

// Detector options shared by `octocap detect` and `octocap solve --images`.
struct DetectorOptions {
  std::string model;  // empty: the mode's default
  std::string mode = "crop";
  std::string pick = "all";
  unsigned threads = 0;
  unsigned mosaic_tile = 256;
  unsigned max_people = 4;
  unsigned parallel_views = 0;
  unsigned views_per_frame = 0;
  std::string device = "cpu";
  std::string runtime = "auto";
  std::string precision = "auto";
  octocap_detector_config_t config() const;
};

// "OpenVINO 2026.4.0 (bf16)", "ONNX Runtime 1.31.1 (f32)": the back end a detection ran in, for the figures printed.
std::string runtime_description(const octocap_detect_info_t& info);

struct DetectOptions {
  std::string images, output, debug_images;
  unsigned max_frames = 0;  // 0: all
  bool quiet = false;
  DetectorOptions detector;
  // --live: a capture node (cameras in, their 2D keypoints published over DDS for a hub's octocap live).
  bool live = false, publish_keypoints = false;
  std::vector<std::string> cameras, camera_names;
  std::string camera_file;  // --cameras: more, with their names (camera_file.h)
  std::string node = "node1", topic = "octocap";
  std::string dds_security;  // a keystore identity folder (role node)
  unsigned domain = 0;
  double duration_s = 0;
  double picture_rate_hz = 30;
  double detect_rate_hz = 0;
};

int run_detect(const DetectOptions& options);
int run_node(const DetectOptions& options);  // --live (node_command.cpp)

// A take reader's borrowed BGR picture, copied so that it can be drawn on.
cv::Mat drawable_copy(const octocap_image_t& bgr);
// frame_000012.png style names shared by the debug outputs.
std::string debug_image_path(const std::string& dir, const std::string& camera, size_t frame);
