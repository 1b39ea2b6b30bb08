#include "stream/remote_feed.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"
#include "stream/dds_entities.h"
#include "stream/topics.h"

namespace octocap::internal {
namespace {

constexpr size_t kDelayWindow = 256;
constexpr int kMaxSamplesPerTake = 16;
// A new writer for a camera takes over once the one in use has been silent this long (a node killed and restarted).
constexpr int64_t kTakeOverSilenceUs = 1000000;

}  // namespace

struct KeypointReceiver::Impl {
  DdsParticipant participant;
  dds_entity_t reader = 0, waitset = 0;
  Impl(uint32_t domain, const std::string& security) : participant(domain, security) {}
};

KeypointReceiver::KeypointReceiver(uint32_t domain_id, const std::string& topic, const std::string& security)
    : impl_(std::make_unique<Impl>(domain_id, security)) {
  DdsParticipant& p = impl_->participant;
  const dds_entity_t t = p.topic(&octocap_wire_ViewKeypoints_desc, topic_name(topic, kKeypointsTopicSuffix));
  impl_->reader = p.reader(t, keypoints_qos(), "creating the keypoints reader");
  impl_->waitset = check_dds(dds_create_waitset(p.get()), "creating a waitset");
  const dds_entity_t ready = check_dds(dds_create_readcondition(impl_->reader, DDS_ANY_STATE), "creating a read condition");
  check_dds(dds_waitset_attach(impl_->waitset, ready, 0), "attaching the read condition");
  thread_ = std::thread([this] { run(); });
}

KeypointReceiver::~KeypointReceiver() {
  stop_ = true;
  dds_waitset_set_trigger(impl_->waitset, true);
  thread_.join();
}

void KeypointReceiver::attach(RemoteFeed* feed) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (std::find(feeds_.begin(), feeds_.end(), feed) == feeds_.end()) feeds_.push_back(feed);
}

void KeypointReceiver::detach(RemoteFeed* feed) {
  const std::lock_guard<std::mutex> lock(mutex_);
  feeds_.erase(std::remove(feeds_.begin(), feeds_.end(), feed), feeds_.end());
}

void KeypointReceiver::run() {
  void* samples[kMaxSamplesPerTake] = {nullptr};
  dds_sample_info_t infos[kMaxSamplesPerTake];
  RemoteView view;
  std::string why;
  while (!stop_) {
    // Woken by keypoints, by the destructor, or every 50 ms to notice silent cameras.
    dds_waitset_wait(impl_->waitset, nullptr, 0, DDS_MSECS(50));
    if (stop_) break;
    const dds_return_t n = dds_take(impl_->reader, samples, infos, kMaxSamplesPerTake, kMaxSamplesPerTake);
    const int64_t arrival = wall_clock_us();
    const std::lock_guard<std::mutex> lock(mutex_);
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      if (!read_view_keypoints(*static_cast<const octocap_wire_ViewKeypoints*>(samples[i]), view, why)) {
        if (rejected_++ == 0) log(LogLevel::warning, "remote keypoints rejected: " + why);
        continue;
      }
      for (RemoteFeed* f : feeds_)
        if (f->names(view)) f->receive(view, arrival, infos[i].publication_handle);
    }
    if (n > 0) dds_return_loan(impl_->reader, samples, n);
    const int64_t now = monotonic_us();
    for (RemoteFeed* f : feeds_) f->check_silence(now);
  }
}

RemoteFeed::RemoteFeed(CameraSpec spec, FeedOptions options, std::shared_ptr<KeypointReceiver> receiver,
                       std::function<void()> on_frame)
    : Feed(std::move(spec), std::move(on_frame)), options_(options), receiver_(std::move(receiver)) {}

RemoteFeed::~RemoteFeed() { stop(); }

