// Cyclone DDS plumbing shared by publisher and subscriber: participant, topics and the two QoS profiles.
#pragma once
#include <dds/dds.h>

#include <string>

#include "stream/stream_config.h"

namespace octocap::internal {

// Owns a participant; deleting it deletes every entity created under it.
class DdsParticipant {
 public:
  explicit DdsParticipant(uint32_t domain_id);
  ~DdsParticipant();
  DdsParticipant(const DdsParticipant&) = delete;
  DdsParticipant& operator=(const DdsParticipant&) = delete;
  dds_entity_t get() const { return participant_; }

 private:
  dds_entity_t participant_;
};

dds_entity_t create_topic(dds_entity_t participant, const dds_topic_descriptor_t* desc, const std::string& name);
// RELIABLE + TRANSIENT_LOCAL + KEEP_LAST 1.
dds_qos_t* definition_qos();
// The pose profile of `config` (see StreamConfig).
dds_qos_t* pose_qos(const StreamConfig& config);
// BEST_EFFORT + VOLATILE + KEEP_LAST 1 (per camera): a capture node's 2D keypoints.
dds_qos_t* keypoints_qos();
// Throws Error(io) naming what failed when rc < 0.
dds_entity_t check_dds(dds_entity_t rc, const char* what);

}  // namespace octocap::internal
