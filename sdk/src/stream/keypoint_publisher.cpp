#include "stream/keypoint_publisher.h"

#include "core/log.h"
#include "stream/dds_entities.h"
#include "stream/topics.h"

namespace octocap::internal {

struct KeypointPublisher::Impl {
  DdsParticipant participant;
  dds_entity_t writer = 0;
  ViewKeypointsBuffers buffers;
  Impl(uint32_t domain, const std::string& security) : participant(domain, security) {}
};

KeypointPublisher::KeypointPublisher(uint32_t domain_id, const std::string& topic, const std::string& security)
    : impl_(std::make_unique<Impl>(domain_id, security)) {
  DdsParticipant& p = impl_->participant;
  const dds_entity_t t = p.topic(&octocap_wire_ViewKeypoints_desc, topic_name(topic, kKeypointsTopicSuffix));
  impl_->writer = p.writer(t, keypoints_qos(), "creating the keypoints writer");
}

KeypointPublisher::~KeypointPublisher() = default;

void KeypointPublisher::publish(const RemoteView& view) {
  const std::lock_guard<std::mutex> lock(mutex_);
  fill_view_keypoints(view, impl_->buffers);
  const dds_return_t rc = dds_write(impl_->writer, &impl_->buffers.sample);
  if (rc < 0) log(LogLevel::warning, std::string("DDS: writing keypoints failed: ") + dds_strretcode(rc));
}

uint32_t KeypointPublisher::matched_readers() const {
  dds_publication_matched_status_t st{};
  if (dds_get_publication_matched_status(impl_->writer, &st) < 0) return 0;
  return st.current_count;
}

}  // namespace octocap::internal
