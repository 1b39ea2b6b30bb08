// What the live-capture and capture-node handles share at the C boundary.
#pragma once
#include <string>
#include <vector>

#include "capture/feed_status.h"
#include "octocap/octocap.h"

namespace octocap::internal::capi {

// A camera's status into the caller's struct (its struct_size bytes).
void fill_camera_status(const FeedStatus& s, const std::string& name, octocap_camera_status_t* out);
// The camera settings of a live capture's and a capture node's config, checked (errors name the field).
FeedOptions feed_options(uint32_t open_timeout_ms, uint32_t read_timeout_ms, uint32_t reconnect_max_ms,
                         float picture_rate_hz);
// The camera settings' defaults in a C config (live or node: the fields are named alike), from the C++ ones.
template <class Config>
void set_feed_defaults(Config& d) {
  const FeedOptions feeds;
  d.open_timeout_ms = static_cast<uint32_t>(feeds.source.open_timeout_ms);
  d.read_timeout_ms = static_cast<uint32_t>(feeds.source.read_timeout_ms);
  d.reconnect_max_ms = static_cast<uint32_t>(feeds.reconnect_max_ms);
  d.picture_rate_hz = static_cast<float>(feeds.source.picture_rate_hz);
}
// `count` C strings (`what` 0, 1, ... names a NULL one in the error).
std::vector<std::string> strings(const char* const* values, uint32_t count, const char* what);
// INVALID_ARGUMENT for a camera index beyond `count`.
void check_camera_index(uint32_t index, size_t count);

}  // namespace octocap::internal::capi
