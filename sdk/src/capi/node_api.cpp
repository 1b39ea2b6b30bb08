// Capture nodes: the C shell over pipeline/keypoint_node. Without DDS in the build, creating one says so
// (OCTOCAP_ERROR_UNSUPPORTED), and no node handle can exist.
#include "capi/boundary.h"
#include "capi/detect_c.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"
#include "capi/live_c.h"
#include "capi/stream_c.h"
#include "capi/struct_versions.h"

using namespace octocap::internal;

namespace {

#ifdef OCTOCAP_HAVE_DDS
KeypointNode& node_of(octocap_node_t* n) { return *capi::checked(n, "node")->node; }
const KeypointNode& node_of(const octocap_node_t* n) { return *capi::checked(n, "node")->node; }
#endif

[[maybe_unused]] [[noreturn]] void no_dds() {
  throw Error(Errc::unsupported, "this build of octocap has no DDS (OCTOCAP_WITH_DDS=OFF): no capture nodes");
}

}  // namespace

extern "C" {

octocap_result_t octocap_node_config_defaults(octocap_node_config_t* c, uint32_t struct_size) {
  return capi::guard([&] {
    capi::require(c, "cfg");
    capi::check_size(struct_size, capi::kNodeConfigSizes, "octocap_node_config_t");
    octocap_node_config_t d{};
    capi::copy_name(d.name, sizeof d.name, "node1");
    capi::copy_name(d.topic, sizeof d.topic, "octocap");
    capi::set_feed_defaults(d);
    capi::write_defaults(c, struct_size, d);
  });
}

octocap_result_t octocap_node_create(const octocap_node_config_t* given, const char* const* cameras,
                                     const char* const* names, uint32_t camera_count, octocap_node_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(given, "cfg");
    capi::check_size(given->struct_size, capi::kNodeConfigSizes, "octocap_node_config_t");
    if (camera_count == 0) throw Error(Errc::invalid_argument, "a capture node needs at least one camera");
    capi::require(cameras, "cameras");
    octocap_node_config_t defaults;
    octocap_node_config_init(&defaults);
    const octocap_node_config_t c = capi::widen(*given, defaults);
    const FeedOptions feeds =
        capi::feed_options(c.open_timeout_ms, c.read_timeout_ms, c.reconnect_max_ms, c.picture_rate_hz);
    const size_t name_len = strnlen(c.name, sizeof c.name);
    if (name_len == 0 || name_len == sizeof c.name)
      throw Error(Errc::invalid_argument, "cfg.name must be a NUL-terminated, non-empty name");
    const std::vector<std::string> specs = capi::strings(cameras, camera_count, "camera");
    const std::vector<std::string> camera_names =
        names ? capi::strings(names, camera_count, "name") : std::vector<std::string>{};
#ifdef OCTOCAP_HAVE_DDS
    NodeConfig config;
    config.name.assign(c.name, name_len);
    config.domain_id = c.domain_id;
    config.topic = capi::topic_name(c.topic, sizeof c.topic, "cfg.topic");
    config.security = capi::c_text(c.security, sizeof c.security, "cfg.security");
    config.feeds = feeds;
    config.detect_rate_hz = c.detect_rate_hz;
    auto node = std::make_unique<KeypointNode>(config, specs, camera_names);
    *out = capi::make_handle<octocap_node_t>(std::move(node));
#else
    (void)feeds;
    (void)specs;
    (void)camera_names;
    no_dds();
#endif
  });
}

octocap_result_t octocap_node_set_detector(octocap_node_t* n, const octocap_detector_config_t* cfg) {
  return capi::guard([&] {
#ifdef OCTOCAP_HAVE_DDS
    KeypointNode& node = node_of(n);
    capi::require(cfg, "cfg");
    node.set_detector(capi::detector_config(*cfg));
#else
    capi::checked(n, "node");
    (void)cfg;
    no_dds();
#endif
  });
}

octocap_result_t octocap_node_start(octocap_node_t* n) {
  return capi::guard([&] {
#ifdef OCTOCAP_HAVE_DDS
    node_of(n).start();
#else
    capi::checked(n, "node");
    no_dds();
#endif
  });
}

octocap_result_t octocap_node_stop(octocap_node_t* n) {
  return capi::guard([&] {
#ifdef OCTOCAP_HAVE_DDS
    node_of(n).stop();
#else
    capi::checked(n, "node");
    no_dds();
#endif
  });
}

void octocap_node_destroy(octocap_node_t* n) { capi::destroy_handle(n); }

octocap_result_t octocap_node_get_stats(const octocap_node_t* n, octocap_node_stats_t* out) {
  return capi::guard([&] {
#ifdef OCTOCAP_HAVE_DDS
    const KeypointNode& node = node_of(n);
    capi::fill_sized(out, sizeof(octocap_node_stats_t), "octocap_node_stats_t", [&](octocap_node_stats_t& o) {
      const NodeStats s = node.stats();
      o.running = s.running ? 1 : 0;
      o.finished = s.finished ? 1 : 0;
      o.camera_count = static_cast<uint32_t>(node.camera_count());
      o.published = s.published;
      o.with_person = s.with_person;
      o.detect_ms = static_cast<float>(s.detect_ms);
      o.processing_ms = static_cast<float>(s.processing_ms);
      o.readers = s.readers;
    });
#else
    capi::checked(n, "node");
    (void)out;
    no_dds();
#endif
  });
}

octocap_result_t octocap_node_get_camera_status(const octocap_node_t* n, uint32_t index, octocap_camera_status_t* out) {
  return capi::guard([&] {
#ifdef OCTOCAP_HAVE_DDS
    const KeypointNode& node = node_of(n);
    capi::check_camera_index(index, node.camera_count());
    capi::fill_camera_status(node.camera_status(index), node.camera_name(index), out);
#else
    capi::checked(n, "node");
    (void)index;
    (void)out;
    no_dds();
#endif
  });
}

}  // extern "C"
