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
  // Throws Error(invalid_argument): the domain or the topic (check_dds_names), a history depth beyond 1..100000.
  void validate() const;
};

// The DDS names every config that reaches DDS gives (streams, capture nodes, the live engine's remote cameras):
// a domain id 0..232 (the highest RTPS maps to ports) and a topic of letters, digits and '_' (it becomes the stem of
// DDS topic names), not empty. Throws Error(invalid_argument) naming `what`.
void check_dds_names(uint32_t domain_id, const std::string& topic, const std::string& what);

}  // namespace octocap::internal
