#include "stream/dds_subscriber.h"

#include "core/error.h"
#include "core/log.h"
#include "stream/dds_entities.h"
#include "stream/topics.h"
#include "stream/wire_convert.h"

namespace octocap::internal {

struct DdsSubscriber::Impl {
  DdsParticipant participant;
  dds_entity_t def_reader = 0, pose_reader = 0, people_reader = 0, waitset = 0;
  Impl(uint32_t domain, const std::string& security) : participant(domain, security) {}
};

DdsSubscriber::DdsSubscriber(const StreamConfig& config)
    : impl_((config.validate(), std::make_unique<Impl>(config.domain_id, config.security))), config_(config) {
  DdsParticipant& p = impl_->participant;
  const dds_entity_t def_topic =
      p.topic(&octocap_wire_SkeletonDefinition_desc, topic_name(config.topic, kDefinitionTopicSuffix));
  const dds_entity_t pose_topic = p.topic(&octocap_wire_Pose_desc, topic_name(config.topic, kPoseTopicSuffix));
  const dds_entity_t people_topic =
      p.topic(&octocap_wire_PeopleFrame_desc, topic_name(config.topic, kPeopleTopicSuffix));
  impl_->def_reader = p.reader(def_topic, definition_qos(), "creating the definition reader");
  impl_->pose_reader = p.reader(pose_topic, pose_qos(config), "creating the pose reader");
  impl_->people_reader = p.reader(people_topic, pose_qos(config), "creating the people reader");
  impl_->waitset = check_dds(dds_create_waitset(p.get()), "creating a waitset");
  for (dds_entity_t reader : {impl_->pose_reader, impl_->people_reader}) {
    const dds_entity_t ready = check_dds(dds_create_readcondition(reader, DDS_ANY_STATE), "creating a read condition");
    check_dds(dds_waitset_attach(impl_->waitset, ready, 0), "attaching the read condition");
  }
}

DdsSubscriber::~DdsSubscriber() = default;

void DdsSubscriber::take_definitions() {
  void* samples[1] = {nullptr};
  dds_sample_info_t info[1];
  for (;;) {
    const dds_return_t n = dds_take(impl_->def_reader, samples, info, 1, 1);
    if (n <= 0) return;
    if (info[0].valid_data) {
      const auto* d = static_cast<const octocap_wire_SkeletonDefinition*>(samples[0]);
      const bool ours = config_.source_id == 0 || d->source_id == config_.source_id;
      bool known = false;
      for (LayoutId l : all_layouts()) known = known || static_cast<int32_t>(l) == d->layout;
      if (ours && d->version == octocap_wire_VERSION && known) {
        const auto layout = static_cast<LayoutId>(d->layout);
        if (!stats_.has_definition || layout != layout_ || d->change_counter != stats_.definition_counter ||
            d->source_id != definition_source_)
          local_definition_ = next_definition_counter();
        layout_ = layout;
        definition_source_ = d->source_id;
        stats_.definition_counter = d->change_counter;
        stats_.has_definition = true;
      } else if (ours) {
        ++stats_.rejected;
        log(LogLevel::warning, "stream: skeleton definition rejected (version " + std::to_string(d->version) +
                                   ", layout " + std::to_string(d->layout) + ")");
      }
    }
    dds_return_loan(impl_->def_reader, samples, n);
  }
}

void DdsSubscriber::guess_layout(uint32_t keypoint_count) {
  // The definition arrives reliably but may trail the first poses; until then, guess by count.
  if (stats_.has_definition || keypoint_count == octocap::internal::layout(layout_).keypoints.size()) return;
  try {
    const LayoutId guess = layout_for_count(keypoint_count);
    if (guess != layout_ || local_definition_ == 0) local_definition_ = next_definition_counter();
    layout_ = guess;
  } catch (const Error&) {
  }
}

bool DdsSubscriber::accept(bool read, FrameResult& next, uint32_t source_id, const std::string& why) {
  if (!read) {
    ++stats_.rejected;
    log(LogLevel::warning, "stream: pose sample rejected: " + why);
    return false;
  }
  const int64_t f = next.info.frame_index;
  stats_.last_gap = 0;
  if (last_frame_ >= 0 && f <= last_frame_) {
    ++stats_.restarts;
    log(LogLevel::info, "stream: frame numbers restarted at " + std::to_string(f) + " after " +
                            std::to_string(last_frame_) + " (publisher restarted)");
  } else if (last_frame_ >= 0 && f > last_frame_ + 1) {
    stats_.last_gap = static_cast<uint64_t>(f - last_frame_ - 1);
    stats_.frames_lost += stats_.last_gap;
  }
  last_frame_ = f;
  stats_.source_id = source_id;
  if (local_definition_ == 0) local_definition_ = next_definition_counter();
  next.source_id = source_id;
  next.definition_counter = local_definition_;
  next.layout = layout_;
  ++stats_.frames_received;
  frame_ = std::move(next);
  return true;
}

namespace {

// Takes samples of `reader` until `handle` accepts one; false when none is left.
template <class Sample, class Handle>
bool take_accepted(dds_entity_t reader, Handle&& handle) {
  void* samples[1] = {nullptr};
  dds_sample_info_t info[1];
  for (;;) {
    const dds_return_t n = dds_take(reader, samples, info, 1, 1);
    if (n <= 0) return false;
    const bool accepted = info[0].valid_data && handle(*static_cast<const Sample*>(samples[0]));
    dds_return_loan(reader, samples, n);
    if (accepted) return true;
  }
}

}  // namespace

bool DdsSubscriber::take_one_pose() {
  auto ours = [&](uint32_t source) { return config_.source_id == 0 || source == config_.source_id; };
  // A source writes one of the two topics: Pose with one person, People with several.
  auto pose = [&](const octocap_wire_Pose& s) {
    if (!ours(s.source_id)) return false;
    guess_layout(s.keypoints._length);
    FrameResult next = frame_;
    std::string why;
    return accept(read_pose(s, layout_, next, why), next, s.source_id, why);
  };
  auto people = [&](const octocap_wire_PeopleFrame& s) {
    if (!ours(s.source_id)) return false;
    if (s.people._length > 0) guess_layout(s.people._buffer[0].keypoints._length);
    FrameResult next = frame_;
    std::string why;
    return accept(read_people(s, layout_, next, why), next, s.source_id, why);
  };
  return take_accepted<octocap_wire_PeopleFrame>(impl_->people_reader, people) ||
         take_accepted<octocap_wire_Pose>(impl_->pose_reader, pose);
}

bool DdsSubscriber::take_next(int timeout_ms) {
  take_definitions();
  if (take_one_pose()) return true;
  if (timeout_ms <= 0) return false;
  const dds_time_t deadline = dds_time() + DDS_MSECS(timeout_ms);
  for (;;) {
    const dds_time_t now = dds_time();
    if (now >= deadline) return false;
    dds_waitset_wait(impl_->waitset, nullptr, 0, deadline - now);
    take_definitions();
    if (take_one_pose()) return true;
  }
}

}  // namespace octocap::internal
