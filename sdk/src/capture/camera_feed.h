// One camera on its own thread: opened, read as fast as it delivers (files and folders at their own rate), every
// picture stamped at grab on the monotonic clock. Only the newest two pictures are kept (two, so that software sync
// can pick the one nearer a set's time): a consumer that is slower drops the ones in between, counted, so latency
// stays bounded. A live camera that breaks is
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
#include "capture/frame_set.h"
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
  // The two newest pictures newer than `after` (a sequence number), for frame-set assembly.
  Candidate candidate(uint64_t after) const;
  // Picture `sequence` if it is still kept; it counts as used.
  bool take(uint64_t sequence, CapturedFrame& out);
  FeedStatus status() const;
  // Ended (a file played out) or failed: nothing more will come.
  bool done() const;
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
  struct Slot {
    CapturedFrame frame;
    bool used = true;  // an empty slot counts as used: nothing to drop
  };
  Slot slots_[2];  // [0] the newest, [1] the one before
  uint64_t sequence_ = 0;
  double mean_interval_us_ = 0;
  FeedStatus status_;
};

}  // namespace octocap
