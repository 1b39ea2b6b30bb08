#include "pipeline/live_recorder.h"

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "core/log.h"
#include "io/calibration_toml.h"
#include "io/openpose_json.h"

namespace fs = std::filesystem;

namespace octocap::internal {
namespace {

// Sets with pictures waiting for the writer: a few, so that a slow disk costs pictures, not memory (four 1080p
// cameras: ~25 MB a set).
constexpr size_t kMaxSetsWithPictures = 4;
// Sets of keypoints and times waiting: a disk this far behind loses whole sets.
constexpr size_t kMaxSets = 256;

std::string numbered(uint64_t n, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%0*llu", digits, static_cast<unsigned long long>(n));
  return buf;
}

}  // namespace

LiveRecorder::LiveRecorder(const std::string& directory, const Calibration& calib, const std::vector<bool>& pictures)
    : dir_(directory) {
  if (directory.empty()) throw Error(Errc::invalid_argument, "recording: no folder given");
  if (pictures.size() != calib.size()) throw Error(Errc::camera_mismatch, "recording: one picture flag per camera");
  const fs::path root(directory);
  std::error_code ec;
  if (fs::exists(root / "timestamps.csv", ec) || fs::exists(root / "keypoints", ec))
    throw Error(Errc::io, "recording: " + directory + " already holds a take (record into a new folder)");
  for (size_t c = 0; c < calib.size(); ++c) {
    const std::string name = calib[c].name;
    const std::string place = numbered(c + 1, 2) + "_" + name;
    names_.push_back(name);
    keypoint_dirs_.push_back((root / "keypoints" / (place + "_json")).string());
    image_dirs_.push_back(pictures[c] ? (root / "images" / place).string() : std::string());
    sizes_.emplace_back(calib[c].width, calib[c].height);
  }
  try {
    for (size_t c = 0; c < calib.size(); ++c) {
      fs::create_directories(keypoint_dirs_[c]);
      if (!image_dirs_[c].empty()) fs::create_directories(image_dirs_[c]);
    }
  } catch (const fs::filesystem_error& e) {
    throw Error(Errc::io, "recording: cannot create folders in " + directory + ": " + e.what());
  }
  write_calibration_toml(calib, (root / "calibration.toml").string());
  times_.open(root / "timestamps.csv");
  if (!times_) throw Error(Errc::io, "recording: cannot write " + (root / "timestamps.csv").string());
  times_ << "set,time_us,pictures";
  for (const std::string& n : names_) times_ << "," << n << "_us";
  times_ << "\n";
  thread_ = std::thread([this] { run(); });
}

LiveRecorder::~LiveRecorder() { close(); }

void LiveRecorder::add(RecordedSet set) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (closing_ || !error_.empty()) return;
    if (queue_.size() >= kMaxSets) {
      ++stats_.sets_dropped;
      return;
    }
    const bool with_pictures = queued_with_pictures_ < kMaxSetsWithPictures;
    if (!with_pictures) {
      ++stats_.pictures_dropped;
      set.pictures.clear();
    }
    queued_with_pictures_ += with_pictures;
    queue_.push_back(Job{next_index_++, std::move(set), with_pictures});
  }
  wake_.notify_one();
}

void LiveRecorder::close() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
  if (times_.is_open()) times_.close();
}

RecorderStats LiveRecorder::stats() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

std::string LiveRecorder::error() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

void LiveRecorder::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return closing_ || !queue_.empty(); });
      if (queue_.empty()) return;  // closing, everything written
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    try {
      write(job);
    } catch (const std::exception& e) {
      const std::lock_guard<std::mutex> lock(mutex_);
      error_ = e.what();
      queue_.clear();
      log(LogLevel::error, "recording stopped: " + error_);
      return;
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    queued_with_pictures_ -= job.with_pictures;
    ++stats_.sets;
  }
}

void LiveRecorder::write(const Job& job) {
  const RecordedSet& s = job.set;
  for (size_t c = 0; c < names_.size(); ++c) {
    write_openpose_file((fs::path(keypoint_dirs_[c]) / (names_[c] + "_" + numbered(job.index, 12) + "_keypoints.json")).string(),
                        c < s.people.size() ? s.people[c] : std::vector<Person2D>{});
    if (!job.with_pictures || image_dirs_[c].empty()) continue;
    const bool present = c < s.pictures.size() && !s.pictures[c].empty();
    if (present) sizes_[c] = s.pictures[c].size();
    const cv::Mat picture = present ? s.pictures[c] : cv::Mat(sizes_[c], CV_8UC3, cv::Scalar::all(0));
    const std::string path = (fs::path(image_dirs_[c]) / (numbered(job.index, 6) + ".jpg")).string();
    if (!cv::imwrite(path, picture, {cv::IMWRITE_JPEG_QUALITY, 92})) throw Error(Errc::io, "cannot write " + path);
  }
  times_ << job.index << "," << s.time_us << "," << (job.with_pictures ? 1 : 0);
  for (size_t c = 0; c < names_.size(); ++c) {
    times_ << ",";
    if (c < s.capture_us.size() && s.capture_us[c] != 0) times_ << s.capture_us[c];
  }
  // Flushed with each set, after its files: a take killed mid-run keeps every set whose line is there (one write per
  // set, on the recorder's own thread).
  times_ << "\n" << std::flush;
  if (!times_) throw Error(Errc::io, "cannot write " + (fs::path(dir_) / "timestamps.csv").string());
}

}  // namespace octocap::internal
