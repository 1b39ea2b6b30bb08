// Live capture handles: the C shell over pipeline/live_engine.
#include <algorithm>
#include <cstddef>
#include <cstring>

#include "capi/boundary.h"
#include "capi/detect_c.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"
#include "capi/live_c.h"
#include "capi/session_c.h"
#include "capi/stream_c.h"
#include "capi/struct_versions.h"
#include "core/redact.h"

using namespace octocap::internal;

namespace {

LiveEngine& engine_of(octocap_live_t* l) { return *capi::checked(l, "live")->engine; }
const LiveEngine& engine_of(const octocap_live_t* l) { return *capi::checked(l, "live")->engine; }

}  // namespace

namespace octocap::internal::capi {

void fill_camera_status(const FeedStatus& s, const std::string& name, octocap_camera_status_t* out) {
  // 1.0's struct ended before clock_offset_ms: its callers get what their size holds.
  fill_sized(out, offsetof(octocap_camera_status_t, clock_offset_ms), "octocap_camera_status_t",
             [&](octocap_camera_status_t& o) {
    o.state = static_cast<octocap_camera_state_t>(s.state);
    o.grabbed = s.grabbed;
    o.used = s.used;
    o.dropped = s.dropped;
    o.reconnects = s.reconnects;
    o.fps = static_cast<float>(s.fps);
    o.nominal_fps = static_cast<float>(s.nominal_fps);
    copy_name(o.name, sizeof o.name, name);
    o.clock_offset_ms = static_cast<float>(s.clock_offset_ms);
    o.stream_clock = s.stream_clock ? 1 : 0;
    copy_name(o.last_error, sizeof o.last_error, redact_credentials(s.last_error));
    o.bad_pictures = s.bad_pictures;
  });
}

FeedOptions feed_options(uint32_t open_timeout_ms, uint32_t read_timeout_ms, uint32_t reconnect_max_ms,
                         float picture_rate_hz) {
  // Clamped, not judged: a value beyond int stays out of range (FeedOptions::validate() judges, where it is used).
  auto ms = [](uint32_t v) { return static_cast<int>(std::min<uint32_t>(v, 1u << 30)); };
  FeedOptions o;
  o.source.open_timeout_ms = ms(open_timeout_ms);
  o.source.read_timeout_ms = ms(read_timeout_ms);
  o.source.picture_rate_hz = picture_rate_hz;
  o.reconnect_max_ms = ms(reconnect_max_ms);
  return o;
}

std::vector<std::string> strings(const char* const* values, uint32_t count, const char* what) {
  std::vector<std::string> out;
  for (uint32_t i = 0; i < count; ++i) {
    if (!values[i]) throw Error(Errc::invalid_argument, std::string(what) + " " + std::to_string(i) + " is NULL");
    out.emplace_back(values[i]);
  }
  return out;
}

void check_camera_index(uint32_t index, size_t count) {
  if (index >= count)
    throw Error(Errc::invalid_argument,
                "camera " + std::to_string(index) + " out of range (" + std::to_string(count) + " cameras)");
}

}  // namespace octocap::internal::capi

extern "C" {

octocap_result_t octocap_live_config_defaults(octocap_live_config_t* c, uint32_t struct_size) {
  return capi::guard([&] {
    capi::require(c, "cfg");
    capi::check_size(struct_size, capi::kLiveConfigSizes, "octocap_live_config_t");
    octocap_live_config_t d{};
    capi::set_feed_defaults(d);
    const LiveConfig live;  // the defaults' one home (pipeline/live_engine.h)
    d.sync_tolerance_us = static_cast<uint32_t>(live.sync_tolerance_us);
    d.max_wait_us = static_cast<uint32_t>(live.max_wait_us);
    d.remote_domain_id = live.remote_domain_id;
    capi::copy_name(d.remote_topic, sizeof d.remote_topic, live.remote_topic);
    capi::copy_name(d.remote_security, sizeof d.remote_security, live.remote_security);
    d.quality = live.governed ? OCTOCAP_QUALITY_GOVERNED : OCTOCAP_QUALITY_MAX;
    d.target_fps = static_cast<float>(live.target_fps);
    d.latency_budget_ms = static_cast<uint32_t>(live.latency_budget_ms);
    capi::write_defaults(c, struct_size, d);
  });
}

octocap_result_t octocap_live_create(const octocap_live_config_t* given, const octocap_session_config_t* session_cfg,
                                     const octocap_calibration_t* calib, const char* const* cameras,
                                     uint32_t camera_count, octocap_live_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(given, "cfg");
    capi::check_size(given->struct_size, capi::kLiveConfigSizes, "octocap_live_config_t");
    capi::checked(calib, "calibration");
    if (camera_count > 0) capi::require(cameras, "cameras");
    octocap_live_config_t defaults;
    octocap_live_config_init(&defaults);
    const octocap_live_config_t c = capi::widen(*given, defaults);
    LiveConfig config;
    config.feeds = capi::feed_options(c.open_timeout_ms, c.read_timeout_ms, c.reconnect_max_ms, c.picture_rate_hz);
    config.session = capi::session_config(session_cfg);
    config.sync_tolerance_us = c.sync_tolerance_us;
    config.max_wait_us = c.max_wait_us;
    config.remote_domain_id = c.remote_domain_id;
    config.remote_topic = capi::topic_name(c.remote_topic, sizeof c.remote_topic, "cfg.remote_topic");
    config.remote_security = capi::c_text(c.remote_security, sizeof c.remote_security, "cfg.remote_security");
    if (c.quality != OCTOCAP_QUALITY_GOVERNED && c.quality != OCTOCAP_QUALITY_MAX)
      throw Error(Errc::invalid_argument, "cfg.quality must be OCTOCAP_QUALITY_GOVERNED or OCTOCAP_QUALITY_MAX");
    config.governed = c.quality == OCTOCAP_QUALITY_GOVERNED;
    config.target_fps = c.target_fps;
    config.latency_budget_ms = c.latency_budget_ms;
    auto engine = std::make_unique<LiveEngine>(config, calib->cameras, capi::strings(cameras, camera_count, "camera"));
    *out = capi::make_handle<octocap_live_t>(std::move(engine));
  });
}

