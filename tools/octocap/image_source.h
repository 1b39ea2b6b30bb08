// Camera images for the command line: a folder holding one sub-folder of pictures per camera, or one video file
// per camera (sorted by name = calibration order), read frame by frame with OpenCV.
#pragma once
#include <future>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

class ImageSource {
 public:
  // Throws std::runtime_error naming the folder when it holds neither layout, or the cameras disagree in length.
  explicit ImageSource(const std::string& folder);
  ~ImageSource();
  size_t camera_count() const { return names_.size(); }
  size_t frame_count() const { return frames_; }
  const std::vector<std::string>& camera_names() const { return names_; }
  // The videos' frame rate (the first camera's; a warning when the others differ); 0 for picture folders.
  double fps() const { return fps_; }
  // BGR images of every camera for frame f (frames are read in order; going back re-opens the videos). While the
  // caller works on frame f, frame f + 1 is decoded on another thread (decoding four 1088x1920 H.264 streams costs
  // about 18 ms a frame: hidden behind detection instead of added to it).
  std::vector<cv::Mat> read(size_t f);

 private:
  struct Camera;
  std::vector<cv::Mat> read_now(size_t f);
  std::vector<std::string> names_;
  std::vector<std::unique_ptr<Camera>> cameras_;
  size_t frames_ = 0;
  double fps_ = 0;
  std::future<std::vector<cv::Mat>> ahead_;  // the next frame, decoding (declared last: joined first)
  size_t ahead_frame_ = 0;
};
