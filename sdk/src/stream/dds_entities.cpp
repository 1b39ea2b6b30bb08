#include "stream/dds_entities.h"

#include "core/error.h"

namespace octocap::internal {

dds_entity_t check_dds(dds_entity_t rc, const char* what) {
  if (rc < 0) throw Error(Errc::io, std::string("DDS: ") + what + " failed: " + dds_strretcode(rc));
  return rc;
}

DdsParticipant::DdsParticipant(uint32_t domain_id)
    : participant_(check_dds(dds_create_participant(domain_id, nullptr, nullptr), "creating the participant")) {}

DdsParticipant::~DdsParticipant() { dds_delete(participant_); }

dds_entity_t create_topic(dds_entity_t participant, const dds_topic_descriptor_t* desc, const std::string& name) {
  return check_dds(dds_create_topic(participant, desc, name.c_str(), nullptr, nullptr), "creating a topic");
}

dds_qos_t* definition_qos() {
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(q, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 1);
  return q;
}

dds_qos_t* pose_qos(const StreamConfig& config) {
  dds_qos_t* q = dds_create_qos();
  if (config.qos == StreamQos::record) {
    dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(q, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(q, DDS_HISTORY_KEEP_LAST, static_cast<int32_t>(config.history_depth));
  } else {
    dds_qset_reliability(q, DDS_RELIABILITY_BEST_EFFORT, 0);
    dds_qset_durability(q, DDS_DURABILITY_VOLATILE);
    dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 1);
  }
  return q;
}

dds_qos_t* keypoints_qos() {
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_qset_durability(q, DDS_DURABILITY_VOLATILE);
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 1);
  return q;
}

}  // namespace octocap::internal
