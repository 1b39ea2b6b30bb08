// A recorded take read frame by frame, for solving offline: a folder holding one video per camera, or one
// sub-folder of pictures per camera, sorted by name (the order a calibration lists its cameras in). Each camera is
// read by the frame sources the live engine plays files with (capture/frame_source.h): one decoder for both paths.
#pragma once
#include <cstddef>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/frame_source.h"

namespace octocap::internal {

class TakeReader {
 public:
  // Throws Error(io) naming the folder when it holds neither videos nor picture sub-folders, or a video cannot be
  // opened.
  explicit TakeReader(const std::string& folder);
  ~TakeReader();
  TakeReader(const TakeReader&) = delete;
  TakeReader& operator=(const TakeReader&) = delete;

  size_t camera_count() const { return cameras_.size(); }
  // The shortest camera's frames: a frame exists when every camera has it.
  size_t frame_count() const { return frames_; }
  // Each camera's name: its video's file name without the extension, or its sub-folder's name.
  const std::vector<std::string>& camera_names() const { return names_; }
  // The videos' rate (the first camera's; the log warns when another says otherwise); 0 for picture folders.
  double fps() const { return fps_; }

  // BGR pictures of every camera for frame f, valid until the next read() (their buffers are reused: a fresh
  // 6 MB picture per camera and frame costs more in page faults than decoding into one kept). While the caller
  // works on frame f, f + 1 decodes on another thread (four 1088x1920 H.264 streams cost about 18 ms a frame,
  // hidden behind detection instead of added to it). Reading forward is cheap; going back seeks. Throws
  // Error(invalid_argument) past the last frame and Error(io) naming the camera when a picture cannot be read.
  const std::vector<cv::Mat>& read(size_t f);

 private:
  struct Camera {
    std::string name;
    std::unique_ptr<FrameSource> source;
    bool pictures = false;  // a folder of pictures, else a video
    size_t next = 0;  // the frame the source's next read() gives
  };
  void read_now(size_t f, std::vector<cv::Mat>& into);
  void read_camera(Camera& camera, size_t f, cv::Mat& into);

  std::vector<std::string> names_;
  std::vector<Camera> cameras_;
  size_t frames_ = 0;
  double fps_ = 0;
  // Two sets of pictures: the one handed out by the last read() and the one the next frame decodes into.
  std::vector<cv::Mat> sets_[2];
  int current_ = 0;
  std::future<void> ahead_;  // decoding frame ahead_frame_ into sets_[1 - current_] (declared last: joined first)
  size_t ahead_frame_ = 0;
};

}  // namespace octocap::internal
