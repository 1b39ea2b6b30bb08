// Session handles: config, create/destroy, solve, per-frame queries.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "capi/boundary.h"
#include "capi/handles.h"
#include "capi/frame_queries.h"
#include "capi/stream_c.h"
#include "capi/detect_c.h"
#include "capi/session_c.h"
#include "capi/struct_versions.h"
#include "core/log.h"

using namespace octocap::internal;

namespace octocap::internal::capi {

// The C struct -> SessionConfig: a mapping only (what C can say that the core type cannot: a filter enum out of range,
// a port beyond 16 bits, an unterminated host); SessionConfig::validate() checks the values.
SessionConfig session_config(const octocap_session_config_t* given) {
  capi::require(given, "cfg");
  capi::check_size(given->struct_size, capi::kSessionConfigSizes, "octocap_session_config_t");
  octocap_session_config_t defaults;
  octocap_session_config_init(&defaults);
  octocap_detector_config_t detector;
  octocap_detector_config_init(&detector);
  const bool nested_detector = given->struct_size == sizeof(capi::LegacySessionConfig03);
  if (nested_detector)  // its 1.0 fields over today's defaults
    std::memcpy(&detector, reinterpret_cast<const capi::LegacySessionConfig03*>(given)->detector, capi::kDetectorConfigSize10);
  if (given->struct_size < sizeof(octocap_session_config_t))
    log(LogLevel::info, "session config of an older program (struct_size " + std::to_string(given->struct_size) +
                            "): fields it does not have take their defaults");
  // A 0.3 caller's struct holds 1.0's session fields, then its detector config.
  octocap_session_config_t c = defaults;
  std::memcpy(&c, given, nested_detector ? capi::kSessionConfigSize10 : std::min<size_t>(given->struct_size, sizeof c));
  c.struct_size = sizeof c;
  SessionConfig s;
  s.layout = static_cast<LayoutId>(c.layout);
  s.method = static_cast<Method>(c.method);
  if (c.filter != OCTOCAP_FILTER_NONE && c.filter != OCTOCAP_FILTER_ONE_EURO && c.filter != OCTOCAP_FILTER_ONE_EURO_FIXED)
    throw Error(Errc::invalid_argument, "config.filter is not a known filter");
  s.filter = c.filter != OCTOCAP_FILTER_NONE;
  s.filter_adaptive = c.filter == OCTOCAP_FILTER_ONE_EURO;
  s.up = static_cast<UpAxis>(c.up_axis);
  s.sigma = static_cast<int>(std::min<uint32_t>(c.sigma, 1000));
  s.min_views = static_cast<int>(std::min<uint32_t>(c.min_views, 1000));
  s.delta = c.delta_m;
  s.pixel_tolerance = c.pixel_tolerance;
  s.max_candidates = static_cast<int>(std::min<uint32_t>(c.max_candidates, 1u << 30));
  s.min_confidence = c.min_confidence;
  s.outlier_threshold_px = c.outlier_threshold_px;
  s.volume_min = Eigen::Vector3d(c.volume_min[0], c.volume_min[1], c.volume_min[2]);
  s.volume_max = Eigen::Vector3d(c.volume_max[0], c.volume_max[1], c.volume_max[2]);
  s.filter_min_cutoff = c.filter_min_cutoff_hz;
  s.filter_beta = c.filter_beta;
  s.threads = std::min<uint32_t>(c.worker_threads, 256);
  s.first_frame_index = c.first_frame_index;
  s.publish = c.stream_enable != 0;
  if (s.publish) s.stream = capi::stream_config(c.stream_domain_id, c.stream_qos, c.stream_history_depth,
                                                c.stream_source_id, c.stream_topic, sizeof c.stream_topic);
  s.stream.security = capi::c_text(c.stream_security, sizeof c.stream_security, "cfg.stream_security");
  if (c.vmc_port > 65535) throw Error(Errc::invalid_argument, "config.vmc_port must be 0..65535");
  s.vmc_port = static_cast<uint16_t>(c.vmc_port);
  const size_t host_len = strnlen(c.vmc_host, sizeof c.vmc_host);
  if (s.vmc_port && (host_len == 0 || host_len == sizeof c.vmc_host))
    throw Error(Errc::invalid_argument, "config.vmc_host must be a NUL-terminated host name");
  s.vmc_host.assign(c.vmc_host, host_len);
  s.max_people = c.max_people;
  if (c.foot_lock > 1) throw Error(Errc::invalid_argument, "config.foot_lock must be 0 or 1");
  s.foot_lock = c.foot_lock != 0;
  s.detector = capi::detector_config(detector);
  return s;
}

// SessionConfig -> the C struct. octocap_session_config_defaults() converts a default-constructed SessionConfig, so
// each default has one home (pipeline/session.h) and the C ABI only maps.
octocap_session_config_t c_session_config(const SessionConfig& s) {
  octocap_session_config_t c{};
  c.struct_size = sizeof c;
  c.layout = static_cast<octocap_layout_t>(s.layout);
  c.method = static_cast<octocap_method_t>(s.method);
  c.filter = !s.filter ? OCTOCAP_FILTER_NONE : s.filter_adaptive ? OCTOCAP_FILTER_ONE_EURO : OCTOCAP_FILTER_ONE_EURO_FIXED;
  c.up_axis = static_cast<octocap_up_axis_t>(s.up);
  c.sigma = static_cast<uint32_t>(s.sigma);
  c.min_views = static_cast<uint32_t>(s.min_views);
  c.delta_m = static_cast<float>(s.delta);
  c.pixel_tolerance = static_cast<float>(s.pixel_tolerance);
  c.max_candidates = static_cast<uint32_t>(s.max_candidates);
  c.min_confidence = static_cast<float>(s.min_confidence);
  c.outlier_threshold_px = static_cast<float>(s.outlier_threshold_px);
  for (int i = 0; i < 3; ++i) {
    c.volume_min[i] = static_cast<float>(s.volume_min[i]);
    c.volume_max[i] = static_cast<float>(s.volume_max[i]);
  }
  c.filter_min_cutoff_hz = static_cast<float>(s.filter_min_cutoff);
  c.filter_beta = static_cast<float>(s.filter_beta);
  c.worker_threads = s.threads;
  c.first_frame_index = s.first_frame_index;
  c.stream_enable = s.publish ? 1 : 0;
  c.stream_domain_id = s.stream.domain_id;
  c.stream_qos = static_cast<octocap_stream_qos_t>(s.stream.qos);
  c.stream_history_depth = s.stream.history_depth;
  c.stream_source_id = s.stream.source_id;
  capi::copy_name(c.stream_topic, sizeof c.stream_topic, s.stream.topic);
  capi::copy_name(c.stream_security, sizeof c.stream_security, s.stream.security);
  c.vmc_port = s.vmc_port;
  capi::copy_name(c.vmc_host, sizeof c.vmc_host, s.vmc_host);
  c.max_people = s.max_people;
  c.foot_lock = s.foot_lock ? 1 : 0;
  return c;
}

}  // namespace octocap::internal::capi

