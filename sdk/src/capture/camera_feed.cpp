#include "capture/camera_feed.h"

#include <algorithm>
#include <chrono>

#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"

namespace octocap {

CameraFeed::CameraFeed(CameraSpec spec, FeedOptions options, std::function<void()> on_frame)
    : spec_(std::move(spec)), options_(options), on_frame_(std::move(on_frame)) {}

CameraFeed::~CameraFeed() { stop(); }

void CameraFeed::start() {
  if (thread_.joinable()) throw Error(Errc::invalid_argument, "camera '" + spec_.text + "' is already running");
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    status_ = FeedStatus{};
    status_.state = FeedState::connecting;
  }
  source_ = make_frame_source(spec_, options_.source);
  source_->open();  // throws, naming the camera
  nominal_fps_ = source_->nominal_fps();
  stop_ = false;
  thread_ = std::thread([this] { run(); });
}

void CameraFeed::stop() {
  stop_ = true;
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  const std::lock_guard<std::mutex> lock(mutex_);
  if (status_.state != FeedState::ended && status_.state != FeedState::failed) status_.state = FeedState::stopped;
}

Candidate CameraFeed::candidate(uint64_t after) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  Candidate c;
  const CapturedFrame& newest = slots_[0].frame;
  const CapturedFrame& previous = slots_[1].frame;
  c.last_us = newest.sequence ? newest.grab_us : 0;
  if (newest.sequence > after && !slots_[0].used) c.newest = {newest.sequence, newest.grab_us};
  if (previous.sequence > after && !slots_[1].used) c.previous = {previous.sequence, previous.grab_us};
  if (!c.newest.sequence && c.previous.sequence) std::swap(c.newest, c.previous);
  return c;
}

bool CameraFeed::take(uint64_t sequence, CapturedFrame& out) {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (Slot& s : slots_)
    if (s.frame.sequence == sequence && sequence != 0) {
      out = s.frame;  // cv::Mat shares the pixels: the feed writes each picture into a fresh buffer
      if (!s.used) ++status_.used;
      s.used = true;
      return true;
    }
  return false;
}

bool CameraFeed::done() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return status_.state == FeedState::ended || status_.state == FeedState::failed;
}

FeedStatus CameraFeed::status() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  FeedStatus s = status_;
  s.nominal_fps = nominal_fps_.load();
  return s;
}

bool CameraFeed::reopen() {
  int wait_ms = options_.reconnect_min_ms;
  while (!stop_) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, std::chrono::milliseconds(wait_ms), [&] { return stop_.load(); });
    }
    if (stop_) return false;
    try {
      source_->open();
      const std::lock_guard<std::mutex> lock(mutex_);
      ++status_.reconnects;
      status_.state = FeedState::streaming;
      log(LogLevel::info, "camera '" + spec_.text + "': reconnected");
      return true;
    } catch (const Error& e) {
      const std::lock_guard<std::mutex> lock(mutex_);
      status_.last_error = e.what();
    }
    wait_ms = std::min(2 * wait_ms, options_.reconnect_max_ms);
  }
  return false;
}

void CameraFeed::run() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    status_.state = FeedState::streaming;
  }
  const bool pace = options_.pace_files && !spec_.live();
  int64_t start_us = 0;
  bool started = false;
  int64_t last_grab_us = 0;
  while (!stop_) {
    cv::Mat image;  // a fresh buffer each time: a consumer may still hold the previous picture
    int64_t stream_us = 0;
    bool ok = false;
    try {
      ok = source_->read(image, stream_us);
    } catch (const Error& e) {
      const std::lock_guard<std::mutex> lock(mutex_);
      status_.last_error = e.what();
    }
    if (!ok) {
      if (!spec_.live()) {
        const std::lock_guard<std::mutex> lock(mutex_);
        status_.state = FeedState::ended;
        break;
      }
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        status_.state = FeedState::reconnecting;
        if (status_.last_error.empty()) status_.last_error = "the stream broke";
      }
      log(LogLevel::warning, "camera '" + spec_.text + "': stream broke, reconnecting");
      if (!reopen()) break;
      continue;
    }
    if (pace) {
      // A file is delivered as its camera did: frame i at its own timestamp after the start.
      if (!started) start_us = monotonic_us() - stream_us, started = true;
      const int64_t due = start_us + stream_us;
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, std::chrono::microseconds(std::max<int64_t>(0, due - monotonic_us())),
                     [&] { return stop_.load(); });
      if (stop_) break;
    }
    const int64_t now = monotonic_us();
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!slots_[1].used) ++status_.dropped;  // pushed out unused
      slots_[1] = std::move(slots_[0]);
      slots_[0].frame = CapturedFrame{image, now, stream_us, ++sequence_};
      slots_[0].used = false;
      ++status_.grabbed;
      if (last_grab_us > 0 && now > last_grab_us) {
        // Smoothed on the interval, not on its inverse: a burst of catch-up reads must not read as a faster camera.
        const double dt = static_cast<double>(now - last_grab_us);
        mean_interval_us_ = mean_interval_us_ > 0 ? 0.9 * mean_interval_us_ + 0.1 * dt : dt;
        status_.fps = 1e6 / mean_interval_us_;
      }
      last_grab_us = now;
    }
    if (on_frame_) on_frame_();
  }
}

}  // namespace octocap
