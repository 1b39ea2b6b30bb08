#include "pipeline/keypoint_node.h"

#include <algorithm>
#include <exception>
#include <cstdlib>
#include <chrono>
#include <cstdio>

#include "capture/camera_feed.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"
#include "stream/keypoint_publisher.h"
#include "stream/stream_config.h"

namespace octocap::internal {
namespace {

// Rates that divide a second into whole ticks, so that nodes choosing different ones still meet at common ticks.
constexpr double kTickRates[] = {60, 30, 20, 15, 12, 10, 6, 5, 4, 3, 2, 1};

// The tick period: the configured rate's, else the fastest listed rate whose period leaves the detector a fifth to
// spare (the measured grab-to-published time, 30 Hz before the first).
int64_t tick_period_us(double rate_hz, double processing_us) {
  if (rate_hz > 0) return static_cast<int64_t>(1e6 / rate_hz);
  if (processing_us <= 0) return static_cast<int64_t>(1e6 / 30);
  for (double r : kTickRates)
    if (1e6 / r >= 1.2 * processing_us) return static_cast<int64_t>(1e6 / r);
  return 1000000;
}

}  // namespace

struct KeypointNode::Camera {
  std::string name;
  std::unique_ptr<CameraFeed> feed;
  std::unique_ptr<Detector> detector;
  std::thread thread;
  std::mutex mutex;
  std::condition_variable wake;
  bool pending = false;
  uint64_t frame_number = 0;
};

KeypointNode::KeypointNode(const NodeConfig& config, const std::vector<std::string>& cameras,
                           std::vector<std::string> names)
    : config_(config) {
  if (cameras.empty()) throw Error(Errc::invalid_argument, "a capture node needs at least one camera");
  config_.feeds.validate();
  check_dds_names(config_.domain_id, config_.topic, "node");
  if (!(config_.detect_rate_hz >= 0 && config_.detect_rate_hz <= 1000))  // NaN fails too
    throw Error(Errc::invalid_argument, "detect_rate_hz must be 0 (automatic) to 1000");
  if (!names.empty() && names.size() != cameras.size())
    throw Error(Errc::invalid_argument, std::to_string(names.size()) + " camera names for " +
                                            std::to_string(cameras.size()) + " cameras");
  if (!valid_remote_name(config_.name))
    throw Error(Errc::invalid_argument, "node name '" + config_.name + "': 1 to 31 bytes, no '/'");
  for (size_t c = 0; c < cameras.size(); ++c) {
    auto cam = std::make_unique<Camera>();
    if (names.empty()) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "cam%02zu", c + 1);
      cam->name = buf;
    } else {
      cam->name = names[c];
    }
    if (!valid_remote_name(cam->name))
      throw Error(Errc::invalid_argument, "camera name '" + cam->name + "': 1 to 31 bytes, no '/'");
    for (const auto& other : cameras_)
      if (other->name == cam->name) throw Error(Errc::invalid_argument, "two cameras named '" + cam->name + "'");
    CameraSpec spec = parse_camera_spec(cameras[c]);
    if (spec.kind == SourceKind::remote)
      throw Error(Errc::invalid_argument, "camera '" + cameras[c] + "': a capture node's cameras are its own");
    Camera* raw = cam.get();
    cam->feed = std::make_unique<CameraFeed>(std::move(spec), config_.feeds, [raw] {
      {
        const std::lock_guard<std::mutex> lock(raw->mutex);
        raw->pending = true;
      }
      raw->wake.notify_one();
    });
    cameras_.push_back(std::move(cam));
  }
}

KeypointNode::~KeypointNode() { stop(); }

const std::string& KeypointNode::camera_name(size_t i) const { return cameras_.at(i)->name; }
FeedStatus KeypointNode::camera_status(size_t i) const { return cameras_.at(i)->feed->status(); }

NodeStats KeypointNode::stats() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  NodeStats s = stats_;
  s.running = running_;
  s.readers = publisher_ ? publisher_->matched_readers() : 0;
  return s;
}

void KeypointNode::set_detector(const DetectorConfig& config) {
  if (running_) throw Error(Errc::invalid_argument, "the capture node is running: set the detector before start");
  config.validate();  // kept for start(): refused now, where the caller set it
  config_.detector = config;
  for (auto& c : cameras_) c->detector.reset();
}

void KeypointNode::start() {
  if (running_) throw Error(Errc::invalid_argument, "the capture node is already running");
  for (auto& c : cameras_)
    if (!c->detector) c->detector = std::make_unique<Detector>(config_.detector);  // fail before opening cameras
  if (!publisher_) publisher_ = std::make_unique<KeypointPublisher>(config_.domain_id, config_.topic, config_.security);
  size_t opened = 0;
  try {
    for (; opened < cameras_.size(); ++opened) cameras_[opened]->feed->start();
  } catch (...) {
    for (size_t c = 0; c < opened; ++c) cameras_[c]->feed->stop();
    throw;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stats_ = NodeStats{};
  }
  stop_ = false;
  running_ = true;
  for (auto& c : cameras_) {
    Camera* raw = c.get();
    c->thread = std::thread([this, raw] { run(*raw); });
  }
}

