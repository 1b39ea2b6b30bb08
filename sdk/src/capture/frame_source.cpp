#include "capture/frame_source.h"

#include <stdlib.h>

#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "capture/mjpeg_http_source.h"
#include "core/error.h"
#include "core/log.h"
#include "io/directories.h"

namespace octocap::internal {
namespace {

// FFmpeg logs to stderr on its own (a refused connection, each retry); the library prints nothing, so it is told to
// be quiet unless the user asked otherwise (OPENCV_FFMPEG_LOGLEVEL set). Reasons reach the log through Error.
void quiet_ffmpeg() {
  static const bool once = [] {
    setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);
    return true;
  }();
  (void)once;
}

class VideoSource : public FrameSource {
 public:
  VideoSource(CameraSpec spec, SourceOptions options) : spec_(std::move(spec)), options_(options) {}

  void open() override {
    quiet_ffmpeg();
    cap_.release();
    const std::vector<int> params = {cv::CAP_PROP_OPEN_TIMEOUT_MSEC, options_.open_timeout_ms,
                                     cv::CAP_PROP_READ_TIMEOUT_MSEC, options_.read_timeout_ms};
    const bool ok = spec_.kind == SourceKind::device ? cap_.open(spec_.device_index, cv::CAP_V4L2, params)
                                                     : cap_.open(spec_.location, cv::CAP_FFMPEG, params);
    if (!ok || !cap_.isOpened()) throw Error(Errc::io, "camera '" + spec_.text + "': cannot be opened");
    // Live sources: the driver's queue is latency, not safety; the feed keeps the newest picture itself.
    if (spec_.live()) cap_.set(cv::CAP_PROP_BUFFERSIZE, 1);
    first_pts_ms_ = -1;
  }

  bool read(cv::Mat& bgr, int64_t& stream_us) override {
    if (!cap_.grab() || !cap_.retrieve(bgr) || bgr.empty()) return false;
    const double pts_ms = cap_.get(cv::CAP_PROP_POS_MSEC);
    if (first_pts_ms_ < 0) first_pts_ms_ = pts_ms;
    stream_us = static_cast<int64_t>((pts_ms - first_pts_ms_) * 1000.0);
    return true;
  }

  double nominal_fps() const override {
    const double fps = cap_.get(cv::CAP_PROP_FPS);
    return fps > 0 && fps < 1000 ? fps : 0;
  }

  int64_t frame_count() const override {
    if (spec_.kind != SourceKind::video_file) return -1;
    const double n = cap_.get(cv::CAP_PROP_FRAME_COUNT);
    return n > 0 && n < 1e12 ? static_cast<int64_t>(n) : -1;
  }

  bool seek(int64_t frame) override {
    return spec_.kind == SourceKind::video_file && cap_.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(frame));
  }

 private:
  CameraSpec spec_;
  SourceOptions options_;
  cv::VideoCapture cap_;
  double first_pts_ms_ = -1;
};

class PictureFolderSource : public FrameSource {
 public:
  PictureFolderSource(CameraSpec spec, SourceOptions options) : spec_(std::move(spec)), options_(options) {}

  void open() override {
    files_ = sorted_files(spec_.location, picture_extensions());
    if (files_.empty()) throw Error(Errc::io, "camera '" + spec_.text + "': the folder holds no pictures");
    next_ = 0;
  }

  bool read(cv::Mat& bgr, int64_t& stream_us) override {
    for (; next_ < files_.size(); ++next_) {
      bgr = cv::imread(files_[next_]);
      if (bgr.empty()) {
        // One bad file is one missing frame, as a camera drops one; the take goes on in time (the index is the clock).
        ++bad_;
        log(LogLevel::warning, "camera '" + spec_.text + "': skipped " + files_[next_] + ": not a readable picture");
        continue;
      }
      stream_us = static_cast<int64_t>(next_ * 1e6 / options_.picture_rate_hz);
      ++next_;
      return true;
    }
    return false;
  }

  double nominal_fps() const override { return options_.picture_rate_hz; }
  uint64_t bad_pictures() const override { return bad_; }
  int64_t frame_count() const override { return static_cast<int64_t>(files_.size()); }
  bool seek(int64_t frame) override {
    if (frame < 0 || static_cast<size_t>(frame) > files_.size()) return false;
    next_ = static_cast<size_t>(frame);
    return true;
  }

 private:
  CameraSpec spec_;
  SourceOptions options_;
  std::vector<std::string> files_;
  size_t next_ = 0;
  uint64_t bad_ = 0;
};

}  // namespace

std::unique_ptr<FrameSource> make_frame_source(const CameraSpec& spec, const SourceOptions& options) {
  if (spec.kind == SourceKind::picture_folder) return std::make_unique<PictureFolderSource>(spec, options);
  // Plain HTTP only: HTTPS stays with FFmpeg, which (unlike libcurl's default) accepts the self-signed certificates
  // IP cameras ship with.
  if (spec.kind == SourceKind::network && spec.location.rfind("http://", 0) == 0)
    return make_mjpeg_http_source(spec, options);
  return make_ffmpeg_source(spec, options);
}

std::unique_ptr<FrameSource> make_ffmpeg_source(const CameraSpec& spec, const SourceOptions& options) {
  return std::make_unique<VideoSource>(spec, options);
}

}  // namespace octocap::internal
