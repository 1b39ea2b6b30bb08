// Stream subscribers. Without DDS in the build every call says so (OCTOCAP_ERROR_UNSUPPORTED).
#include <cctype>
#include <cstring>

#include "capi/boundary.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"
#include "capi/stream_c.h"
#include "stream/dds_subscriber.h"

using namespace octocap;

struct octocap_subscriber_t {
  std::unique_ptr<DdsSubscriber> subscriber;
};

namespace octocap::capi {

StreamConfig stream_config(uint32_t domain_id, int32_t qos, uint32_t history_depth, uint32_t source_id,
                           const char* topic, size_t topic_capacity) {
  StreamConfig s;
  if (domain_id > 232) throw Error(Errc::invalid_argument, "DDS domain id must be 0..232");
  if (qos != OCTOCAP_QOS_LIVE && qos != OCTOCAP_QOS_RECORD)
    throw Error(Errc::invalid_argument, "stream qos must be OCTOCAP_QOS_LIVE or OCTOCAP_QOS_RECORD");
  if (history_depth < 1 || history_depth > 100000)
    throw Error(Errc::invalid_argument, "stream history depth must be 1..100000");
  const size_t len = strnlen(topic, topic_capacity);
  if (len == 0 || len == topic_capacity)
    throw Error(Errc::invalid_argument, "stream topic must be a NUL-terminated, non-empty name");
  for (size_t i = 0; i < len; ++i)
    if (!std::isalnum(static_cast<unsigned char>(topic[i])) && topic[i] != '_')
      throw Error(Errc::invalid_argument, "stream topic may hold letters, digits and '_' only");
  s.domain_id = domain_id;
  s.qos = static_cast<StreamQos>(qos);
  s.history_depth = history_depth;
  s.source_id = source_id;
  s.topic.assign(topic, len);
  return s;
}

}  // namespace octocap::capi

namespace {

const FrameResult& current(const octocap_subscriber_t* s) {
  capi::checked(s, "subscriber");
  if (s->subscriber->stats().frames_received == 0) throw Error(Errc::no_result, "no pose has been received yet");
  return s->subscriber->frame();
}

}  // namespace

extern "C" {

void octocap_subscriber_config_init(octocap_subscriber_config_t* c) {
  if (!c) return;
  *c = octocap_subscriber_config_t{};
  c->struct_size = sizeof *c;
  c->qos = OCTOCAP_QOS_LIVE;
  c->history_depth = 256;
  capi::copy_name(c->topic, sizeof c->topic, "octocap");
}

octocap_result_t octocap_subscriber_create(const octocap_subscriber_config_t* cfg, octocap_subscriber_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(cfg, "cfg");
    if (cfg->struct_size != sizeof(octocap_subscriber_config_t))
      throw Error(Errc::struct_size, "octocap_subscriber_config_t.struct_size is " + std::to_string(cfg->struct_size) +
                                         ", expected " + std::to_string(sizeof(octocap_subscriber_config_t)));
    const StreamConfig sc =
        capi::stream_config(cfg->domain_id, cfg->qos, cfg->history_depth, cfg->source_id, cfg->topic, sizeof cfg->topic);
#ifdef OCTOCAP_HAVE_DDS
    auto sub = std::make_unique<DdsSubscriber>(sc);
    *out = capi::make_handle<octocap_subscriber_t>(std::move(sub));
#else
    (void)sc;
    throw Error(Errc::unsupported, "this build of octocap has no DDS streaming (OCTOCAP_WITH_DDS=OFF)");
#endif
  });
}

void octocap_subscriber_destroy(octocap_subscriber_t* s) { capi::destroy_handle(s); }

octocap_result_t octocap_subscriber_take(octocap_subscriber_t* s, int32_t timeout_ms) {
  return capi::guard([&] {
    capi::checked(s, "subscriber");
    if (!s->subscriber->take_next(timeout_ms))
      throw Error(Errc::no_result, "no pose arrived within " + std::to_string(timeout_ms) + " ms");
  });
}

octocap_result_t octocap_subscriber_get_stream_info(const octocap_subscriber_t* s, octocap_stream_info_t* out) {
  return capi::guard([&] {
    capi::checked(s, "subscriber");
    capi::require(out, "out");
    const StreamStats& st = s->subscriber->stats();
    *out = octocap_stream_info_t{};
    out->frames_received = st.frames_received;
    out->frames_lost = st.frames_lost;
    out->last_gap = st.last_gap;
    out->restarts = st.restarts;
    out->rejected = st.rejected;
    out->source_id = st.source_id;
    out->definition_counter = st.definition_counter;
    out->layout = static_cast<octocap_layout_t>(s->subscriber->layout());
    out->has_definition = st.has_definition ? 1 : 0;
  });
}

octocap_result_t octocap_subscriber_get_frame_info(const octocap_subscriber_t* s, octocap_frame_info_t* out) {
  return capi::guard([&] { capi::query_frame_info(current(s), out); });
}

octocap_result_t octocap_subscriber_get_keypoints3d(const octocap_subscriber_t* s, octocap_joint_t* out,
                                                    uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_keypoints(current(s), out, capacity, count); });
}

octocap_result_t octocap_subscriber_get_joints(const octocap_subscriber_t* s, octocap_joint_t* out, uint32_t capacity,
                                               uint32_t* count) {
  return capi::guard([&] { capi::query_joints(current(s), out, capacity, count); });
}

octocap_result_t octocap_subscriber_get_bones(const octocap_subscriber_t* s, octocap_coord_frame_t frame,
                                              octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_bones(current(s), frame, out, capacity, count); });
}

}  // extern "C"
