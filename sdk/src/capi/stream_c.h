// C stream settings -> StreamConfig, checked (used by session config and subscriber config).
#pragma once
#include <cstddef>
#include <cstdint>

#include "stream/stream_config.h"

namespace octocap::capi {

StreamConfig stream_config(uint32_t domain_id, int32_t qos, uint32_t history_depth, uint32_t source_id,
                           const char* topic, size_t topic_capacity);

}  // namespace octocap::capi
