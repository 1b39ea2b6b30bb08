// The live engine: N camera feeds (capture/: pixels; stream/: a capture node's keypoints over DDS), frame-set
// assembly (software sync), and one solving thread running the session (detect -> solve -> rig -> the session's
// sinks: DDS, VMC). Every hand-over is a mailbox of one: a
// feed keeps its newest picture, the engine keeps its newest solved frame; under overload the oldest is dropped
// and counted, so latency is bounded by design.
#pragma once
#include <array>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "capture/feed_status.h"
#include "capture/frame_set.h"
#include "core/frame.h"
#include "pipeline/session.h"

namespace octocap::internal {

class Feed;
class RateGovernor;
class KeypointReceiver;
class LiveRecorder;
struct CapturedFrame;

struct LiveConfig {
  SessionConfig session;
  FeedOptions feeds;
  int64_t sync_tolerance_us = 0;  // 0: half a frame period of the slowest camera
  int64_t max_wait_us = 0;        // 0: 1.5 frame periods of the slowest camera (measured, when slower than it says)
  std::vector<int64_t> latency_offsets_us;  // per camera (see FrameSetOptions::offsets_us)
  uint32_t remote_domain_id = 0;            // where remote cameras' keypoints are read (dds://NODE/CAMERA)
  std::string remote_topic = "octocap";     // ... "<topic>_keypoints2d"
  std::string remote_security;              // a keystore identity folder: read them over DDS Security ("" off)
  // The rate governor (rate_governor.h): off, every set gets the detector config's detection (--quality max).
  bool governed = true;
  double target_fps = 0;           // sets a second it holds; 0: the slowest camera's rate
  double latency_budget_ms = 100;  // grab to frame, 99th percentile
  // Throws Error(invalid_argument) for a value out of range (the feeds', target_fps 0..1000, latency_budget_ms
  // 10..10000); the session's config is its own (SessionConfig::validate, with the cameras).
  void validate() const;
};

// Means over the frames solved so far, and the latency distribution of the last ones.
struct LiveStats {
  bool running = false;
  bool finished = false;          // every camera ended (files played out)
  uint64_t frame_sets = 0;        // sets assembled and solved
  uint64_t frames_with_person = 0;
  uint64_t sets_incomplete = 0;   // sets that went out without every camera
  uint64_t frames_not_taken = 0;  // solved frames replaced before anyone took them (the output mailbox)
  double fps = 0;                 // solved frames per second, smoothed
  double capture_ms = 0;          // grab of the set's oldest picture -> the solve starts (waiting for the set)
  double detect_ms = 0;
  double solve_ms = 0;            // 3D + rig
  double publish_ms = 0;          // sinks and the output mailbox
  double latency_p50_ms = 0;      // grab of the oldest picture -> frame available
  double latency_p99_ms = 0;
  uint64_t sets_recorded = 0;     // sets written by the recording (set_recording)
  uint64_t recording_pictures_dropped = 0;  // recorded sets whose pictures were left out (the disk was behind)
  std::string last_error;         // a solve that failed, or the recording's write error (the engine goes on)
  bool failed = false;            // the engine stopped on an error it cannot go on from (last_error says which)
  // The rate governor's choice for the last set: its rung of the quality ladder (0 best) of `quality_rungs` (0: not
  // governed), the model that ran and on how many views (the others followed by optical flow), the rate it holds
  // and how much of a set's budget the sets used (smoothed; above 1 it steps down).
  uint32_t quality_rung = 0, quality_rungs = 0;
  uint32_t views_detected = 0;
  uint32_t views_in_set = 0;  // cameras the last set held (a picture or a node's keypoints)
  std::string model;
  double target_fps = 0;
  double budget_used = 0;
  uint64_t rung_changes = 0;
};

class LiveEngine {
 public:
  // Parses every camera spec (errors name it) and checks the count against the calibration; opens nothing yet.
  LiveEngine(const LiveConfig& config, Calibration calib, const std::vector<std::string>& cameras);
  ~LiveEngine();
  LiveEngine(const LiveEngine&) = delete;
  LiveEngine& operator=(const LiveEngine&) = delete;

  void set_detector(const DetectorConfig& config);  // before start()
  // Per camera, how late it delivers (µs, subtracted from its grab times before matching); before start().
  void set_latency_offsets(const std::vector<int64_t>& offsets_us);
  // Records every frame set into `directory` from the next start() (see live_recorder.h); empty: no recording.
  // Before start().
  void set_recording(const std::string& directory);
  // Opens every camera (Error(io) naming one that cannot be opened; the others are closed again), then runs.
  void start();
  void stop();  // idempotent
  bool running() const { return running_; }

  // The newest solved frame (null before the first).
  std::shared_ptr<const FrameResult> latest() const;
  // The newest frame newer than the last one this call returned, waiting up to timeout_ms; null on timeout.
  std::shared_ptr<const FrameResult> take(int timeout_ms);
  LiveStats stats() const;
  size_t camera_count() const { return feeds_.size(); }
  FeedStatus camera_status(size_t i) const;
  const CameraSpec& camera_spec(size_t i) const;
  const std::string& camera_name(size_t i) const { return calib_.at(i).name; }

 private:
  void run();
  // Why a picture of this set cannot be its camera's (another aspect ratio than its calibration), "" when all can.
  std::string wrong_picture(const std::vector<CapturedFrame>& frames, const std::vector<bool>& present) const;
  void solve_set(const std::vector<CapturedFrame>& frames, const std::vector<bool>& present, int64_t set_time_us);
  void record(const std::vector<CapturedFrame>& frames, const std::vector<bool>& present, int64_t set_time_us);
  void add_recording_stats(LiveStats& s) const;  // the recording's figures into `s`, while there is a recording
  // The sync tolerance and wait now: the configured ones, else from the slowest camera's measured rate (a camera
  // that delivers slower than it says, a host that cannot decode every picture, still makes whole sets).
  void update_sync_window();
  // Before a set: the rung the governor chose, applied to the detector; after it, what the set cost.
  void govern_before_set();
  void govern_after_set(double cost_ms, double wait_ms, int64_t now_us);

  LiveConfig config_;
  Calibration calib_;
  std::unique_ptr<Session> session_;
  std::shared_ptr<KeypointReceiver> receiver_;  // only with remote cameras
  std::vector<std::unique_ptr<Feed>> feeds_;
  std::string record_dir_;
  std::unique_ptr<LiveRecorder> recorder_;  // from start() to stop(), when recording
  FrameSetOptions sync_;
  double slowest_fps_ = 30;                 // the slowest camera's rate (update_sync_window)
  std::unique_ptr<RateGovernor> governor_;  // from start(), when governed and some camera is detected here
  int top_views_ = 0;                       // the detector config's views_per_frame: the ladder's top
  std::thread thread_;
  std::atomic<bool> running_{false}, stop_{false};
  mutable std::mutex mutex_;          // guards what follows
  std::condition_variable new_input_; // a feed has a picture (or stop)
  std::condition_variable new_output_;
  bool input_pending_ = false;
  std::shared_ptr<const FrameResult> latest_;
  uint64_t latest_serial_ = 0, taken_serial_ = 0;
  LiveStats stats_;
  std::vector<double> latencies_ms_;  // ring of the last ones
  size_t latency_next_ = 0;
  int64_t last_solved_us_ = 0;
  double mean_interval_us_ = 0;
};

}  // namespace octocap::internal
