#include "stream/keypoint_publisher.h"

#include "core/log.h"
#include "stream/dds_entities.h"

namespace octocap::internal {

struct KeypointPublisher::Impl {
  DdsParticipant participant;
  dds_entity_t writer = 0;
  ViewKeypointsBuffers buffers;
  explicit Impl(uint32_t domain) : participant(domain) {}
};

KeypointPublisher::KeypointPublisher(uint32_t domain_id, const std::string& topic)
    : impl_(std::make_unique<Impl>(domain_id)) {
  const dds_entity_t p = impl_->participant.get();
  const dds_entity_t t = create_topic(p, &octocap_wire_ViewKeypoints_desc, topic + "_keypoints2d");
  dds_qos_t* q = keypoints_qos();
  impl_->writer = dds_create_writer(p, t, q, nullptr);
  dds_delete_qos(q);
  check_dds(impl_->writer, "creating the keypoints writer");
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
