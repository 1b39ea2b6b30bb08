// Publishes solved frames without ever blocking the solve: the session hands a copy to a queue, a thread of
// the publisher writes it. A full queue (slow network, reliable readers that stall) drops the oldest frame.
#pragma once
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>

#include "core/frame.h"
#include "core/frame_sink.h"
#include "stream/stream_config.h"

namespace octocap::internal {

class DdsPublisher : public FrameSink {
 public:
  // `definition_counter` goes out with the definition and every pose (the source's next_definition_counter()).
  DdsPublisher(const StreamConfig& config, LayoutId layout, uint32_t definition_counter = 1);
  ~DdsPublisher() override;
  DdsPublisher(const DdsPublisher&) = delete;
  DdsPublisher& operator=(const DdsPublisher&) = delete;

  void publish(const FrameResult& frame) override;
  // Waits until everything queued has been written (for tests and for a clean end of a recording).
  void flush() override;
  uint32_t receivers() const override { return matched_readers(); }
  uint64_t dropped() const;
  // Readers of the pose topic currently matched (so a recorder can be waited for before a take starts).
  uint32_t matched_readers() const;

 private:
  void run();
  struct Impl;
  std::unique_ptr<Impl> impl_;
  StreamConfig config_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<FrameResult> queue_;
  size_t capacity_;
  bool writing_ = false, stop_ = false;
  uint64_t dropped_ = 0;
  std::thread thread_;
};

}  // namespace octocap::internal