octocap_result_t octocap_live_set_detector(octocap_live_t* l, const octocap_detector_config_t* cfg) {
  return capi::guard([&] {
    LiveEngine& e = engine_of(l);
    capi::require(cfg, "cfg");
    e.set_detector(capi::detector_config(*cfg));
  });
}

octocap_result_t octocap_live_set_latency_offsets(octocap_live_t* l, const int32_t* offsets_us, uint32_t camera_count) {
  return capi::guard([&] {
    LiveEngine& e = engine_of(l);
    if (camera_count > 0) capi::require(offsets_us, "offsets_us");
    e.set_latency_offsets(std::vector<int64_t>(offsets_us, offsets_us + camera_count));
  });
}

octocap_result_t octocap_live_set_recording(octocap_live_t* l, const char* directory) {
  return capi::guard([&] { engine_of(l).set_recording(directory ? directory : ""); });
}

octocap_result_t octocap_live_start(octocap_live_t* l) {
  return capi::guard([&] { engine_of(l).start(); });
}

octocap_result_t octocap_live_stop(octocap_live_t* l) {
  return capi::guard([&] { engine_of(l).stop(); });
}

void octocap_live_destroy(octocap_live_t* l) { capi::destroy_handle(l); }

octocap_result_t octocap_live_take_frame(octocap_live_t* l, int32_t timeout_ms, octocap_frame_t** out) {
  bool taken = false;
  const octocap_result_t r = capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    LiveEngine& e = engine_of(l);
    std::shared_ptr<const FrameResult> frame = e.take(timeout_ms);
    if (!frame) return;
    *out = capi::make_frame(std::move(frame));
    taken = true;
  });
  return capi::status_unless(r, taken, OCTOCAP_STATUS_TIMEOUT);
}

octocap_result_t octocap_live_get_frame(const octocap_live_t* l, octocap_frame_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    std::shared_ptr<const FrameResult> frame = engine_of(l).latest();
    if (!frame) throw Error(Errc::no_result, "no frame has been solved yet");
    *out = capi::make_frame(std::move(frame));
  });
}

octocap_result_t octocap_live_get_stats(const octocap_live_t* l, octocap_live_stats_t* out) {
  return capi::guard([&] {
    const LiveEngine& e = engine_of(l);
    // 1.0's and 1.1's struct ended before sets_recorded: their callers get what their size holds.
    capi::fill_sized(out, offsetof(octocap_live_stats_t, sets_recorded), "octocap_live_stats_t",
                     [&](octocap_live_stats_t& o) {
      const LiveStats s = e.stats();
      o.running = s.running ? 1 : 0;
      o.finished = s.finished ? 1 : 0;
      o.camera_count = static_cast<uint32_t>(e.camera_count());
      o.frame_sets = s.frame_sets;
      o.frames_with_person = s.frames_with_person;
      o.sets_incomplete = s.sets_incomplete;
      o.frames_not_taken = s.frames_not_taken;
      o.fps = static_cast<float>(s.fps);
      o.capture_ms = static_cast<float>(s.capture_ms);
      o.detect_ms = static_cast<float>(s.detect_ms);
      o.solve_ms = static_cast<float>(s.solve_ms);
      o.publish_ms = static_cast<float>(s.publish_ms);
      o.latency_p50_ms = static_cast<float>(s.latency_p50_ms);
      o.latency_p99_ms = static_cast<float>(s.latency_p99_ms);
      o.sets_recorded = s.sets_recorded;
      o.recording_pictures_dropped = s.recording_pictures_dropped;
      o.failed = s.failed ? 1 : 0;
      capi::copy_name(o.last_error, sizeof o.last_error, redact_credentials(s.last_error));
      o.quality_rung = s.quality_rung;
      o.quality_rungs = s.quality_rungs;
      o.views_detected = s.views_detected;
      o.views_in_set = s.views_in_set;
      o.target_fps = static_cast<float>(s.target_fps);
      o.budget_used = static_cast<float>(s.budget_used);
      o.rung_changes = static_cast<uint32_t>(s.rung_changes);
      capi::copy_name(o.model, sizeof o.model, s.model);
    });
  });
}

octocap_result_t octocap_live_get_camera_status(const octocap_live_t* l, uint32_t index, octocap_camera_status_t* out) {
  return capi::guard([&] {
    const LiveEngine& e = engine_of(l);
    capi::check_camera_index(index, e.camera_count());
    capi::fill_camera_status(e.camera_status(index), e.camera_name(index), out);
  });
}

}  // extern "C"
