#include "capture/camera_feed.h"

#include <algorithm>
#include <exception>
#include <chrono>

#include "capture/stream_clock.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"

namespace octocap::internal {

CameraFeed::CameraFeed(CameraSpec spec, FeedOptions options, std::function<void()> on_frame)
    : Feed(std::move(spec), std::move(on_frame)), options_(options) {}

CameraFeed::~CameraFeed() { stop(); }

void CameraFeed::start() {
  if (thread_.joinable()) throw Error(Errc::invalid_argument, "camera '" + spec_.text + "' is already running");
  reset_status(FeedState::connecting);
  source_ = make_frame_source(spec_, options_.source);
  source_skipped_ = 0;
  source_->open();  // throws, naming the camera
  nominal_fps_ = source_->nominal_fps();
  stop_ = false;
  thread_ = std::thread([this] { run(); });
}

void CameraFeed::request_stop() {
  stop_ = true;
  if (source_) source_->interrupt();
  {
    const std::lock_guard<std::mutex> lock(mutex_);  // a waiter between its check and its sleep still wakes
  }
  wake_.notify_all();
}

void CameraFeed::stop() {
  request_stop();
  if (thread_.joinable()) thread_.join();
  const std::lock_guard<std::mutex> lock(mutex_);
  if (status_.state != FeedState::ended && status_.state != FeedState::failed) status_.state = FeedState::stopped;
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
    } catch (const std::exception& e) {  // octocap's, OpenCV's, the allocator's: no thread ends the process
      if (stop_) return false;  // interrupted by the stop: not the camera's fault
      set_error(e.what());
    }
    wait_ms = std::min(2 * wait_ms, options_.reconnect_max_ms);
  }
  return false;
}

void CameraFeed::count_source_losses() {
  const uint64_t skipped = source_->skipped(), bad = source_->bad_pictures();
  const std::lock_guard<std::mutex> lock(mutex_);
  status_.dropped += skipped - source_skipped_;  // never delivered, so never used: dropped as the mailbox drops
  source_skipped_ = skipped;
  status_.bad_pictures = bad;
}

void CameraFeed::run() {
  set_state(FeedState::streaming);
  const bool pace = options_.pace_files && !spec_.live();
  int64_t start_us = 0;
  bool started = false;
  int64_t first_arrival_us = -1;  // sources without timestamps of their own
  StreamClock clock;  // live sources: capture times from the stream's own timestamps, once they prove steady
  while (!stop_) {
    cv::Mat& image = pictures_.next();  // never a buffer a consumer still holds: theirs stays as it was
    int64_t stream_us = 0;
    bool ok = false;
    try {
      ok = source_->read(image, stream_us);
    } catch (const std::exception& e) {  // octocap's, OpenCV's, the allocator's: no thread ends the process
      if (!stop_) set_error(e.what());
    }
    count_source_losses();
    if (stop_) break;
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
      clock.reset();
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
    CapturedFrame frame;
    frame.width = image.cols;
    frame.height = image.rows;
    frame.image = image;  // shared with the pool, which will not write it again while the frame is held
    if (!source_->own_timestamps()) {
      // The host's clock when the picture arrived, before its decode: the best capture time such a camera allows.
      if (first_arrival_us < 0) first_arrival_us = stream_us;
      frame.grab_us = stream_us;
      frame.stream_us = stream_us - first_arrival_us;
    } else {
      frame.grab_us = spec_.live() ? clock.capture_us(monotonic_us(), stream_us) : monotonic_us();
      frame.stream_clock = spec_.live() && clock.trusted();
      frame.stream_us = stream_us;
    }
    deliver(std::move(frame));
  }
}

}  // namespace octocap::internal
