// What the live engine reads a camera through: the newest two pictures (or, from a remote capture node, the 2D
// keypoints detected in them), each stamped on the host's monotonic clock, and the camera's status. The mailbox and
// its accounting live here; a CameraFeed fills it from pixels on its own thread, a remote feed (stream/) from DDS.
// Two slots, so that software sync can pick the one nearer a set's time; a consumer that is slower drops the ones in
// between, counted, so latency stays bounded.
#pragma once
#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/camera_spec.h"
#include "capture/feed_status.h"
#include "capture/frame_set.h"
#include "core/person2d.h"

namespace octocap::internal {

struct CapturedFrame {
  cv::Mat image;                 // BGR; empty when the camera's keypoints were detected elsewhere
  std::vector<Person2D> people;  // keypoints from a capture node (in its picture's pixels); empty for pixels
  bool has_keypoints = false;    // people is the answer (possibly nobody), not the image
  int width = 0, height = 0;     // the picture's size
  int64_t grab_us = 0;           // when it was captured, host monotonic clock (µs)
  int64_t stream_us = 0;         // the stream's own timestamp (µs from its first frame)
  bool stream_clock = false;     // grab_us comes from the stream's timestamps (capture/stream_clock.h), not the host's
  int64_t arrival_us = 0;        // when it reached the mailbox (monotonic; set by Feed::deliver)
  uint64_t sequence = 0;         // 1, 2, ... per feed
};

class Feed {
 public:
  // `on_frame` is called from the feed's thread after each new picture (to wake a consumer); it must not block.
  Feed(CameraSpec spec, std::function<void()> on_frame) : spec_(std::move(spec)), on_frame_(std::move(on_frame)) {}
  virtual ~Feed() = default;
  Feed(const Feed&) = delete;
  Feed& operator=(const Feed&) = delete;

  // Opens the camera on the calling thread (Error(io) naming it when it cannot), then starts receiving.
  virtual void start() = 0;
  // Asks the feed to stop without waiting (so that many feeds stop together); stop() then waits for it.
  virtual void request_stop() {}
  virtual void stop() = 0;
  // The two newest pictures newer than `after` (a sequence number), for frame-set assembly.
  Candidate candidate(uint64_t after) const;
  // Picture `sequence` if it is still kept; it counts as used.
  bool take(uint64_t sequence, CapturedFrame& out);
  FeedStatus status() const;
  double fps() const;
  // Ended (a file played out) or failed: nothing more will come.
  bool done() const;
  double nominal_fps() const { return nominal_fps_.load(); }
  const CameraSpec& spec() const { return spec_; }

 protected:
  // Puts a new picture in the mailbox (its sequence is given here), counts the one pushed out unused, wakes the
  // consumer.
  void deliver(CapturedFrame frame);
  void reset_status(FeedState state);
  void set_state(FeedState state);
  void set_error(const std::string& message);

  CameraSpec spec_;
  std::atomic<double> nominal_fps_{0};
  mutable std::mutex mutex_;  // guards what follows and the subclasses' state
  FeedStatus status_;

 private:
  std::function<void()> on_frame_;
  struct Slot {
    CapturedFrame frame;
    bool used = true;  // an empty slot counts as used: nothing to drop
  };
  Slot slots_[2];  // [0] the newest, [1] the one before
  uint64_t sequence_ = 0;
  int64_t last_delivery_us_ = 0;
  double mean_interval_us_ = 0;
};

}  // namespace octocap::internal
