// Prints skeletons received over DDS, one line per frame, or records them (--record OUT.trc|OUT.csv).
#include <CLI/CLI.hpp>
#include <chrono>
#include <optional>
#include <cstdio>
#include <string>
#include <vector>

#include "octocap/octocap.hpp"

namespace {

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
  std::string topic = "octocap", qos = "live", record, security;
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
  app.add_option("--dds-security", security, "DDS Security: this reader's identity folder, KEYSTORE/NAME (octocap security add ... --role viewer)");
  CLI11_PARSE(app, argc, argv);
  octocap_set_log_callback(log_to_stderr, OCTOCAP_LOG_INFO, nullptr);

  try {
    octocap_subscriber_config_t cfg;
    octocap_subscriber_config_init(&cfg);
    cfg.domain_id = domain;
    cfg.qos = qos == "record" ? OCTOCAP_QOS_RECORD : OCTOCAP_QOS_LIVE;
    cfg.source_id = source;
    std::snprintf(cfg.topic, sizeof cfg.topic, "%s", topic.c_str());
    if (security.size() >= sizeof cfg.security) throw std::runtime_error("--dds-security: the path is too long");
    std::snprintf(cfg.security, sizeof cfg.security, "%s", security.c_str());
    octocap::Subscriber sub(cfg);
    std::optional<octocap::MotionWriter> writer;
    unsigned received = 0;
    while (count == 0 || received < count) {
      std::optional<octocap::Frame> frame = sub.take(static_cast<int32_t>(timeout_s * 1000));
      if (!frame) {
        std::fprintf(stderr, "octocap-stream-echo: nothing for %.1f s, stopping\n", timeout_s);
        break;
      }
      ++received;
      const octocap_frame_summary_t s = frame->summary();
      const octocap_stream_info_t info = sub.stream_info();
      if (!record.empty() && !writer) {
        const octocap_motion_format_t fmt = ends_with(record, ".csv") ? OCTOCAP_MOTION_CSV : OCTOCAP_MOTION_TRC;
        writer.emplace(record, fmt, s.layout, OCTOCAP_UP_Y, rate);
      }
      if (writer) writer->add(*frame, 0);
      if (quiet) continue;
      if (s.person_count == 0) {
        std::printf("frame %lld t=%.3f s source %u: nobody\n", static_cast<long long>(s.frame_index),
                    s.timestamp_us * 1e-6, s.source_id);
        continue;
      }
      const octocap_person_t person = frame->person(0);
      const std::vector<octocap_bone_pose_t> bones = frame->bones(0, OCTOCAP_FRAME_RIG);
      std::printf("frame %lld t=%.3f s source %u person %u: %u/%u keypoints, root (%.3f %.3f %.3f)%s\n",
                  static_cast<long long>(s.frame_index), s.timestamp_us * 1e-6, s.source_id, person.id,
                  person.keypoints_solved, person.keypoints_total, bones[0].head_position[0], bones[0].head_position[1],
                  bones[0].head_position[2],
                  info.last_gap ? (" (gap: " + std::to_string(info.last_gap) + " frames lost)").c_str() : "");
      std::fflush(stdout);
    }
    const octocap_stream_info_t info = sub.stream_info();
    std::printf("received %llu frames, lost %llu, publisher restarts %llu, rejected %llu\n",
                static_cast<unsigned long long>(info.frames_received), static_cast<unsigned long long>(info.frames_lost),
                static_cast<unsigned long long>(info.restarts), static_cast<unsigned long long>(info.rejected));
    if (writer) writer->close();
    return 0;
  } catch (const octocap::Error& e) {
    std::fprintf(stderr, "octocap-stream-echo: %s\n", e.what());
    return 1;
  }
}
