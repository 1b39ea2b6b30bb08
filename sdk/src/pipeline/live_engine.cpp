#include "pipeline/live_engine.h"

#include <algorithm>
#include <exception>
#include <chrono>

#include "capture/camera_feed.h"
#ifdef OCTOCAP_HAVE_DDS
#include "stream/remote_feed.h"
#endif
#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"
#include "core/stats.h"
#include "pipeline/live_recorder.h"
#include "pipeline/rate_governor.h"
#include "stream/stream_config.h"

namespace octocap::internal {
namespace {

constexpr size_t kLatencyWindow = 1000;

// Running mean: stats are means over every frame solved.
void accumulate(double& mean, double value, uint64_t n) { mean += (value - mean) / static_cast<double>(n); }


}  // namespace

void LiveConfig::validate() const {
  feeds.validate();
  check_dds_names(remote_domain_id, remote_topic, "remote cameras'");
  if (!(target_fps >= 0 && target_fps <= 1000))  // NaN fails too
    throw Error(Errc::invalid_argument, "target_fps must be 0 (the cameras' rate) to 1000");
  if (!(latency_budget_ms >= 10 && latency_budget_ms <= 10000))
    throw Error(Errc::invalid_argument, "latency_budget_ms must be 10 to 10000");
}

LiveEngine::LiveEngine(const LiveConfig& config, Calibration calib, const std::vector<std::string>& cameras)
    : config_(config), calib_(std::move(calib)) {
  config_.validate();
  if (cameras.size() != calib_.size())
    throw Error(Errc::camera_mismatch, std::to_string(cameras.size()) + " cameras given, the calibration has " +
                                           std::to_string(calib_.size()) + " (give them in calibration order)");
  // The session first: a config it refuses is an error before any camera is opened.
  session_ = std::make_unique<Session>(config_.session, calib_);
  auto wake = [this] {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      input_pending_ = true;
    }
    new_input_.notify_one();
  };
  for (size_t c = 0; c < cameras.size(); ++c) {
    CameraSpec spec = parse_camera_spec(cameras[c]);
    if (spec.kind != SourceKind::remote) {
      feeds_.push_back(std::make_unique<CameraFeed>(std::move(spec), config_.feeds, wake));
      continue;
    }
#ifdef OCTOCAP_HAVE_DDS
    if (!receiver_) receiver_ = std::make_shared<KeypointReceiver>(config_.remote_domain_id, config_.remote_topic,
                                                                   config_.remote_security);
    feeds_.push_back(std::make_unique<RemoteFeed>(std::move(spec), config_.feeds, receiver_, wake));
#else
    throw Error(Errc::unsupported, "camera '" + cameras[c] + "': remote cameras need DDS, which this build has not");
#endif
  }
  if (!config_.latency_offsets_us.empty() && config_.latency_offsets_us.size() != cameras.size())
    throw Error(Errc::invalid_argument, "latency offsets: one per camera");
}

LiveEngine::~LiveEngine() { stop(); }

FeedStatus LiveEngine::camera_status(size_t i) const { return feeds_.at(i)->status(); }
const CameraSpec& LiveEngine::camera_spec(size_t i) const { return feeds_.at(i)->spec(); }

void LiveEngine::set_detector(const DetectorConfig& config) {
  if (running_) throw Error(Errc::invalid_argument, "the live engine is running: set the detector before start");
  DetectorConfig c = config;
  c.load_lighter = config_.governed;  // the ladder's last rung
  session_->set_detector(c);
  top_views_ = config.views_per_frame;
}

void LiveEngine::set_latency_offsets(const std::vector<int64_t>& offsets_us) {
  if (running_) throw Error(Errc::invalid_argument, "the live engine is running: set latency offsets before start");
  if (offsets_us.size() != feeds_.size())
    throw Error(Errc::invalid_argument, "latency offsets: " + std::to_string(offsets_us.size()) + " given, " +
                                            std::to_string(feeds_.size()) + " cameras");
  for (int64_t o : offsets_us)
    if (o < -10000000 || o > 10000000) throw Error(Errc::invalid_argument, "a latency offset beyond 10 s");
  config_.latency_offsets_us = offsets_us;
}

void LiveEngine::set_recording(const std::string& directory) {
  if (running_) throw Error(Errc::invalid_argument, "the live engine is running: set the recording before start");
  record_dir_ = directory;
}

