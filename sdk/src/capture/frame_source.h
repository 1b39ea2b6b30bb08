// Reading pictures from one camera, whatever it is. OpenCV's videoio does the work: V4L2 for devices, FFmpeg for
// network streams and files (with open and read timeouts, so a dead server is an error, never a hang).
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "capture/camera_spec.h"

namespace octocap {

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
};

std::unique_ptr<FrameSource> make_frame_source(const CameraSpec& spec, const SourceOptions& options);

}  // namespace octocap
