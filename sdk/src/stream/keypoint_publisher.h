// A capture node's side of remote cameras: each camera's 2D keypoints written to "<topic>_keypoints2d". Safe to call
// from several camera threads at once; a write never waits for a reader (best effort).
#pragma once
#include <memory>
#include <mutex>
#include <string>

#include "stream/keypoint_wire.h"

namespace octocap::internal {

class KeypointPublisher {
 public:
  // `security`: a keystore identity folder ("" unsecured).
  KeypointPublisher(uint32_t domain_id, const std::string& topic, const std::string& security = "");
  ~KeypointPublisher();
  KeypointPublisher(const KeypointPublisher&) = delete;
  KeypointPublisher& operator=(const KeypointPublisher&) = delete;

  // Throws Error(invalid_argument) for a view the wire cannot hold (see fill_view_keypoints).
  void publish(const RemoteView& view);
  uint32_t matched_readers() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::mutex mutex_;  // the write buffers
};

}  // namespace octocap::internal