void LiveEngine::start() {
  if (running_) throw Error(Errc::invalid_argument, "the live engine is already running");
  // Fail before opening cameras; a hub whose cameras are all remote needs no detector (nor models).
  const bool local = std::any_of(feeds_.begin(), feeds_.end(), [](const auto& f) { return f->spec().kind != SourceKind::remote; });
  if (local && !session_->detector()) set_detector(config_.session.detector);
  governor_.reset();
  Detector* detector = session_->detector();
  if (local && detector && config_.governed && detector->config().mode != DetectMode::mosaic) {
    const int views = static_cast<int>(std::count_if(feeds_.begin(), feeds_.end(),
                                                     [](const auto& f) { return f->spec().kind != SourceKind::remote; }));
    GovernorOptions options;
    options.target_fps = config_.target_fps > 0 ? config_.target_fps : 30;
    options.latency_budget_ms = config_.latency_budget_ms;
    governor_ = std::make_unique<RateGovernor>(
        quality_ladder(views, top_views_, static_cast<int>(detector->networks())), options);
  } else if (detector) {
    detector->use_network(0, top_views_);  // a capture that was governed before runs as configured
  }
  if (!record_dir_.empty()) {
    std::vector<bool> pictures;
    for (const auto& f : feeds_) pictures.push_back(f->spec().kind != SourceKind::remote);
    recorder_ = std::make_unique<LiveRecorder>(record_dir_, calib_, pictures);  // Error(io) before any camera opens
  }
  size_t opened = 0;
  try {
    for (; opened < feeds_.size(); ++opened) feeds_[opened]->start();
  } catch (...) {
    for (size_t c = 0; c < opened; ++c) feeds_[c]->stop();
    recorder_.reset();
    throw;
  }
  sync_ = FrameSetOptions{};
  sync_.offsets_us = config_.latency_offsets_us;
  update_sync_window();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stats_ = LiveStats{};
    stats_.running = true;
    latencies_ms_.clear();
    latency_next_ = 0;
  }
  stop_ = false;
  running_ = true;
  thread_ = std::thread([this] { run(); });
}

void LiveEngine::update_sync_window() {
  double slowest = 0;
  for (const auto& f : feeds_) {
    double fps = f->nominal_fps();
    const double measured = f->fps();
    if (measured > 0 && (fps <= 0 || measured < fps)) fps = measured;
    if (fps > 0) slowest = slowest > 0 ? std::min(slowest, fps) : fps;
  }
  if (slowest <= 0) slowest = 30;
  slowest = std::max(slowest, 5.0);  // a camera slower than 5 pictures a second sets no window wider than 200 ms
  slowest_fps_ = slowest;
  sync_.tolerance_us = config_.sync_tolerance_us > 0 ? config_.sync_tolerance_us : static_cast<int64_t>(0.5e6 / slowest);
  // A period and a half: a camera that delivers once a period, with jitter (a capture node's detection time
  // varies), is still awaited; one silent that long is not.
  sync_.max_wait_us = config_.max_wait_us > 0 ? config_.max_wait_us : static_cast<int64_t>(1.5e6 / slowest);
}

void LiveEngine::stop() {
  stop_ = true;
  new_input_.notify_all();
  new_output_.notify_all();
  for (auto& f : feeds_) f->request_stop();  // all at once: a stop waits for the slowest camera, not their sum
  if (thread_.joinable()) thread_.join();
  for (auto& f : feeds_) f->stop();
  running_ = false;
  if (recorder_) recorder_->close();  // everything queued is on disk when stop() returns
  const std::lock_guard<std::mutex> lock(mutex_);
  stats_.running = false;
  add_recording_stats(stats_);  // kept after the recorder is gone
  recorder_.reset();
}

void LiveEngine::add_recording_stats(LiveStats& s) const {
  if (!recorder_) return;
  const RecorderStats r = recorder_->stats();
  s.sets_recorded = r.sets;
  s.recording_pictures_dropped = r.pictures_dropped;
  if (!recorder_->error().empty()) s.last_error = recorder_->error();
}

std::shared_ptr<const FrameResult> LiveEngine::latest() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return latest_;
}

std::shared_ptr<const FrameResult> LiveEngine::take(int timeout_ms) {
  std::unique_lock<std::mutex> lock(mutex_);
  new_output_.wait_for(lock, std::chrono::milliseconds(std::max(0, timeout_ms)),
                       [&] { return latest_serial_ > taken_serial_ || stop_ || stats_.finished; });
  if (latest_serial_ <= taken_serial_) return nullptr;
  taken_serial_ = latest_serial_;
  return latest_;
}