void RemoteFeed::start() {
  reset_status(FeedState::connecting);
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    last_frame_number_ = 0;
    writer_ = intruder_ = 0;
    delays_ms_.clear();
    delay_next_ = 0;
  }
  receiver_->attach(this);
  std::unique_lock<std::mutex> lock(mutex_);
  if (!first_.wait_for(lock, std::chrono::milliseconds(options_.source.open_timeout_ms),
                       [&] { return status_.state == FeedState::streaming; })) {
    lock.unlock();
    receiver_->detach(this);
    set_state(FeedState::failed);
    throw Error(Errc::io, "camera '" + spec_.text + "': no keypoints from node '" + spec_.node + "' camera '" +
                              spec_.camera + "' within " + std::to_string(options_.source.open_timeout_ms) +
                              " ms (is `octocap detect --live --publish-keypoints` running there, on the same DDS "
                              "domain and topic?)");
  }
}

void RemoteFeed::stop() {
  receiver_->detach(this);
  const std::lock_guard<std::mutex> lock(mutex_);
  if (status_.state != FeedState::failed) status_.state = FeedState::stopped;
}

void RemoteFeed::receive(const RemoteView& view, int64_t arrival_wall_us, uint64_t writer) {
  CapturedFrame frame;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (status_.state == FeedState::stopped || status_.state == FeedState::failed) return;
    // A writer other than the one in use: a restarted node once the old one fell silent (taken over), else a second
    // node under the same name, whose frames interleaved with the first's would look like restarts and doubled rates.
    if (writer_ != 0 && writer != writer_) {
      const bool first_silent = monotonic_us() - last_arrival_us_ > kTakeOverSilenceUs;
      if (!first_silent) {
        if (intruder_ != writer) {
          intruder_ = writer;
          status_.last_error = "two capture nodes publish as '" + spec_.node + "' camera '" + spec_.camera +
                               "': the first one heard is used, the other ignored (give each node its own --node)";
          log(LogLevel::warning, "camera '" + spec_.text + "': " + status_.last_error);
        }
        return;
      }
    }
    writer_ = writer;
    // The least delay seen is transit plus the clocks' difference: the estimate of the node's clock offset.
    const double delay = static_cast<double>(arrival_wall_us - view.capture_time_us) / 1000.0 - view.processing_ms;
    if (delays_ms_.size() < kDelayWindow) delays_ms_.push_back(delay);
    else delays_ms_[delay_next_++ % kDelayWindow] = delay;
    status_.clock_offset_ms = *std::min_element(delays_ms_.begin(), delays_ms_.end());
    const bool restarted = last_frame_number_ != 0 && view.frame_number <= last_frame_number_;
    if (status_.state == FeedState::reconnecting || (restarted && status_.state == FeedState::streaming)) {
      ++status_.reconnects;
      log(LogLevel::info, "camera '" + spec_.text + "': keypoints again" + (restarted ? " (the node restarted)" : ""));
    }
    status_.state = FeedState::streaming;
    last_frame_number_ = view.frame_number;
    last_arrival_us_ = monotonic_us();
    frame.grab_us = wall_to_monotonic_us(view.capture_time_us + static_cast<int64_t>(status_.clock_offset_ms * 1000));
    nominal_fps_ = view.nominal_fps;
  }
  first_.notify_all();
  frame.people = view.people;
  frame.has_keypoints = true;
  frame.width = view.width;
  frame.height = view.height;
  frame.stream_us = view.stream_time_us;
  deliver(std::move(frame));
}

void RemoteFeed::check_silence(int64_t now_us) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (status_.state != FeedState::streaming || now_us - last_arrival_us_ <= options_.source.read_timeout_ms * 1000LL)
    return;
  status_.state = FeedState::reconnecting;
  status_.last_error = "no keypoints for " + std::to_string(options_.source.read_timeout_ms) + " ms";
  log(LogLevel::warning, "camera '" + spec_.text + "': " + status_.last_error + ", waiting for its node");
}

}  // namespace octocap::internal
