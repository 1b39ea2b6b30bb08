#include "image_source.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

namespace fs = std::filesystem;

namespace {

bool has_extension(const fs::path& p, std::initializer_list<const char*> extensions) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* x : extensions)
    if (e == x) return true;
  return false;
}

bool is_picture(const fs::path& p) { return has_extension(p, {".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff"}); }
bool is_video(const fs::path& p) { return has_extension(p, {".mp4", ".avi", ".mov", ".mkv", ".webm"}); }

std::vector<fs::path> sorted_entries(const fs::path& dir, bool (*keep)(const fs::directory_entry&)) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (keep(e)) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

struct ImageSource::Camera {
  std::vector<fs::path> pictures;  // picture folder
  fs::path video;                  // or a video
  cv::VideoCapture capture;
  size_t next = 0;                 // next frame the capture will give
  // Decoding writes each frame into one of these once the frame that was there is let go: a fresh 6 MB picture per
  // camera and frame cost more in page faults than the copy itself. One being decoded, one being solved, one spare.
  cv::Mat buffers[3];

  cv::Mat& unheld_buffer() {
    for (cv::Mat& b : buffers)  // the refcount drops atomically on the solving thread: read it so
      if (b.u == nullptr || __atomic_load_n(&b.u->refcount, __ATOMIC_ACQUIRE) == 1) return b;
    buffers[0].release();  // all still held (a caller keeping frames): theirs stay, this one starts anew
    return buffers[0];
  }
};

ImageSource::ImageSource(const std::string& folder) {
  if (!fs::is_directory(folder)) throw std::runtime_error(folder + " is not a folder");
  const auto videos = sorted_entries(folder, [](const fs::directory_entry& e) { return e.is_regular_file() && is_video(e.path()); });
  const auto dirs = sorted_entries(folder, [](const fs::directory_entry& e) { return e.is_directory(); });
  if (!videos.empty()) {
    for (const auto& v : videos) {
      auto cam = std::make_unique<Camera>();
      cam->video = v;
      cam->capture.open(v.string());
      if (!cam->capture.isOpened()) throw std::runtime_error("cannot open video " + v.string());
      const auto n = static_cast<size_t>(std::max(0.0, cam->capture.get(cv::CAP_PROP_FRAME_COUNT)));
      frames_ = cameras_.empty() ? n : std::min(frames_, n);
      const double fps = cam->capture.get(cv::CAP_PROP_FPS);
      if (cameras_.empty() && std::isfinite(fps) && fps > 0 && fps <= 1e5) fps_ = fps;
      else if (fps_ > 0 && std::abs(fps - fps_) > 0.01 * fps_)
        std::fprintf(stderr, "octocap: warning: %s says %.3g frames/s, %s %.3g: the first camera's rate is used\n",
                     v.filename().string().c_str(), fps, names_.front().c_str(), fps_);
      names_.push_back(v.stem().string());
      cameras_.push_back(std::move(cam));
    }
  } else {
    for (const auto& d : dirs) {
      auto cam = std::make_unique<Camera>();
      cam->pictures = sorted_entries(d, [](const fs::directory_entry& e) { return e.is_regular_file() && is_picture(e.path()); });
      if (cam->pictures.empty()) continue;
      frames_ = cameras_.empty() ? cam->pictures.size() : std::min(frames_, cam->pictures.size());
      names_.push_back(d.filename().string());
      cameras_.push_back(std::move(cam));
    }
  }
  if (cameras_.empty())
    throw std::runtime_error(folder + " holds neither videos (one per camera) nor sub-folders of pictures");
}

ImageSource::~ImageSource() {
  if (ahead_.valid()) ahead_.wait();  // its error, if any, is nobody's now
}

std::vector<cv::Mat> ImageSource::read(size_t f) {
  std::vector<cv::Mat> images;
  if (ahead_.valid() && ahead_frame_ == f) {
    images = ahead_.get();
  } else {
    if (ahead_.valid()) ahead_.wait();  // another frame was asked for: the cameras are free again once it is read
    ahead_ = {};
    images = read_now(f);
  }
  // The next frame decodes while the caller detects and solves this one: one frame ahead, never more.
  if (f + 1 < frames_) {
    ahead_frame_ = f + 1;
    ahead_ = std::async(std::launch::async, [this, f] { return read_now(f + 1); });
  }
  return images;
}

std::vector<cv::Mat> ImageSource::read_now(size_t f) {
  std::vector<cv::Mat> images;
  for (size_t c = 0; c < cameras_.size(); ++c) {
    Camera& cam = *cameras_[c];
    cv::Mat& image = cam.unheld_buffer();
    if (!cam.pictures.empty()) {
      image = cv::imread(cam.pictures.at(f).string(), cv::IMREAD_COLOR);
      if (image.empty()) throw std::runtime_error("cannot read " + cam.pictures[f].string());
    } else {
      if (f < cam.next) {
        cam.capture.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(f));
        cam.next = f;
      }
      while (cam.next <= f) {
        if (!cam.capture.read(image)) throw std::runtime_error("cannot read frame " + std::to_string(f) + " of " + cam.video.string());
        ++cam.next;
      }
    }
    images.push_back(image);
  }
  return images;
}
