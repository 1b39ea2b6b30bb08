#include "stream/dds_entities.h"

#include "core/error.h"
#include "stream/dds_security.h"

namespace octocap::internal {

dds_entity_t check_dds(dds_entity_t rc, const char* what) {
  if (rc < 0) throw Error(Errc::io, std::string("DDS: ") + what + " failed: " + dds_strretcode(rc));
  return rc;
}

DdsParticipant::DdsParticipant(uint32_t domain_id, const std::string& security) {
  if (security.empty()) {
    participant_ = check_dds(dds_create_participant(domain_id, nullptr, nullptr), "creating the participant");
    return;
  }
  const SecureIdentity id = check_identity(security);
  identity_ = "identity '" + id.folder + "'" + (id.role.empty() ? "" : " (role " + id.role + ")");
  dds_qos_t* qos = dds_create_qos();
  set_security_qos(qos, id);
  participant_ = dds_create_participant(domain_id, qos, nullptr);
  dds_delete_qos(qos);
  // The files were checked: what is left is a governance that does not cover the domain, or plugins not installed.
  if (participant_ < 0)
    throw Error(Errc::io, "DDS: the secure participant of " + identity_ + " on domain " + std::to_string(domain_id) +
                              " failed: " + dds_strretcode(participant_) +
                              " (are Cyclone's security plugins, libdds_security_*.so, installed?)");
}

DdsParticipant::~DdsParticipant() { dds_delete(participant_); }

dds_entity_t DdsParticipant::check(dds_entity_t rc, const char* what, dds_entity_t topic, const char* may) const {
  if (rc == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY && !identity_.empty()) {
    char name[256] = "";
    if (topic > 0) dds_get_name(topic, name, sizeof name);
    throw Error(Errc::invalid_argument, "DDS security: " + identity_ + " may not " + may + " '" + name +
                                            "' (its permissions.xml; `octocap security add --role` gives each role "
                                            "what it needs)");
  }
  return check_dds(rc, what);
}

dds_entity_t DdsParticipant::topic(const dds_topic_descriptor_t* desc, const std::string& name) {
  const dds_entity_t t = dds_create_topic(participant_, desc, name.c_str(), nullptr, nullptr);
  if (t == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY && !identity_.empty())
    throw Error(Errc::invalid_argument, "DDS security: " + identity_ + " may neither publish nor read '" + name +
                                            "' (its permissions.xml)");
  return check_dds(t, "creating a topic");
}

dds_entity_t DdsParticipant::writer(dds_entity_t topic, dds_qos_t* qos, const char* what) {
  const dds_entity_t w = dds_create_writer(participant_, topic, qos, nullptr);
  dds_delete_qos(qos);
  return check(w, what, topic, "publish");
}

dds_entity_t DdsParticipant::reader(dds_entity_t topic, dds_qos_t* qos, const char* what) {
  const dds_entity_t r = dds_create_reader(participant_, topic, qos, nullptr);
  dds_delete_qos(qos);
  return check(r, what, topic, "read");
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
