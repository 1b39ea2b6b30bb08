// One camera on its own thread: opened, read as fast as it delivers (files and folders at their own rate), every
// picture stamped at grab on the monotonic clock and put in the feed's mailbox (capture/feed.h). A live camera that
// breaks is reopened with back-off while the others go on.
#pragma once
#include <condition_variable>
#include <memory>
#include <thread>

#include "capture/feed.h"
#include "capture/frame_source.h"
#include "capture/picture_pool.h"

namespace octocap::internal {

class CameraFeed : public Feed {
 public:
  CameraFeed(CameraSpec spec, FeedOptions options, std::function<void()> on_frame);
  ~CameraFeed() override;

  void start() override;
  void request_stop() override;
  void stop() override;

 private:
  void run();
  bool reopen();
  void count_source_losses();

  FeedOptions options_;
  std::unique_ptr<FrameSource> source_;
  uint64_t source_skipped_ = 0;  // of source_->skipped(), already counted as dropped
  PicturePool pictures_;  // the decoder's buffers, used by the camera's thread only
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::condition_variable wake_;  // interrupts back-off and pacing sleeps on stop (with Feed::mutex_)
};

}  // namespace octocap::internal
