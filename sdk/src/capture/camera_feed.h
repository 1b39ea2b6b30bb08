// One camera on its own thread: opened, read as fast as it delivers (files and folders at their own rate), every
// picture stamped at grab on the monotonic clock. Only the newest picture is kept (a mailbox of one): a consumer
// that is slower drops the ones in between, counted, so latency stays bounded. A live camera that breaks is
// reopened with back-off while the others go on.
#pragma once
#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <opencv2/core.hpp>

#include "capture/camera_spec.h"
#include "capture/feed_status.h"
#include "capture/frame_source.h"

namespace octocap {

struct CapturedFrame {
  cv::Mat image;           // BGR
  int64_t grab_us = 0;     // host monotonic clock, at grab
  int64_t stream_us = 0;   // the stream's own timestamp (µs from its first frame)
  uint64_t sequence = 0;   // 1, 2, ... per feed
};

class CameraFeed {
 public:
  // `on_frame` is called from the feed's thread after each new picture (to wake a consumer); it must not block.
  CameraFeed(CameraSpec spec, FeedOptions options, std::function<void()> on_frame);
  ~CameraFeed();
  CameraFeed(const CameraFeed&) = delete;
  CameraFeed& operator=(const CameraFeed&) = delete;

  // Opens the source on the calling thread (Error(io) naming the camera when it cannot), then starts reading.
  void start();
  void stop();
  // The newest picture if it is newer than `after` (a sequence number); it counts as used.
  bool take_newer(uint64_t after, CapturedFrame& out);
  // The newest picture's grab time and sequence without taking it (false when none).
  bool peek(int64_t& grab_us, uint64_t& sequence) const;
  FeedStatus status() const;
  double nominal_fps() const { return nominal_fps_.load(); }
  const CameraSpec& spec() const { return spec_; }

 private:
  void run();
  bool reopen();

  CameraSpec spec_;
  FeedOptions options_;
  std::function<void()> on_frame_;
  std::unique_ptr<FrameSource> source_;
  std::atomic<double> nominal_fps_{0};
  std::thread thread_;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::condition_variable wake_;  // interrupts back-off and pacing sleeps on stop
  CapturedFrame latest_;
  bool has_latest_ = false;
  bool latest_taken_ = true;
  uint64_t sequence_ = 0;
  FeedStatus status_;
};

}  // namespace octocap
