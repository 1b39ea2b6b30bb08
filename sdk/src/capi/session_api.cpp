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

using namespace octocap;

namespace {

// The 0.1 struct ended at worker_threads; callers built against it pass that size and get defaults for the rest.
constexpr size_t kConfigV1Size = offsetof(octocap_session_config_t, first_frame_index);

SessionConfig from_c(const octocap_session_config_t& given) {
  // A struct_size that cuts the nested detector config in two is no version of this struct.
  const size_t detector_at = offsetof(octocap_session_config_t, detector);
  if (given.struct_size > detector_at && given.struct_size < sizeof(octocap_session_config_t))
    throw Error(Errc::struct_size, "octocap_session_config_t.struct_size " + std::to_string(given.struct_size) +
                                       " ends inside the detector config (call octocap_session_config_init first)");
  if (given.struct_size < kConfigV1Size || given.struct_size > sizeof(octocap_session_config_t))
    throw Error(Errc::struct_size, "octocap_session_config_t.struct_size is " + std::to_string(given.struct_size) +
                                       ", this library accepts " + std::to_string(kConfigV1Size) + " to " +
                                       std::to_string(sizeof(octocap_session_config_t)) +
                                       " (call octocap_session_config_init first)");
  octocap_session_config_t c;
  octocap_session_config_init(&c);
  std::memcpy(&c, &given, given.struct_size);
  SessionConfig s;
  if (octocap_layout_keypoint_count(c.layout) == 0)
    throw Error(Errc::invalid_argument, "config.layout must be a concrete layout (not AUTO)");
  s.layout = static_cast<LayoutId>(c.layout);
  if (c.method != OCTOCAP_METHOD_SUBDIVISION && c.method != OCTOCAP_METHOD_TRIANGULATION &&
      c.method != OCTOCAP_METHOD_AUTO)
    throw Error(Errc::invalid_argument, "config.method is not a known method");
  s.method = static_cast<Method>(c.method);
  if (c.filter != OCTOCAP_FILTER_NONE && c.filter != OCTOCAP_FILTER_ONE_EURO)
    throw Error(Errc::invalid_argument, "config.filter is not a known filter");
  s.filter = c.filter == OCTOCAP_FILTER_ONE_EURO;
  if (c.up_axis != OCTOCAP_UP_Y && c.up_axis != OCTOCAP_UP_Z && c.up_axis != OCTOCAP_UP_AUTO)
    throw Error(Errc::invalid_argument, "config.up_axis must be Y, Z or AUTO");
  s.up = static_cast<UpAxis>(c.up_axis);
  const float floats[] = {c.delta_m, c.pixel_tolerance, c.min_confidence, c.outlier_threshold_px,
                          c.filter_min_cutoff_hz, c.filter_beta, c.volume_min[0], c.volume_min[1],
                          c.volume_min[2], c.volume_max[0], c.volume_max[1], c.volume_max[2]};
  for (float f : floats) capi::require_finite(f, "a config value");
  if (!(c.delta_m > 0)) throw Error(Errc::invalid_argument, "config.delta_m must be > 0");
  if (c.pixel_tolerance < 0) throw Error(Errc::invalid_argument, "config.pixel_tolerance must be >= 0");
  if (c.max_candidates < 1) throw Error(Errc::invalid_argument, "config.max_candidates must be >= 1");
  if (!(c.outlier_threshold_px > 0)) throw Error(Errc::invalid_argument, "config.outlier_threshold_px must be > 0");
  if (!(c.filter_min_cutoff_hz > 0) || c.filter_beta < 0)
    throw Error(Errc::invalid_argument, "config.filter_min_cutoff_hz must be > 0 and filter_beta >= 0");
  s.sigma = static_cast<int>(std::min<uint32_t>(c.sigma, 1000));
  s.min_views = static_cast<int>(std::min<uint32_t>(c.min_views, 1000));
  s.delta = c.delta_m;
  s.pixel_tolerance = c.pixel_tolerance;
  s.max_candidates = static_cast<int>(std::min<uint32_t>(c.max_candidates, 100000));
  s.min_confidence = c.min_confidence;
  s.outlier_threshold_px = c.outlier_threshold_px;
  const Eigen::Vector3d lo(c.volume_min[0], c.volume_min[1], c.volume_min[2]);
  const Eigen::Vector3d hi(c.volume_max[0], c.volume_max[1], c.volume_max[2]);
  if (lo != hi) {
    if ((hi.array() <= lo.array()).any())
      throw Error(Errc::invalid_argument, "config.volume_max must exceed volume_min on every axis");
    s.volume = Eigen::AlignedBox3d(lo, hi);
  }
  s.filter_min_cutoff = c.filter_min_cutoff_hz;
  s.filter_beta = c.filter_beta;
  s.threads = std::min<uint32_t>(c.worker_threads, 256);
  s.first_frame_index = c.first_frame_index;
  s.publish = c.stream_enable != 0;
  if (s.publish) s.stream = capi::stream_config(c.stream_domain_id, c.stream_qos, c.stream_history_depth,
                                                c.stream_source_id, c.stream_topic, sizeof c.stream_topic);
  if (c.vmc_port > 65535) throw Error(Errc::invalid_argument, "config.vmc_port must be 0..65535");
  s.vmc_port = static_cast<uint16_t>(c.vmc_port);
  const size_t host_len = strnlen(c.vmc_host, sizeof c.vmc_host);
  if (s.vmc_port && (host_len == 0 || host_len == sizeof c.vmc_host))
    throw Error(Errc::invalid_argument, "config.vmc_host must be a NUL-terminated host name");
  s.vmc_host.assign(c.vmc_host, host_len);
  s.detector = capi::detector_config(c.detector);
  return s;
}

const Session& result_of(const octocap_session_t* s) {
  capi::checked(s, "session");
  if (!s->session->has_result()) throw Error(Errc::no_result, "no frame has been solved yet");
  return *s->session;
}

}  // namespace

