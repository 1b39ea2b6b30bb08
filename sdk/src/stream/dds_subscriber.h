// Receives skeletons published by another process (or machine), one person or several, and keeps the last one as a
// FrameResult, which the C ABI queries exactly like a local session's. Reports lost frames and publisher restarts.
#pragma once
#include <memory>
#include <string>

#include "core/frame.h"
#include "stream/stream_config.h"

namespace octocap::internal {

struct StreamStats {
  uint64_t frames_received = 0;
  uint64_t frames_lost = 0;     // gaps in frame numbers, summed
  uint64_t last_gap = 0;        // frames missing right before the current one
  uint64_t restarts = 0;        // times the frame numbers went backwards (a publisher restarted)
  uint64_t rejected = 0;        // samples refused (other version, wrong sizes, NaN)
  uint32_t source_id = 0;
  uint32_t definition_counter = 0;
  bool has_definition = false;
};

class DdsSubscriber {
 public:
  explicit DdsSubscriber(const StreamConfig& config);
  ~DdsSubscriber();
  DdsSubscriber(const DdsSubscriber&) = delete;
  DdsSubscriber& operator=(const DdsSubscriber&) = delete;

  // Takes the next pose in arrival order, waiting up to timeout_ms. False on timeout.
  bool take_next(int timeout_ms);
  const FrameResult& frame() const { return frame_; }
  const StreamStats& stats() const { return stats_; }
  LayoutId layout() const { return layout_; }

 private:
  void take_definitions();
  bool take_one_pose();
  void guess_layout(uint32_t keypoint_count);
  // Counts a read sample (or its rejection) and makes it the current frame.
  bool accept(bool read, FrameResult& next, uint32_t source_id, const std::string& why);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  StreamConfig config_;
  FrameResult frame_;
  StreamStats stats_;
  LayoutId layout_ = LayoutId::body25;
  int64_t last_frame_ = -1;
  uint32_t local_definition_ = 0;   // this process's counter for the definition in use (0: none yet)
  uint32_t definition_source_ = 0;  // source of the definition in use
};

}  // namespace octocap::internal