namespace {

const FrameResult& result_of(const octocap_session_t* s) {
  capi::checked(s, "session");
  if (!s->session->has_result()) throw Error(Errc::no_result, "no frame has been solved yet");
  return s->session->result();
}

}  // namespace

extern "C" {

octocap_result_t octocap_session_config_defaults(octocap_session_config_t* c, uint32_t struct_size) {
  return capi::guard([&] {
    capi::require(c, "cfg");
    capi::check_size(struct_size, capi::kSessionConfigSizes, "octocap_session_config_t");
    octocap_session_config_t d = capi::c_session_config(SessionConfig{});
    if (struct_size == sizeof(capi::LegacySessionConfig03)) {
      capi::LegacySessionConfig03 legacy{};
      d.struct_size = struct_size;
      std::memcpy(legacy.base, &d, sizeof legacy.base);
      octocap_detector_config_defaults(reinterpret_cast<octocap_detector_config_t*>(legacy.detector),
                                       capi::kDetectorConfigSize10);
      std::memcpy(c, &legacy, sizeof legacy);
      return;
    }
    capi::write_defaults(c, struct_size, d);
  });
}

octocap_result_t octocap_session_create(const octocap_session_config_t* cfg, const octocap_calibration_t* calib,
                                        octocap_session_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::checked(calib, "calibration");
    const SessionConfig config = capi::session_config(cfg);
    auto session = std::make_unique<Session>(config, calib->cameras);
    *out = capi::make_handle<octocap_session_t>(std::move(session));
  });
}

void octocap_session_destroy(octocap_session_t* s) { capi::destroy_handle(s); }