extern "C" {

void octocap_session_config_init(octocap_session_config_t* c) {
  if (!c) return;
  *c = octocap_session_config_t{};
  c->struct_size = sizeof(octocap_session_config_t);
  c->layout = OCTOCAP_LAYOUT_BODY_25;
  c->method = OCTOCAP_METHOD_AUTO;
  c->filter = OCTOCAP_FILTER_ONE_EURO;
  c->up_axis = OCTOCAP_UP_AUTO;
  c->sigma = 0;
  c->min_views = 2;
  c->delta_m = 0.01f;
  c->pixel_tolerance = 4.0f;
  c->max_candidates = 8;
  c->min_confidence = 0.3f;
  c->outlier_threshold_px = 15.0f;
  c->filter_min_cutoff_hz = 1.5f;
  c->filter_beta = 20.0f;
  c->worker_threads = 0;
  c->first_frame_index = 0;
  c->stream_enable = 0;
  c->stream_domain_id = 0;
  c->stream_qos = OCTOCAP_QOS_LIVE;
  c->stream_history_depth = 256;
  c->stream_source_id = 1;
  capi::copy_name(c->stream_topic, sizeof c->stream_topic, "octocap");
  c->vmc_port = 0;
  capi::copy_name(c->vmc_host, sizeof c->vmc_host, "127.0.0.1");
  octocap_detector_config_init(&c->detector);
}

octocap_result_t octocap_session_create(const octocap_session_config_t* cfg, const octocap_calibration_t* calib,
                                        octocap_session_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(cfg, "cfg");
    capi::checked(calib, "calibration");
    const SessionConfig config = from_c(*cfg);
    auto session = std::make_unique<Session>(config, calib->cameras);
    *out = capi::make_handle<octocap_session_t>(std::move(session));
  });
}

void octocap_session_destroy(octocap_session_t* s) { capi::destroy_handle(s); }

