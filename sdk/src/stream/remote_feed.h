// Remote cameras (dds://NODE/CAMERA): the 2D keypoints a capture node detected, received over Cyclone DDS and put in
// a feed's mailbox exactly as a local camera's pictures are, so that frame sets are assembled from both alike. A
// camera whose node falls silent is "reconnecting" until keypoints come again (a reconnect, counted); a node that
// restarted (its frame numbers start again) counts as one too. Two nodes publishing under one name (two DDS writers
// for one dds://NODE/CAMERA) are not merged: the one heard first is kept while it speaks, the other ignored and named
// in a warning and the camera's last error.
#pragma once
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "capture/feed.h"
#include "stream/keypoint_wire.h"

namespace octocap::internal {

class RemoteFeed;

// One reader for every remote camera of an engine: its thread takes samples, hands each to the feed it names, and
// tells feeds the time so that silent ones notice.
class KeypointReceiver {
 public:
  // `security`: a keystore identity folder ("" unsecured).
  KeypointReceiver(uint32_t domain_id, const std::string& topic, const std::string& security = "");
  ~KeypointReceiver();
  KeypointReceiver(const KeypointReceiver&) = delete;
  KeypointReceiver& operator=(const KeypointReceiver&) = delete;

  void attach(RemoteFeed* feed);
  // After it returns, the receiver never calls the feed again.
  void detach(RemoteFeed* feed);
  uint64_t rejected() const { return rejected_; }

 private:
  void run();
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::mutex mutex_;  // feeds_
  std::vector<RemoteFeed*> feeds_;
  std::atomic<uint64_t> rejected_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

class RemoteFeed : public Feed {
 public:
  // `spec` is a SourceKind::remote spec (node, camera).
  RemoteFeed(CameraSpec spec, FeedOptions options, std::shared_ptr<KeypointReceiver> receiver,
             std::function<void()> on_frame);
  ~RemoteFeed() override;

  // Waits up to the open timeout for the camera's first keypoints: Error(io) naming it when none come.
  void start() override;
  void stop() override;

  // From the receiver's thread.
  bool names(const RemoteView& view) const { return view.node == spec_.node && view.camera == spec_.camera; }
  // `writer`: the DDS writer the sample came from (its publication handle).
  void receive(const RemoteView& view, int64_t arrival_wall_us, uint64_t writer);
  void check_silence(int64_t now_us);

 private:
  FeedOptions options_;
  std::shared_ptr<KeypointReceiver> receiver_;
  std::condition_variable first_;  // with Feed::mutex_
  uint64_t last_frame_number_ = 0;
  int64_t last_arrival_us_ = 0;    // monotonic
  uint64_t writer_ = 0;            // the writer whose keypoints are used (0: none yet)
  uint64_t intruder_ = 0;          // the last other writer heard under the same name (warned about once each)
  std::vector<double> delays_ms_;  // ring of the last ones, for the clock offset
  size_t delay_next_ = 0;
};

}  // namespace octocap::internal
