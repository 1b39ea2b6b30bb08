// A capture node: the cameras of one machine, each detected on its own thread (its newest picture, always: a slow
// detector drops pictures, counted, never queues them) and its 2D keypoints published over DDS for a hub (octocap
// live --camera dds://NODE/CAMERA) that solves them with its other cameras. For rigs with more cameras than one
// machine can detect.
#pragma once
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "capture/feed_status.h"
#include "detect/detector.h"

namespace octocap::internal {

class CameraFeed;
class KeypointPublisher;

struct NodeConfig {
  std::string name = "node1";  // the NODE of dds://NODE/CAMERA
  uint32_t domain_id = 0;
  std::string topic = "octocap";  // keypoints go to "<topic>_keypoints2d"
  std::string security;           // a keystore identity folder: publish over DDS Security ("" off)
  FeedOptions feeds;
  DetectorConfig detector;
  // Detections per second and camera, at wall-clock ticks every node shares (k / rate since 1970); 0: the fastest of
  // 60, 30, 20, 15, 12, 10, 6, 5 ... that the detector keeps up with.
  double detect_rate_hz = 0;
};

struct NodeStats {
  bool running = false;
  bool finished = false;      // every camera ended (files played out)
  uint64_t published = 0;     // views published, all cameras
  uint64_t with_person = 0;   // of those, with at least one person
  double detect_ms = 0;       // mean per view
  double processing_ms = 0;   // grab -> published, mean
  uint32_t readers = 0;       // hubs matched now
};

class KeypointNode {
 public:
  // `names`: the CAMERA of each (empty: cam01, cam02, ...). Parses the specs (errors name them); opens nothing.
  KeypointNode(const NodeConfig& config, const std::vector<std::string>& cameras, std::vector<std::string> names);
  ~KeypointNode();
  KeypointNode(const KeypointNode&) = delete;
  KeypointNode& operator=(const KeypointNode&) = delete;

  void set_detector(const DetectorConfig& config);  // before start(); loaded at start
  // Loads the detectors, opens every camera (Error(io) naming one that cannot be opened), starts publishing.
  void start();
  void stop();  // idempotent
  bool running() const { return running_; }
  NodeStats stats() const;
  size_t camera_count() const { return cameras_.size(); }
  FeedStatus camera_status(size_t i) const;
  const std::string& camera_name(size_t i) const;

 private:
  struct Camera;
  void run(Camera& camera);

  NodeConfig config_;
  std::vector<std::unique_ptr<Camera>> cameras_;
  std::unique_ptr<KeypointPublisher> publisher_;
  std::atomic<bool> running_{false}, stop_{false};
  mutable std::mutex mutex_;  // stats_
  NodeStats stats_;
};

}  // namespace octocap::internal