void KeypointNode::stop() {
  stop_ = true;
  for (auto& c : cameras_) {
    {
      const std::lock_guard<std::mutex> lock(c->mutex);
      c->pending = true;
    }
    c->wake.notify_all();
  }
  for (auto& c : cameras_)
    if (c->thread.joinable()) c->thread.join();
  for (auto& c : cameras_) c->feed->stop();
  running_ = false;
}

void KeypointNode::run(Camera& cam) {
  uint64_t last = 0;
  CapturedFrame frame;
  RemoteView view;
  view.node = config_.name;
  view.camera = cam.name;
  double processing_us = 0;  // grab -> published, smoothed: what the automatic rate follows
  int64_t tick = 0;          // the wall-clock instant this camera detects next
  while (!stop_) {
    {
      std::unique_lock<std::mutex> lock(cam.mutex);
      cam.wake.wait_for(lock, std::chrono::milliseconds(100), [&] { return cam.pending; });
      cam.pending = false;
    }
    if (stop_) break;
    const Candidate c = cam.feed->candidate(last);
    if (c.newest.sequence == 0) {
      if (!cam.feed->done()) continue;
      bool all_done = true;
      for (const auto& other : cameras_) all_done = all_done && other->feed->done();
      const std::lock_guard<std::mutex> lock(mutex_);
      stats_.finished = all_done;
      break;  // played out
    }
    // Every node detects the pictures nearest the same wall-clock ticks, so that a hub's frame sets find views of
    // one instant: nodes that detected whenever they were free would send views of different instants, and no set
    // would be whole. A tick the detector cannot keep up with is skipped, never queued.
    const int64_t period = tick_period_us(config_.detect_rate_hz, processing_us);
    if (tick == 0) tick = (monotonic_to_wall_us(c.newest.time_us) / period + 1) * period;
    if (monotonic_to_wall_us(c.newest.time_us) < tick) continue;  // the tick's picture is yet to come
    const bool previous_nearer =
        c.previous.sequence != 0 && std::llabs(monotonic_to_wall_us(c.previous.time_us) - tick) <
                                        std::llabs(monotonic_to_wall_us(c.newest.time_us) - tick);
    const uint64_t chosen = previous_nearer ? c.previous.sequence : c.newest.sequence;
    if (!cam.feed->take(chosen, frame)) continue;
    last = std::max(c.newest.sequence, c.previous.sequence);
    const cv::Mat& m = frame.image;
    std::vector<std::vector<DetectedPerson>> found;
    try {
      found = cam.detector->detect({ImageView{m.data, m.cols, m.rows, static_cast<int>(m.step[0]), PixelFormat::bgr8}});
    } catch (const std::exception& e) {  // octocap's, OpenCV's, the allocator's: no thread ends the process
      log(LogLevel::warning, "capture node: camera '" + cam.name + "': detection failed: " + e.what());
      continue;
    }
    view.people.clear();
    for (DetectedPerson& d : found.at(0)) view.people.push_back(std::move(d.keypoints));
    // The crop path follows the most confident person of the last picture (a hub's 3D is not known here).
    if (!view.people.empty()) cam.detector->set_hints({{view.people.front()}});
    view.frame_number = ++cam.frame_number;
    view.capture_time_us = monotonic_to_wall_us(frame.grab_us);
    view.stream_time_us = frame.stream_us;
    view.nominal_fps = static_cast<float>(cam.feed->nominal_fps());
    view.layout = cam.detector->card().layout;
    view.width = m.cols;
    view.height = m.rows;
    const int64_t done_us = monotonic_us();
    view.processing_ms = static_cast<float>(done_us - frame.grab_us) / 1000.0f;
    processing_us = processing_us > 0 ? 0.9 * processing_us + 0.1 * static_cast<double>(done_us - frame.grab_us)
                                      : static_cast<double>(done_us - frame.grab_us);
    const int64_t next_period = tick_period_us(config_.detect_rate_hz, processing_us);
    tick = (monotonic_to_wall_us(done_us) / next_period + 1) * next_period;
    try {
      publisher_->publish(view);
    } catch (const std::exception& e) {  // octocap's, OpenCV's, the allocator's: no thread ends the process
      log(LogLevel::warning, "capture node: camera '" + cam.name + "': " + e.what());
      continue;
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    const double n = static_cast<double>(++stats_.published);
    stats_.with_person += !view.people.empty();
    stats_.detect_ms += (cam.detector->timings().total_ms - stats_.detect_ms) / n;
    stats_.processing_ms += (view.processing_ms - stats_.processing_ms) / n;
  }
}

}  // namespace octocap::internal
