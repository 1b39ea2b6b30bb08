// C stream settings -> StreamConfig (used by session config and subscriber config): mapped, not judged; the DDS
// publisher and subscriber check what they are given (StreamConfig::validate).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "stream/stream_config.h"

namespace octocap::internal::capi {

// A DDS topic base name from a C char array, NUL-terminated within it.
std::string topic_name(const char* topic, size_t topic_capacity, const char* what);
StreamConfig stream_config(uint32_t domain_id, int32_t qos, uint32_t history_depth, uint32_t source_id,
                           const char* topic, size_t topic_capacity);

}  // namespace octocap::internal::capi