octocap_result_t octocap_session_solve_keypoints(octocap_session_t* s, const octocap_keypoint2d_t* keypoints,
                                                 const uint32_t* people_per_view, uint32_t view_count,
                                                 int64_t timestamp_us) {
  bool solved = false;
  const octocap_result_t r = capi::guard([&] {
    capi::checked(s, "session");
    Session& session = *s->session;
    const size_t cams = session.calibration().size();
    if (view_count != cams)
      throw Error(Errc::camera_mismatch, "view_count is " + std::to_string(view_count) +
                                             ", the calibration has " + std::to_string(cams) + " cameras");
    const size_t K = session.keypoint_layout().keypoints.size();
    std::vector<uint32_t> counts(view_count, 1);
    if (people_per_view) counts.assign(people_per_view, people_per_view + view_count);
    size_t total = 0;
    for (uint32_t n : counts) total += n;
    if (total > 0) capi::require(keypoints, "keypoints");
    std::vector<std::vector<Person2D>> people(view_count);
    size_t offset = 0;
    for (uint32_t v = 0; v < view_count; ++v) {
      if (counts[v] > kMaxPeoplePerView)
        throw Error(Errc::invalid_argument, "view " + std::to_string(v) + " has " + std::to_string(counts[v]) +
                                                " people, at most " + std::to_string(kMaxPeoplePerView) + " are taken");
      for (uint32_t p = 0; p < counts[v]; ++p, offset += K) {
        Person2D person(K);
        for (size_t k = 0; k < K; ++k) {
          const octocap_keypoint2d_t& kp = keypoints[offset + k];
          person[k] = Keypoint2D{kp.x, kp.y, kp.confidence};
        }
        people[v].push_back(std::move(person));
      }
    }
    solved = session.solve(people, timestamp_us);
  });
  return capi::status_unless(r, solved, OCTOCAP_STATUS_NO_PERSON);
}

octocap_result_t octocap_session_method(const octocap_session_t* s, octocap_method_t* out) {
  return capi::guard([&] {
    capi::checked(s, "session");
    capi::require(out, "out");
    *out = s->session->method() == Method::triangulation ? OCTOCAP_METHOD_TRIANGULATION : OCTOCAP_METHOD_SUBDIVISION;
  });
}

octocap_result_t octocap_session_up_axis(const octocap_session_t* s, octocap_up_axis_t* out) {
  return capi::guard([&] {
    capi::checked(s, "session");
    capi::require(out, "out");
    *out = s->session->z_up() ? OCTOCAP_UP_Z : OCTOCAP_UP_Y;
  });
}

octocap_result_t octocap_session_stream_subscribers(const octocap_session_t* s, uint32_t* out) {
  return capi::guard([&] {
    capi::checked(s, "session");
    capi::require(out, "out");
    *out = s->session->stream_readers();
  });
}

octocap_result_t octocap_session_flush_stream(octocap_session_t* s) {
  return capi::guard([&] { capi::checked(s, "session")->session->flush_stream(); });
}

octocap_result_t octocap_session_reset(octocap_session_t* s) {
  return capi::guard([&] { capi::checked(s, "session")->session->reset(); });
}

octocap_result_t octocap_session_get_frame(const octocap_session_t* s, octocap_frame_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    *out = capi::make_frame(std::make_shared<const FrameResult>(result_of(s)));
  });
}

// Deprecated 0.x queries: the session's current frame through the same conversions as the frame queries.

octocap_result_t octocap_session_get_frame_info(const octocap_session_t* s, octocap_frame_info_t* out) {
  return capi::guard([&] { capi::query_frame_info(result_of(s), out); });
}

octocap_result_t octocap_session_get_keypoints3d(const octocap_session_t* s, octocap_joint_t* out,
                                                 uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_keypoints(result_of(s).person_or_blank(0), out, capacity, count); });
}

octocap_result_t octocap_session_get_joints(const octocap_session_t* s, octocap_joint_t* out, uint32_t capacity,
                                            uint32_t* count) {
  return capi::guard([&] { capi::query_joints(result_of(s).person_or_blank(0), out, capacity, count); });
}

octocap_result_t octocap_session_get_selected_people(const octocap_session_t* s, int32_t* out, uint32_t capacity,
                                                     uint32_t* count) {
  return capi::guard([&] { capi::query_person_views(result_of(s).person_or_blank(0), out, capacity, count); });
}

octocap_result_t octocap_session_get_bones(const octocap_session_t* s, octocap_coord_frame_t frame,
                                           octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_bones(result_of(s).person_or_blank(0), frame, out, capacity, count); });
}

octocap_result_t octocap_session_get_bone_rotation(const octocap_session_t* s, uint32_t bone,
                                                   octocap_coord_frame_t frame, octocap_quat_t* out) {
  return capi::guard([&] {
    capi::require(out, "out");
    if (bone >= static_cast<uint32_t>(kBoneCount))
      throw Error(Errc::invalid_argument, "bone index " + std::to_string(bone) + " out of range");
    octocap_bone_pose_t bones[kBoneCount];
    uint32_t n = 0;
    capi::query_bones(result_of(s).person_or_blank(0), frame, bones, kBoneCount, &n);
    *out = bones[bone].local_rotation;
  });
}

octocap_result_t octocap_session_definition_counter(const octocap_session_t* s, uint32_t* out) {
  return capi::guard([&] {
    capi::checked(s, "session");
    capi::require(out, "out");
    *out = s->session->result().definition_counter;
  });
}

}  // extern "C"
