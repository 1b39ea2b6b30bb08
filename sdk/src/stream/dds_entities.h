// Cyclone DDS plumbing shared by publisher and subscriber: participant, topics and the two QoS profiles.
#pragma once
#include <dds/dds.h>

#include <string>

#include "stream/stream_config.h"

namespace octocap::internal {

// Owns a participant; deleting it deletes every entity created under it. With a security identity folder (see
// dds_security.h) the participant joins only a secured network, and an entity its permissions refuse is an error
// naming the identity and the topic.
class DdsParticipant {
 public:
  explicit DdsParticipant(uint32_t domain_id, const std::string& security = "");
  ~DdsParticipant();
  DdsParticipant(const DdsParticipant&) = delete;
  DdsParticipant& operator=(const DdsParticipant&) = delete;
  dds_entity_t get() const { return participant_; }

  dds_entity_t topic(const dds_topic_descriptor_t* desc, const std::string& name);
  // Take ownership of `qos` (deleted whatever happens).
  dds_entity_t writer(dds_entity_t topic, dds_qos_t* qos, const char* what);
  dds_entity_t reader(dds_entity_t topic, dds_qos_t* qos, const char* what);

 private:
  dds_entity_t check(dds_entity_t rc, const char* what, dds_entity_t topic, const char* may) const;
  dds_entity_t participant_ = 0;
  std::string identity_;  // "" unsecured; else "identity 'KEYSTORE/NAME' (role R)"
};

// RELIABLE + TRANSIENT_LOCAL + KEEP_LAST 1.
dds_qos_t* definition_qos();
// The pose profile of `config` (see StreamConfig).
dds_qos_t* pose_qos(const StreamConfig& config);
// BEST_EFFORT + VOLATILE + KEEP_LAST 1 (per camera): a capture node's 2D keypoints.
dds_qos_t* keypoints_qos();
// Throws Error(io) naming what failed when rc < 0.
dds_entity_t check_dds(dds_entity_t rc, const char* what);

}  // namespace octocap::internal