octocap_result_t octocap_session_solve_keypoints(octocap_session_t* s, const octocap_keypoint2d_t* keypoints,
                                                 const uint32_t* people_per_view, uint32_t view_count,
                                                 int64_t timestamp_us) {
  return capi::guard([&] {
    capi::checked(s, "session");
    Session& session = *s->session;
    const size_t cams = session.calibration().size();
    if (view_count != cams)
      throw Error(Errc::camera_mismatch, "view_count is " + std::to_string(view_count) +
                                             ", the calibration has " + std::to_string(cams) + " cameras");
    const size_t K = session.keypoint_layout().keypoints.size();
    size_t total_people = 0;
    for (uint32_t v = 0; v < view_count; ++v) {
      const uint32_t n = people_per_view ? people_per_view[v] : 1;
      if (n > 64) throw Error(Errc::invalid_argument, "more than 64 people in view " + std::to_string(v));
      total_people += n;
    }
    if (total_people > 0) capi::require(keypoints, "keypoints");
    std::vector<std::vector<Person2D>> people(view_count);
    size_t offset = 0;
    for (uint32_t v = 0; v < view_count; ++v) {
      const uint32_t n = people_per_view ? people_per_view[v] : 1;
      for (uint32_t p = 0; p < n; ++p) {
        Person2D person(K);
        for (size_t k = 0; k < K; ++k) {
          const octocap_keypoint2d_t& kp = keypoints[offset++];
          // NaN/inf or a (0,0) OpenPose placeholder is "not detected", not an error: detectors emit them.
          const bool ok = std::isfinite(kp.x) && std::isfinite(kp.y) && std::isfinite(kp.confidence) &&
                          kp.confidence > 0 && !(kp.x == 0 && kp.y == 0);
          person[k] = ok ? Keypoint2D{kp.x, kp.y, kp.confidence} : Keypoint2D{};
        }
        people[v].push_back(std::move(person));
      }
    }
    session.solve(people, timestamp_us);
  });
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

octocap_result_t octocap_session_get_frame_info(const octocap_session_t* s, octocap_frame_info_t* out) {
  return capi::guard([&] { capi::query_frame_info(result_of(s).result(), out); });
}

octocap_result_t octocap_session_get_keypoints3d(const octocap_session_t* s, octocap_joint_t* out,
                                                 uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_keypoints(result_of(s).result(), out, capacity, count); });
}

octocap_result_t octocap_session_get_joints(const octocap_session_t* s, octocap_joint_t* out, uint32_t capacity,
                                            uint32_t* count) {
  return capi::guard([&] { capi::query_joints(result_of(s).result(), out, capacity, count); });
}

octocap_result_t octocap_session_get_selected_people(const octocap_session_t* s, int32_t* out, uint32_t capacity,
                                                     uint32_t* count) {
  return capi::guard([&] {
    const auto& sel = result_of(s).selected_people();
    capi::require(count, "count");
    *count = static_cast<uint32_t>(sel.size());
    if (!out) return;
    if (capacity < sel.size()) throw Error(Errc::buffer_too_small, "capacity is below the view count");
    for (size_t v = 0; v < sel.size(); ++v) out[v] = sel[v];
  });
}

octocap_result_t octocap_session_get_bones(const octocap_session_t* s, octocap_coord_frame_t frame,
                                           octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_bones(result_of(s).result(), frame, out, capacity, count); });
}

octocap_result_t octocap_session_get_bone_rotation(const octocap_session_t* s, uint32_t bone,
                                                   octocap_coord_frame_t frame, octocap_quat_t* out) {
  return capi::guard([&] {
    capi::require(out, "out");
    if (bone >= static_cast<uint32_t>(kBoneCount))
      throw Error(Errc::invalid_argument, "bone index " + std::to_string(bone) + " out of range");
    octocap_bone_pose_t bones[kBoneCount];
    uint32_t n = 0;
    capi::query_bones(result_of(s).result(), frame, bones, kBoneCount, &n);
    *out = bones[bone].local_rotation;
  });
}

octocap_result_t octocap_session_definition_counter(const octocap_session_t* s, uint32_t* out) {
  return capi::guard([&] {
    capi::checked(s, "session");
    capi::require(out, "out");
    *out = s->definition_counter;
  });
}

}  // extern "C"