LiveStats LiveEngine::stats() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  LiveStats s = stats_;
  add_recording_stats(s);
  std::vector<double> latencies = latencies_ms_;
  s.latency_p50_ms = quantile_in_place(latencies, 0.5, 0);
  s.latency_p99_ms = quantile_in_place(latencies, 0.99, 0);
  return s;
}

void LiveEngine::run() {
  const size_t n = feeds_.size();
  std::vector<uint64_t> last_used(n, 0);
  std::vector<Candidate> candidates(n);
  std::vector<CapturedFrame> frames(n);
  std::vector<bool> present(n);
  while (!stop_) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      // A short timeout: a set that waits for a late camera goes out at max_wait even if nothing new arrives.
      new_input_.wait_for(lock, std::chrono::milliseconds(5), [&] { return input_pending_ || stop_.load(); });
      input_pending_ = false;
    }
    if (stop_) break;
    bool any = false, all_done = true;
    for (size_t c = 0; c < n; ++c) {
      candidates[c] = feeds_[c]->candidate(last_used[c]);
      any = any || candidates[c].newest.sequence != 0;
      all_done = all_done && feeds_[c]->done();
    }
    if (!any) {
      if (all_done) break;  // files played out
      continue;
    }
    update_sync_window();
    const FrameSetDecision d = decide_frame_set(candidates, monotonic_us(), sync_);
    if (!d.emit && !all_done) continue;  // a camera that delivers is about to: wait for it
    for (size_t c = 0; c < n; ++c) {
      present[c] = d.take[c] != 0 && feeds_[c]->take(d.take[c], frames[c]);
      if (present[c]) last_used[c] = frames[c].sequence;
    }
    if (const std::string wrong = wrong_picture(frames, present); !wrong.empty()) {
      // Not a set to drop and go on from: every later picture of that camera is as wrong, and a take that runs its
      // whole duration solving nothing is a take lost.
      log(LogLevel::error, "live: " + wrong);
      const std::lock_guard<std::mutex> lock(mutex_);
      stats_.last_error = wrong;
      stats_.failed = true;
      break;
    }
    if (std::none_of(present.begin(), present.end(), [](bool p) { return p; })) {
      // Every camera ended and their last pictures make no set: nothing is left to solve.
      for (size_t c = 0; c < n; ++c) last_used[c] = std::max(last_used[c], candidates[c].newest.sequence);
      continue;
    }
    solve_set(frames, present, d.time_us);
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  stats_.finished = !stop_ || stats_.failed;
  new_output_.notify_all();
}

std::string LiveEngine::wrong_picture(const std::vector<CapturedFrame>& frames, const std::vector<bool>& present) const {
  for (size_t c = 0; c < frames.size(); ++c) {
    if (!present[c]) continue;
    const int width = frames[c].has_keypoints ? frames[c].width : frames[c].image.cols;
    const int height = frames[c].has_keypoints ? frames[c].height : frames[c].image.rows;
    const std::string mismatch = picture_mismatch(calib_[c], width, height);
    if (!mismatch.empty()) return "camera '" + feeds_[c]->spec().text + "': " + mismatch;
  }
  return "";
}

void LiveEngine::govern_before_set() {
  if (!governor_) return;
  // The cameras' rate is known only once they deliver; a configured target stays.
  if (config_.target_fps <= 0) governor_->set_target_fps(slowest_fps_);
  const QualityRung& r = governor_->rung();
  session_->detector()->use_network(static_cast<size_t>(r.network), r.views);
}

void LiveEngine::govern_after_set(double cost_ms, double wait_ms, int64_t now_us) {
  const Detector* detector = session_->detector();
  const bool changed = governor_ && governor_->observe(cost_ms, wait_ms, now_us);
  const std::lock_guard<std::mutex> lock(mutex_);
  if (detector) stats_.model = detector->card().name;
  if (!governor_) return;
  stats_.quality_rung = static_cast<uint32_t>(governor_->rung_index());
  stats_.quality_rungs = static_cast<uint32_t>(governor_->rungs());
  stats_.target_fps = config_.target_fps > 0 ? config_.target_fps : slowest_fps_;
  stats_.budget_used = governor_->budget_used();
  if (changed) ++stats_.rung_changes;
}

