// octocap live: cameras in, 3D out while the person moves; a status line each second, the per-stage table at the end.
#include "live_command.h"

#include "camera_file.h"
#include "command_main.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "live_common.h"
#include "take_writers.h"
#include "octocap/octocap.hpp"

namespace {

using live_common::interrupted;
using live_common::state_name;

int live(const LiveOptions& o) {
  std::vector<std::string> cameras = o.cameras, unused_names;
  if (!o.camera_file.empty()) read_camera_file(o.camera_file, cameras, unused_names);
  octocap_set_log_callback(live_common::log_to_stderr, OCTOCAP_LOG_WARNING, nullptr);
  const octocap::Calibration calib = octocap::Calibration::load(o.calibration);
  octocap_live_config_t cfg;
  octocap_live_config_init(&cfg);
  cfg.picture_rate_hz = static_cast<float>(o.picture_rate_hz);
  cfg.quality = o.quality == "max" ? OCTOCAP_QUALITY_MAX : OCTOCAP_QUALITY_GOVERNED;
  cfg.target_fps = static_cast<float>(o.target_fps);
  cfg.latency_budget_ms = o.latency_budget_ms;
  // Remote cameras (dds://NODE/CAMERA) are read where this rig streams: one DDS domain and topic per rig.
  cfg.remote_domain_id = o.out.domain;
  std::snprintf(cfg.remote_topic, sizeof cfg.remote_topic, "%s", o.out.topic.c_str());
  set_identity(cfg.remote_security, o.out.dds_security);  // a hub: one identity reads the nodes and streams
  octocap_session_config_t scfg;
  octocap_session_config_init(&scfg);
  scfg.layout = OCTOCAP_LAYOUT_COCO_17;  // the shipped models' layout
  scfg.method = o.method == "triangulation" ? OCTOCAP_METHOD_TRIANGULATION
                : o.method == "subdivision"  ? OCTOCAP_METHOD_SUBDIVISION
                                             : OCTOCAP_METHOD_AUTO;
  scfg.filter = o.filter == "none"            ? OCTOCAP_FILTER_NONE
                : o.filter == "oneeuro-fixed" ? OCTOCAP_FILTER_ONE_EURO_FIXED
                                              : OCTOCAP_FILTER_ONE_EURO;
  scfg.max_people = max_people_of(o.people);
  scfg.foot_lock = o.foot_lock ? 1 : 0;
  apply_outputs(o.out, scfg);
  octocap::Live capture(cfg, scfg, calib, live_common::expand_camera_secrets(cameras));
  capture.set_detector(o.detector.config());
  if (!o.record.empty()) capture.set_recording(o.record);
  octocap_up_axis_t up = OCTOCAP_UP_Y;
  {
    // The up axis the session decides from the cameras, for the TRC: asked of a session without outputs, so that no
    // second publisher joins the stream.
    octocap_session_config_t quiet = scfg;
    quiet.stream_enable = 0;
    quiet.vmc_port = 0;
    up = octocap::Session(quiet, calib).up_axis();
  }
  // A live take's sets come when the cameras and the host allow: the CSV keeps each set's time, TRC and BVH rows are
  // resampled to the take's mean rate, or to --rate. Journaled: a take killed on the way keeps its frames.
  TakeWriters writers(o.output, o.csv, o.bvh, OCTOCAP_LAYOUT_COCO_17, up, o.rate_hz, scfg.max_people != 1, true);
  if (!writers.journals().empty())  // stdout, as the summary: --quiet silences only the status line
    std::printf("octocap live: until the take ends its frames are also kept in %s (left only if it is killed)\n",
                writers.journals().c_str());

  live_common::catch_interrupts();
  capture.start();
  const auto start = std::chrono::steady_clock::now();
  auto last_status = start;
  uint64_t taken = 0;
  for (;;) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (interrupted() || (o.duration_s > 0 && elapsed >= o.duration_s)) break;
    std::optional<octocap::Frame> frame = capture.take(200);
    if (frame) {
      ++taken;
      writers.add(*frame);
    }
    const octocap_live_stats_t s = capture.stats();
    if (!frame && s.finished) break;  // every camera played out
    if (!o.quiet && std::chrono::steady_clock::now() - last_status >= std::chrono::seconds(1)) {
      last_status = std::chrono::steady_clock::now();
      std::fprintf(stderr, "\r%6.1f s  solved %5.1f fps  latency p50 %5.0f ms p99 %5.0f ms  ", elapsed, s.fps,
                   s.latency_p50_ms, s.latency_p99_ms);
      if (s.quality_rungs > 0)
        std::fprintf(stderr, "%s on %u view%s (rung %u/%u)  ", s.model, s.views_detected, s.views_detected == 1 ? "" : "s",
                     s.quality_rung + 1, s.quality_rungs);
      std::fprintf(stderr, "cameras");
      live_common::print_camera_rates(capture, s.camera_count);
    }
  }
  capture.stop();
  if (!o.quiet) std::fprintf(stderr, "\n");
  const octocap_live_stats_t s = capture.stats();
  // A take with nobody in any set is no take: no files, and a failure that says why.
  const bool captured = s.frames_with_person > 0 && !s.failed;
  if (captured) writers.close();
  std::printf("octocap live: %u cameras, %llu frame sets solved (%llu with a person, %llu without every camera), "
              "%llu frames taken\n",
              s.camera_count, static_cast<unsigned long long>(s.frame_sets),
              static_cast<unsigned long long>(s.frames_with_person), static_cast<unsigned long long>(s.sets_incomplete),
              static_cast<unsigned long long>(taken));
  std::printf("  per frame: image collection %.1f ms, 2D detection %.1f ms, 3D + rig %.2f ms, hand-over %.3f ms\n",
              s.capture_ms, s.detect_ms, s.solve_ms, s.publish_ms);
  std::printf("  latency (grab to frame): p50 %.1f ms, p99 %.1f ms; %.1f frames/s\n", s.latency_p50_ms,
              s.latency_p99_ms, s.fps);
  if (s.quality_rungs > 0)
    std::printf("  quality governed at %.1f sets/s: last set %s on %u of %u views (rung %u of %u, %.0f %% of its budget), "
                "%u rung changes\n", s.target_fps, s.model, s.views_detected, s.views_in_set, s.quality_rung + 1,
                s.quality_rungs, 100.0 * s.budget_used, s.rung_changes);
  for (uint32_t c = 0; c < s.camera_count; ++c) {
    const octocap_camera_status_t cam = capture.camera(c);
    std::printf("  camera %-10s %-12s %6llu frames, %6llu used, %6llu dropped, reconnects %llu, %.1f fps",
                cam.name, state_name(cam.state), static_cast<unsigned long long>(cam.grabbed),
                static_cast<unsigned long long>(cam.used), static_cast<unsigned long long>(cam.dropped),
                static_cast<unsigned long long>(cam.reconnects), cam.fps);
    if (cam.nominal_fps > 0) std::printf(" (says %.1f)", cam.nominal_fps);
    if (cam.bad_pictures > 0)
      std::printf(", %llu bad pictures skipped", static_cast<unsigned long long>(cam.bad_pictures));
    if (cameras[c].rfind("dds://", 0) == 0)
      std::printf(", %s, clock offset %.1f ms", octocap_redact_credentials(cameras[c].c_str()), cam.clock_offset_ms);
    else if (cam.stream_clock) std::printf(", times from the stream's clock");
    if (cam.last_error[0]) std::printf("; last error: %s", cam.last_error);
    std::printf("\n");
  }
  if (captured && (!o.output.empty() || !o.csv.empty() || !o.bvh.empty()))
    std::printf("  wrote %s\n", writers.written().c_str());
  if (!o.record.empty())
    std::printf("  recorded %llu frame sets into %s (pictures left out of %llu: the disk was behind)\n",
                static_cast<unsigned long long>(s.sets_recorded), o.record.c_str(),
                static_cast<unsigned long long>(s.recording_pictures_dropped));
  if (captured) return 0;
  if (s.failed) {
    std::fprintf(stderr, "octocap live: error: stopped: %s\n", s.last_error);
  } else {
    std::fprintf(stderr, "octocap live: error: nothing was captured: no frame set had a person%s\n",
                 o.output.empty() && o.csv.empty() && o.bvh.empty() ? "" : " (no file written)");
    for (uint32_t c = 0; c < s.camera_count; ++c) {
      const octocap_camera_status_t cam = capture.camera(c);
      if (cam.used == 0)
        std::fprintf(stderr, "  camera %s (number %u, %s) delivered nothing%s%s\n", cam.name, c + 1,
                     octocap_redact_credentials(cameras[c].c_str()), cam.last_error[0] ? ": " : "", cam.last_error);
    }
    if (s.last_error[0]) std::fprintf(stderr, "  the last frame set failed with: %s\n", s.last_error);
  }
  return 1;
}

}  // namespace

int run_live(const LiveOptions& options) { return run_reporting_errors("live", options, live); }
