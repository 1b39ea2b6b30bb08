// Stream subscribers. Without DDS in the build every call says so (OCTOCAP_ERROR_UNSUPPORTED).
#include <cstring>

#include "capi/boundary.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"
#include "capi/stream_c.h"
#include "capi/struct_versions.h"

using namespace octocap::internal;

namespace octocap::internal::capi {

// A C topic field as text: NUL-terminated within its field (what it may hold is check_dds_names' rule, applied
// where it is used).
std::string topic_name(const char* topic, size_t topic_capacity, const char* what) {
  const size_t len = strnlen(topic, topic_capacity);
  if (len == topic_capacity) throw Error(Errc::invalid_argument, std::string(what) + " is not NUL-terminated");
  return std::string(topic, len);
}

StreamConfig stream_config(uint32_t domain, int32_t qos, uint32_t history_depth, uint32_t source_id,
                           const char* topic, size_t topic_capacity) {
  StreamConfig s;
  s.domain_id = domain;
  if (qos != OCTOCAP_QOS_LIVE && qos != OCTOCAP_QOS_RECORD)
    throw Error(Errc::invalid_argument, "stream qos must be OCTOCAP_QOS_LIVE or OCTOCAP_QOS_RECORD");
  s.topic = topic_name(topic, topic_capacity, "stream topic");
  s.qos = static_cast<StreamQos>(qos);
  s.history_depth = history_depth;
  s.source_id = source_id;
  return s;
}

}  // namespace octocap::internal::capi

namespace {

#ifdef OCTOCAP_HAVE_DDS
DdsSubscriber& subscriber_of(const octocap_subscriber_t* s) { return *capi::checked(s, "subscriber")->subscriber; }
#else
[[noreturn]] void no_dds() {
  throw Error(Errc::unsupported, "this build of octocap has no DDS streaming (OCTOCAP_WITH_DDS=OFF)");
}
struct NoSubscriber {
  [[noreturn]] const FrameResult& frame() const { no_dds(); }
};
NoSubscriber subscriber_of(const octocap_subscriber_t* s) {
  capi::checked(s, "subscriber");
  no_dds();
}
#endif

const FrameResult& current(const octocap_subscriber_t* s) {
#ifdef OCTOCAP_HAVE_DDS
  if (subscriber_of(s).stats().frames_received == 0) throw Error(Errc::no_result, "no pose has been received yet");
#endif
  return subscriber_of(s).frame();
}

}  // namespace

extern "C" {

octocap_result_t octocap_subscriber_config_defaults(octocap_subscriber_config_t* c, uint32_t struct_size) {
  return capi::guard([&] {
    capi::require(c, "cfg");
    capi::check_size(struct_size, capi::kSubscriberConfigSizes, "octocap_subscriber_config_t");
    octocap_subscriber_config_t d{};
    d.qos = OCTOCAP_QOS_LIVE;
    d.history_depth = 256;
    capi::copy_name(d.topic, sizeof d.topic, "octocap");
    capi::write_defaults(c, struct_size, d);
  });
}

octocap_result_t octocap_subscriber_create(const octocap_subscriber_config_t* cfg, octocap_subscriber_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(cfg, "cfg");
    capi::check_size(cfg->struct_size, capi::kSubscriberConfigSizes, "octocap_subscriber_config_t");
    octocap_subscriber_config_t defaults;
    octocap_subscriber_config_init(&defaults);
    const octocap_subscriber_config_t c = capi::widen(*cfg, defaults);
    StreamConfig sc = capi::stream_config(c.domain_id, c.qos, c.history_depth, c.source_id, c.topic, sizeof c.topic);
    sc.security = capi::c_text(c.security, sizeof c.security, "cfg.security");
#ifdef OCTOCAP_HAVE_DDS
    auto sub = std::make_unique<DdsSubscriber>(sc);
    *out = capi::make_handle<octocap_subscriber_t>(std::move(sub));
#else
    (void)sc;
    no_dds();
#endif
  });
}

void octocap_subscriber_destroy(octocap_subscriber_t* s) { capi::destroy_handle(s); }

octocap_result_t octocap_subscriber_take_frame(octocap_subscriber_t* s, int32_t timeout_ms, octocap_frame_t** out) {
  bool taken = false;
  const octocap_result_t r = capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
#ifdef OCTOCAP_HAVE_DDS
    DdsSubscriber& sub = subscriber_of(s);
    if (!sub.take_next(timeout_ms)) return;
    *out = capi::make_frame(std::make_shared<const FrameResult>(sub.frame()));
    taken = true;
#else
    (void)timeout_ms;
    subscriber_of(s);
#endif
  });
  return capi::status_unless(r, taken, OCTOCAP_STATUS_TIMEOUT);
}

octocap_result_t octocap_subscriber_take(octocap_subscriber_t* s, int32_t timeout_ms) {
  return capi::guard([&] {
#ifdef OCTOCAP_HAVE_DDS
    if (!subscriber_of(s).take_next(timeout_ms))
      throw Error(Errc::no_result, "no pose arrived within " + std::to_string(timeout_ms) + " ms");
#else
    (void)timeout_ms;
    subscriber_of(s);
#endif
  });
}

octocap_result_t octocap_subscriber_get_stream_info(const octocap_subscriber_t* s, octocap_stream_info_t* out) {
  return capi::guard([&] {
    capi::require(out, "out");
#ifdef OCTOCAP_HAVE_DDS
    const DdsSubscriber& sub = subscriber_of(s);
    const StreamStats& st = sub.stats();
    *out = octocap_stream_info_t{};
    out->frames_received = st.frames_received;
    out->frames_lost = st.frames_lost;
    out->last_gap = st.last_gap;
    out->restarts = st.restarts;
    out->rejected = st.rejected;
    out->source_id = st.source_id;
    out->definition_counter = st.definition_counter;
    out->layout = static_cast<octocap_layout_t>(sub.layout());
    out->has_definition = st.has_definition ? 1 : 0;
#else
    subscriber_of(s);
#endif
  });
}

// Deprecated 0.x queries of the current received frame.

octocap_result_t octocap_subscriber_get_frame_info(const octocap_subscriber_t* s, octocap_frame_info_t* out) {
  return capi::guard([&] { capi::query_frame_info(current(s), out); });
}

octocap_result_t octocap_subscriber_get_keypoints3d(const octocap_subscriber_t* s, octocap_joint_t* out,
                                                    uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_keypoints(current(s).person_or_blank(0), out, capacity, count); });
}

octocap_result_t octocap_subscriber_get_joints(const octocap_subscriber_t* s, octocap_joint_t* out, uint32_t capacity,
                                               uint32_t* count) {
  return capi::guard([&] { capi::query_joints(current(s).person_or_blank(0), out, capacity, count); });
}

octocap_result_t octocap_subscriber_get_bones(const octocap_subscriber_t* s, octocap_coord_frame_t frame,
                                              octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_bones(current(s).person_or_blank(0), frame, out, capacity, count); });
}

}  // extern "C"
