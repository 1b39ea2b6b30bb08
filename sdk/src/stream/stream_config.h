// Where and how skeletons are streamed over DDS.
#pragma once
#include <cstdint>
#include <string>

namespace octocap::internal {

// live: BEST_EFFORT, VOLATILE, KEEP_LAST 1 - engines want the newest pose, never an old one late.
// record: RELIABLE, TRANSIENT_LOCAL, KEEP_LAST history_depth - every frame arrives; a late joiner gets the
// last history_depth poses. Publisher and subscriber must use the same profile.
enum class StreamQos : int { live = 0, record = 1 };

struct StreamConfig {
  uint32_t domain_id = 0;
  std::string topic = "octocap";  // topics are "<topic>_definition" and "<topic>_pose" (or "<topic>_people")
  StreamQos qos = StreamQos::live;
  uint32_t history_depth = 256;
  uint32_t source_id = 1;         // publisher: this rig's id; subscriber: 0 = any source
  bool several_people = false;    // publisher: everyone on "<topic>_people", not the first person on "<topic>_pose"
  std::string security;           // a keystore identity folder (stream/keystore.h): DDS Security on; "" off
};

}  // namespace octocap::internal
