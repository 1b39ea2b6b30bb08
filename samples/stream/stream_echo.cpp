// Prints skeletons received over DDS, one line per frame, or records them (--record OUT.trc|OUT.csv).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "octocap/octocap.h"

namespace {

int fail(const char* what) {
  std::fprintf(stderr, "octocap-stream-echo: %s: %s\n", what, octocap_last_error());
  return 1;
}

void log_to_stderr(octocap_log_level_t level, const char* message, void*) {
  std::fprintf(stderr, "octocap-stream-echo: [%d] %s\n", level, message);
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"octocap-stream-echo: receive octocap skeletons over DDS, print or record them"};
  unsigned domain = 0, count = 0, source = 0;
  std::string topic = "octocap", qos = "live", record;
  double timeout_s = 10, rate = 30;
  bool quiet = false;
  app.add_option("--domain", domain, "DDS domain id")->capture_default_str();
  app.add_option("--topic", topic, "Topic base name")->capture_default_str();
  app.add_option("--qos", qos, "Must match the publisher's")->check(CLI::IsMember({"live", "record"}))->capture_default_str();
  app.add_option("--source-id", source, "Only this source (0: any)")->capture_default_str();
  app.add_option("--count", count, "Stop after this many frames (0: no limit)")->capture_default_str();
  app.add_option("--timeout-s", timeout_s, "Stop when nothing arrives for this long")->capture_default_str();
  app.add_option("--record", record, "Write the received keypoints to a .trc or .csv file");
  app.add_option("--rate", rate, "Frame rate written to a TRC")->capture_default_str();
  app.add_flag("--quiet", quiet, "No line per frame");
  CLI11_PARSE(app, argc, argv);
  octocap_set_log_callback(log_to_stderr, OCTOCAP_LOG_INFO, nullptr);

  octocap_subscriber_config_t cfg;
  octocap_subscriber_config_init(&cfg);
  cfg.domain_id = domain;
  cfg.qos = qos == "record" ? OCTOCAP_QOS_RECORD : OCTOCAP_QOS_LIVE;
  cfg.source_id = source;
  std::snprintf(cfg.topic, sizeof cfg.topic, "%s", topic.c_str());
  octocap_subscriber_t* sub = nullptr;
  if (octocap_subscriber_create(&cfg, &sub) != OCTOCAP_OK) return fail("subscribing");

  octocap_motion_writer_t* writer = nullptr;
  std::vector<octocap_joint_t> kps(64);
  unsigned received = 0;
  while (count == 0 || received < count) {
    const octocap_result_t r = octocap_subscriber_take(sub, static_cast<int32_t>(timeout_s * 1000));
    if (r == OCTOCAP_ERROR_NO_RESULT) break;
    if (r != OCTOCAP_OK) return fail("taking a pose");
    ++received;
    octocap_stream_info_t info;
    octocap_frame_info_t frame;
    uint32_t n = 0;
    octocap_subscriber_get_stream_info(sub, &info);
    octocap_subscriber_get_frame_info(sub, &frame);
    octocap_subscriber_get_keypoints3d(sub, kps.data(), static_cast<uint32_t>(kps.size()), &n);
    if (!record.empty() && !writer) {
      const octocap_motion_format_t fmt = ends_with(record, ".csv") ? OCTOCAP_MOTION_CSV : OCTOCAP_MOTION_TRC;
      if (octocap_motion_writer_create(record.c_str(), fmt, info.layout, OCTOCAP_UP_Y, rate, &writer) != OCTOCAP_OK)
        return fail("--record");
    }
    if (writer && octocap_motion_writer_add_keypoints(writer, kps.data(), n) != OCTOCAP_OK) return fail("recording");
    if (!quiet) {
      octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
      uint32_t nb = 0;
      octocap_subscriber_get_bones(sub, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &nb);
      std::printf("frame %lld t=%.3f s source %u: %u/%u keypoints, root (%.3f %.3f %.3f)%s\n",
                  static_cast<long long>(frame.frame_index), frame.timestamp_us * 1e-6, info.source_id,
                  frame.keypoints_solved, frame.keypoints_total, bones[0].head_position[0], bones[0].head_position[1],
                  bones[0].head_position[2],
                  info.last_gap ? (" (gap: " + std::to_string(info.last_gap) + " frames lost)").c_str() : "");
      std::fflush(stdout);
    }
  }
  octocap_stream_info_t info;
  octocap_subscriber_get_stream_info(sub, &info);
  std::printf("received %llu frames, lost %llu, publisher restarts %llu, rejected %llu\n",
              static_cast<unsigned long long>(info.frames_received), static_cast<unsigned long long>(info.frames_lost),
              static_cast<unsigned long long>(info.restarts), static_cast<unsigned long long>(info.rejected));
  if (writer && octocap_motion_writer_close(writer) != OCTOCAP_OK) return fail("writing the recording");
  octocap_subscriber_destroy(sub);
  return 0;
}
