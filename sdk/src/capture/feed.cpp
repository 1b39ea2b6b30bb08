#include "capture/feed.h"

#include <algorithm>
#include <utility>

#include "core/clock.h"
#include "core/error.h"

namespace octocap::internal {

void FeedOptions::validate() const {
  if (!(source.picture_rate_hz >= 0.01 && source.picture_rate_hz <= 1000))  // NaN fails too
    throw Error(Errc::invalid_argument, "picture_rate_hz must be 0.01 to 1000");
  if (source.open_timeout_ms < 1 || source.open_timeout_ms > 600000 || source.read_timeout_ms < 1 ||
      source.read_timeout_ms > 600000)
    throw Error(Errc::invalid_argument, "open_timeout_ms and read_timeout_ms must be 1 ms to 10 minutes");
  if (reconnect_min_ms < 1 || reconnect_max_ms < std::max(100, reconnect_min_ms) || reconnect_max_ms > 600000)
    throw Error(Errc::invalid_argument, "reconnect_max_ms must be 100 ms to 10 minutes");
}

Candidate Feed::candidate(uint64_t after) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  Candidate c;
  const CapturedFrame& newest = slots_[0].frame;
  const CapturedFrame& previous = slots_[1].frame;
  c.last_us = newest.sequence ? newest.grab_us : 0;
  c.last_arrival_us = newest.sequence ? newest.arrival_us : 0;
  if (newest.sequence > after && !slots_[0].used) c.newest = {newest.sequence, newest.grab_us, newest.arrival_us};
  if (previous.sequence > after && !slots_[1].used)
    c.previous = {previous.sequence, previous.grab_us, previous.arrival_us};
  if (!c.newest.sequence && c.previous.sequence) std::swap(c.newest, c.previous);
  return c;
}

bool Feed::take(uint64_t sequence, CapturedFrame& out) {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (Slot& s : slots_)
    if (s.frame.sequence == sequence && sequence != 0) {
      out = s.frame;  // cv::Mat shares the pixels: every picture is written into a fresh buffer
      if (!s.used) ++status_.used;
      s.used = true;
      return true;
    }
  return false;
}

bool Feed::done() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return status_.state == FeedState::ended || status_.state == FeedState::failed;
}

FeedStatus Feed::status() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  FeedStatus s = status_;
  s.nominal_fps = nominal_fps_.load();
  return s;
}

double Feed::fps() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return status_.fps;
}

void Feed::reset_status(FeedState state) {
  const std::lock_guard<std::mutex> lock(mutex_);
  status_ = FeedStatus{};
  status_.state = state;
  slots_[0] = slots_[1] = Slot{};
  last_delivery_us_ = 0;
  mean_interval_us_ = 0;
}

void Feed::set_state(FeedState state) {
  const std::lock_guard<std::mutex> lock(mutex_);
  status_.state = state;
}

void Feed::set_error(const std::string& message) {
  const std::lock_guard<std::mutex> lock(mutex_);
  status_.last_error = message;
}

void Feed::deliver(CapturedFrame frame) {
  const int64_t now = monotonic_us();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!slots_[1].used) ++status_.dropped;  // pushed out unused
    slots_[1] = std::move(slots_[0]);
    frame.sequence = ++sequence_;
    frame.arrival_us = now;
    slots_[0].frame = std::move(frame);
    slots_[0].used = false;
    ++status_.grabbed;
    status_.stream_clock = slots_[0].frame.stream_clock;
    if (last_delivery_us_ > 0 && now > last_delivery_us_) {
      // Smoothed on the interval, not on its inverse: a burst of catch-up reads must not read as a faster camera.
      const double dt = static_cast<double>(now - last_delivery_us_);
      mean_interval_us_ = mean_interval_us_ > 0 ? 0.9 * mean_interval_us_ + 0.1 * dt : dt;
      status_.fps = 1e6 / mean_interval_us_;
    }
    last_delivery_us_ = now;
  }
  if (on_frame_) on_frame_();
}

}  // namespace octocap::internal
