#include "stream/dds_subscriber.h"

#include "core/error.h"
#include "core/log.h"
#include "stream/dds_entities.h"
#include "stream/wire_convert.h"

namespace octocap {

struct DdsSubscriber::Impl {
  DdsParticipant participant;
  dds_entity_t def_reader = 0, pose_reader = 0, waitset = 0, pose_ready = 0;
  explicit Impl(uint32_t domain) : participant(domain) {}
};

DdsSubscriber::DdsSubscriber(const StreamConfig& config)
    : impl_(std::make_unique<Impl>(config.domain_id)), config_(config) {
  const dds_entity_t p = impl_->participant.get();
  const dds_entity_t def_topic = create_topic(p, &octocap_wire_SkeletonDefinition_desc, config.topic + "_definition");
  const dds_entity_t pose_topic = create_topic(p, &octocap_wire_Pose_desc, config.topic + "_pose");
  dds_qos_t* dq = definition_qos();
  impl_->def_reader = dds_create_reader(p, def_topic, dq, nullptr);
  dds_delete_qos(dq);
  check_dds(impl_->def_reader, "creating the definition reader");
  dds_qos_t* pq = pose_qos(config);
  impl_->pose_reader = dds_create_reader(p, pose_topic, pq, nullptr);
  dds_delete_qos(pq);
  check_dds(impl_->pose_reader, "creating the pose reader");
  impl_->waitset = check_dds(dds_create_waitset(p), "creating a waitset");
  impl_->pose_ready = check_dds(dds_create_readcondition(impl_->pose_reader, DDS_ANY_STATE), "creating a read condition");
  check_dds(dds_waitset_attach(impl_->waitset, impl_->pose_ready, 0), "attaching the read condition");
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

bool DdsSubscriber::take_one_pose() {
  void* samples[1] = {nullptr};
  dds_sample_info_t info[1];
  for (;;) {
    const dds_return_t n = dds_take(impl_->pose_reader, samples, info, 1, 1);
    if (n <= 0) return false;
    bool accepted = false;
    if (info[0].valid_data) {
      const auto* pose = static_cast<const octocap_wire_Pose*>(samples[0]);
      if (config_.source_id == 0 || pose->source_id == config_.source_id) {
        std::string why;
        if (!stats_.has_definition && pose->keypoints._length != octocap::layout(layout_).keypoints.size()) {
          // The definition arrives reliably but may trail the first poses; until then, guess by count.
          try {
            const LayoutId guess = layout_for_count(pose->keypoints._length);
            if (guess != layout_ || local_definition_ == 0) local_definition_ = next_definition_counter();
            layout_ = guess;
          } catch (const Error&) {
          }
        }
        FrameResult next = frame_;
        if (read_pose(*pose, layout_, next, why)) {
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
          stats_.source_id = pose->source_id;
          if (local_definition_ == 0) local_definition_ = next_definition_counter();
          next.source_id = pose->source_id;
          next.definition_counter = local_definition_;
          next.layout = layout_;
          ++stats_.frames_received;
          frame_ = std::move(next);
          accepted = true;
        } else {
          ++stats_.rejected;
          log(LogLevel::warning, "stream: pose sample rejected: " + why);
        }
      }
    }
    dds_return_loan(impl_->pose_reader, samples, n);
    if (accepted) return true;
  }
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

}  // namespace octocap
