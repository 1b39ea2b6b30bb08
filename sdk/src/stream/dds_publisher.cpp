#include "stream/dds_publisher.h"

#include "core/error.h"
#include "core/log.h"
#include "stream/dds_entities.h"
#include "stream/topics.h"
#include "stream/wire_convert.h"

namespace octocap::internal {

struct DdsPublisher::Impl {
  DdsParticipant participant;
  dds_entity_t pose_writer = 0;
  uint32_t definition_counter = 1;
  DefinitionBuffers definition;
  PoseBuffers pose;
  PeopleBuffers people;
  Impl(uint32_t domain, const std::string& security) : participant(domain, security) {}
};

DdsPublisher::DdsPublisher(const StreamConfig& config, LayoutId layout, uint32_t definition_counter)
    : impl_((config.validate(), std::make_unique<Impl>(config.domain_id, config.security))),
      config_(config),
      capacity_(config.qos == StreamQos::record ? std::max<size_t>(config.history_depth, 64) : 1) {
  DdsParticipant& p = impl_->participant;
  const dds_entity_t def_topic =
      p.topic(&octocap_wire_SkeletonDefinition_desc, topic_name(config.topic, kDefinitionTopicSuffix));
  // A several-people session writes People instead of Pose (the IDL says why).
  const dds_entity_t pose_topic =
      config.several_people ? p.topic(&octocap_wire_PeopleFrame_desc, topic_name(config.topic, kPeopleTopicSuffix))
                            : p.topic(&octocap_wire_Pose_desc, topic_name(config.topic, kPoseTopicSuffix));
  const dds_entity_t def_writer = p.writer(def_topic, definition_qos(), "creating the definition writer");
  impl_->pose_writer = p.writer(pose_topic, pose_qos(config), "creating the pose writer");
  impl_->definition_counter = definition_counter;
  fill_definition(layout, config.source_id, impl_->definition_counter, impl_->definition);
  check_dds(dds_write(def_writer, &impl_->definition.sample), "writing the skeleton definition");
  thread_ = std::thread([this] { run(); });
}

DdsPublisher::~DdsPublisher() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void DdsPublisher::publish(const FrameResult& frame) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (queue_.size() >= capacity_) {
      queue_.pop_front();
      ++dropped_;
    }
    queue_.push_back(frame);
  }
  wake_.notify_one();
}

void DdsPublisher::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [&] { return queue_.empty() && !writing_; });
}

uint64_t DdsPublisher::dropped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

uint32_t DdsPublisher::matched_readers() const {
  dds_publication_matched_status_t st{};
  if (dds_get_publication_matched_status(impl_->pose_writer, &st) < 0) return 0;
  return st.current_count;
}

void DdsPublisher::run() {
  for (;;) {
    FrameResult frame;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, nothing left
      frame = std::move(queue_.front());
      queue_.pop_front();
      writing_ = true;
    }
    dds_return_t rc;
    if (config_.several_people) {
      fill_people(frame, config_.source_id, impl_->definition_counter, impl_->people);
      rc = dds_write(impl_->pose_writer, &impl_->people.sample);
    } else {
      fill_pose(frame, config_.source_id, impl_->definition_counter, impl_->pose);
      rc = dds_write(impl_->pose_writer, &impl_->pose.sample);
    }
    if (rc < 0) log(LogLevel::warning, std::string("DDS: writing a pose failed: ") + dds_strretcode(rc));
    {
      std::lock_guard<std::mutex> lock(mutex_);
      writing_ = false;
    }
    idle_.notify_all();
  }
}

}  // namespace octocap::internal