void LiveEngine::solve_set(const std::vector<CapturedFrame>& frames, const std::vector<bool>& present,
                           int64_t set_time_us) {
  govern_before_set();
  const int64_t t0 = monotonic_us();
  int64_t oldest_grab = t0;
  std::vector<ImageView> views(frames.size());
  std::vector<GivenView> given(frames.size());
  for (size_t c = 0; c < frames.size(); ++c) {
    if (!present[c]) continue;  // an absent view: solved without
    oldest_grab = std::min(oldest_grab, frames[c].grab_us);
    if (frames[c].has_keypoints) {
      given[c] = {&frames[c].people, frames[c].width, frames[c].height};  // a capture node detected them
      continue;
    }
    const cv::Mat& m = frames[c].image;
    views[c] = {m.data, m.cols, m.rows, static_cast<int>(m.step[0]), PixelFormat::bgr8};
  }
  bool solved = false;
  try {
    solved = session_->solve_images(views, set_time_us, given);
  } catch (const std::exception& e) {  // octocap's, OpenCV's, the allocator's: no thread ends the process
    log(LogLevel::warning, std::string("live: a frame set could not be solved: ") + e.what());
    const std::lock_guard<std::mutex> lock(mutex_);
    stats_.last_error = e.what();
    return;
  }
  const int64_t t1 = monotonic_us();
  if (recorder_) record(frames, present, set_time_us);
  auto frame = std::make_shared<const FrameResult>(session_->result());
  const bool detected = std::any_of(views.begin(), views.end(), [](const ImageView& v) { return !absent(v); });
  const double detect_ms = detected && session_->detector() ? session_->detector()->timings().total_ms : 0;
  const uint32_t pictures = static_cast<uint32_t>(std::count_if(views.begin(), views.end(), [](const ImageView& v) { return !absent(v); }));
  const uint32_t views_detected =
      detected && session_->detector() ? pictures - static_cast<uint32_t>(session_->detector()->timings().views_tracked) : 0;
  const uint32_t views_in_set = static_cast<uint32_t>(std::count(present.begin(), present.end(), true));
  govern_after_set(static_cast<double>(t1 - t0) / 1000.0, static_cast<double>(t0 - oldest_grab) / 1000.0, t1);
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (latest_serial_ > taken_serial_) ++stats_.frames_not_taken;
    latest_ = std::move(frame);
    ++latest_serial_;
    const uint64_t k = ++stats_.frame_sets;
    if (views_in_set < present.size()) ++stats_.sets_incomplete;
    if (solved) ++stats_.frames_with_person;
    stats_.views_detected = views_detected;
    stats_.views_in_set = views_in_set;
    const double latency = static_cast<double>(monotonic_us() - oldest_grab) / 1000.0;
    accumulate(stats_.capture_ms, static_cast<double>(t0 - oldest_grab) / 1000.0, k);
    accumulate(stats_.detect_ms, detect_ms, k);
    accumulate(stats_.solve_ms, static_cast<double>(t1 - t0) / 1000.0 - detect_ms, k);
    accumulate(stats_.publish_ms, static_cast<double>(monotonic_us() - t1) / 1000.0, k);
    if (latencies_ms_.size() < kLatencyWindow) latencies_ms_.push_back(latency);
    else latencies_ms_[latency_next_++ % kLatencyWindow] = latency;
    if (last_solved_us_ > 0 && t1 > last_solved_us_) {
      const double dt = static_cast<double>(t1 - last_solved_us_);
      mean_interval_us_ = mean_interval_us_ > 0 ? 0.9 * mean_interval_us_ + 0.1 * dt : dt;
      stats_.fps = 1e6 / mean_interval_us_;
    }
    last_solved_us_ = t1;
  }
  new_output_.notify_all();
}

void LiveEngine::record(const std::vector<CapturedFrame>& frames, const std::vector<bool>& present,
                        int64_t set_time_us) {
  RecordedSet set;
  set.time_us = set_time_us;
  set.people = session_->image_people();
  set.people.resize(frames.size());
  set.capture_us.assign(frames.size(), 0);
  set.pictures.resize(frames.size());
  for (size_t c = 0; c < frames.size(); ++c) {
    if (!present[c]) {
      set.people[c].clear();  // nobody seen: the solve went without this camera
      continue;
    }
    set.capture_us[c] = frames[c].grab_us;
    set.pictures[c] = frames[c].image;  // shared, never copied: every picture has a buffer of its own
  }
  recorder_->add(std::move(set));
}

}  // namespace octocap::internal
