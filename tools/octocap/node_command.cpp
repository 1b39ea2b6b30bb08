// octocap detect --live: a capture node. Its cameras are detected here and their 2D keypoints published over DDS for
// a hub (octocap live --camera dds://NODE/CAMERA); a status line each second, a line per camera at the end.
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "camera_file.h"
#include "command_main.h"
#include "detect_command.h"
#include "live_common.h"
#include "output_options.h"
#include "octocap/octocap.hpp"

namespace {

namespace {

std::string default_camera_name(size_t index) {
  char name[16];
  std::snprintf(name, sizeof name, "cam%02zu", index + 1);
  return name;
}

}  // namespace

int node(const DetectOptions& o) {
  std::vector<std::string> cameras = o.cameras, names = o.camera_names, file_names;
  if (!o.camera_file.empty()) {
    read_camera_file(o.camera_file, cameras, file_names);
    // Named cameras keep their names; the others are cam01, cam02, ... by their place, as without a file.
    if (!names.empty() && names.size() != o.cameras.size())
      throw std::runtime_error("--camera-name: give one per --camera (the file's cameras are named in the file)");
    bool any = !names.empty();
    for (const std::string& n : file_names) any = any || !n.empty();
    if (any) {
      for (size_t c = names.size(); c < o.cameras.size(); ++c) names.push_back(default_camera_name(c));
      for (size_t i = 0; i < file_names.size(); ++i)
        names.push_back(file_names[i].empty() ? default_camera_name(o.cameras.size() + i) : file_names[i]);
    }
  }
  if (cameras.empty()) throw std::runtime_error("--live needs at least one --camera (or --cameras FILE)");
  if (!o.publish_keypoints)
    throw std::runtime_error("--live detects for a hub: add --publish-keypoints (the keypoints go out over DDS)");
  octocap_set_log_callback(live_common::log_to_stderr, OCTOCAP_LOG_WARNING, nullptr);
  octocap_node_config_t cfg;
  octocap_node_config_init(&cfg);
  if (o.node.size() >= sizeof cfg.name || o.topic.size() >= sizeof cfg.topic)
    throw std::runtime_error("--node and --topic: at most 31 bytes");
  std::snprintf(cfg.name, sizeof cfg.name, "%s", o.node.c_str());
  std::snprintf(cfg.topic, sizeof cfg.topic, "%s", o.topic.c_str());
  cfg.domain_id = o.domain;
  set_identity(cfg.security, o.dds_security);
  cfg.picture_rate_hz = static_cast<float>(o.picture_rate_hz);
  cfg.detect_rate_hz = static_cast<float>(o.detect_rate_hz);
  octocap::Node capture(cfg, live_common::expand_camera_secrets(cameras), names);
  capture.set_detector(o.detector.config());
  live_common::catch_interrupts();
  capture.start();
  const auto start = std::chrono::steady_clock::now();
  auto last_status = start;
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const octocap_node_stats_t s = capture.stats();
    if (live_common::interrupted() || (o.duration_s > 0 && elapsed >= o.duration_s) || s.finished) break;
    if (!o.quiet && std::chrono::steady_clock::now() - last_status >= std::chrono::seconds(1)) {
      last_status = std::chrono::steady_clock::now();
      std::fprintf(stderr, "\r%6.1f s  published %6llu views  detect %5.1f ms  hubs %u  cameras", elapsed,
                   static_cast<unsigned long long>(s.published), s.detect_ms, s.readers);
      live_common::print_camera_rates(capture, s.camera_count);
    }
  }
  capture.stop();
  if (!o.quiet) std::fprintf(stderr, "\n");
  const octocap_node_stats_t s = capture.stats();
  std::printf("octocap detect --live: node %s, %u cameras, %llu views published (%llu with a person) on %s_keypoints2d, "
              "domain %u\n",
              o.node.c_str(), s.camera_count, static_cast<unsigned long long>(s.published),
              static_cast<unsigned long long>(s.with_person), o.topic.c_str(), o.domain);
  std::printf("  per view: 2D detection %.1f ms, grab to published %.1f ms\n", s.detect_ms, s.processing_ms);
  for (uint32_t c = 0; c < s.camera_count; ++c) {
    const octocap_camera_status_t cam = capture.camera(c);
    std::printf("  camera dds://%s/%-8s %-12s %6llu frames, %6llu used, %6llu dropped, reconnects %llu, %.1f fps\n",
                o.node.c_str(), cam.name, live_common::state_name(cam.state),
                static_cast<unsigned long long>(cam.grabbed), static_cast<unsigned long long>(cam.used),
                static_cast<unsigned long long>(cam.dropped), static_cast<unsigned long long>(cam.reconnects), cam.fps);
  }
  return 0;
}

}  // namespace

int run_node(const DetectOptions& options) { return run_reporting_errors("detect --live", options, node); }
