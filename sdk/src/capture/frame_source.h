// Reading pictures from one camera, whatever it is. OpenCV's videoio does most of the work: V4L2 for devices, FFmpeg
// for RTSP, HTTPS and files (with open and read timeouts, so a dead server is an error, never a hang); MJPEG over
// plain HTTP has a reader of its own (capture/mjpeg_http_source.h).
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "capture/camera_spec.h"

namespace octocap::internal {

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // Throws Error(io) naming the camera when it cannot be opened.
  virtual void open() = 0;
  // The next picture (BGR) and its time on the stream's own clock (µs from the stream's start); false at the end
  // of a file or when a live stream broke.
  virtual bool read(cv::Mat& bgr, int64_t& stream_us) = 0;
  // Frames per second the source says it delivers (0 when it does not say).
  virtual double nominal_fps() const = 0;
  // Whether read()'s stream_us is the stream's own clock; false: it is the host's monotonic time the picture arrived.
  virtual bool own_timestamps() const { return true; }
  // Pictures the source left out itself: skipped() because a newer one had arrived before read() was called (the
  // reader fell behind), bad_pictures() because they could not be decoded. Both count from construction.
  virtual uint64_t skipped() const { return 0; }
  virtual uint64_t bad_pictures() const { return 0; }
  // From another thread: a blocked open() or read() gives up soon (read() returns false). Sources that cannot be
  // interrupted (FFmpeg's) end at their own timeouts.
  virtual void interrupt() {}
  // Files and folders only: the frames the source holds (-1: a live stream, or a file that does not say), and a
  // jump so that the next read() gives frame `frame` (false where the source cannot jump).
  virtual int64_t frame_count() const { return -1; }
  virtual bool seek(int64_t /*frame*/) { return false; }
};

std::unique_ptr<FrameSource> make_frame_source(const CameraSpec& spec, const SourceOptions& options);
// OpenCV's videoio alone, whatever the spec (the MJPEG reader hands over to it what is not MJPEG).
std::unique_ptr<FrameSource> make_ffmpeg_source(const CameraSpec& spec, const SourceOptions& options);

}  // namespace octocap::internal
