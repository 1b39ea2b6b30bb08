#include "capture/take_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/log.h"
#include "io/directories.h"

namespace fs = std::filesystem;

namespace octocap::internal {

TakeReader::TakeReader(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw Error(Errc::io, folder + " is not a folder");
  const SourceOptions options;  // a folder's pictures play at its default rate: the index is the take's clock
  const std::vector<std::string> videos = sorted_files(folder, video_extensions());
  std::vector<std::pair<std::string, CameraSpec>> specs;
  if (!videos.empty()) {
    for (const std::string& v : videos) specs.emplace_back(fs::path(v).stem().string(), parse_camera_spec(v));
  } else {
    for (const fs::path& d : sorted_subdirectories(folder))
      if (!sorted_files(d.string(), picture_extensions()).empty())
        specs.emplace_back(d.filename().string(), parse_camera_spec(d.string()));
  }
  if (specs.empty())
    throw Error(Errc::io, folder + " holds neither videos (one per camera) nor sub-folders of pictures");
  for (auto& [name, spec] : specs) {
    Camera cam{name, make_frame_source(spec, options), spec.kind == SourceKind::picture_folder, 0};
    cam.source->open();
    const int64_t n = cam.source->frame_count();
    if (n < 0) throw Error(Errc::io, "camera '" + spec.text + "': it does not say how many frames it holds");
    frames_ = cameras_.empty() ? static_cast<size_t>(n) : std::min(frames_, static_cast<size_t>(n));
    if (spec.kind == SourceKind::video_file) {
      const double fps = cam.source->nominal_fps();
      if (cameras_.empty()) fps_ = fps;
      else if (fps_ > 0 && std::abs(fps - fps_) > 0.01 * fps_)
        log(LogLevel::warning, name + " says " + std::to_string(fps) + " frames/s, " + names_.front() + " " +
                                   std::to_string(fps_) + ": the first camera's rate is used");
    }
    names_.push_back(name);
    cameras_.push_back(std::move(cam));
  }
  for (auto& set : sets_) set.resize(cameras_.size());
}

TakeReader::~TakeReader() {
  if (ahead_.valid()) ahead_.wait();  // its error, if any, is nobody's now
}

const std::vector<cv::Mat>& TakeReader::read(size_t f) {
  if (f >= frames_)
    throw Error(Errc::invalid_argument, "frame " + std::to_string(f) + " is past the take's end (" +
                                            std::to_string(frames_) + " frames)");
  const int next = 1 - current_;
  if (ahead_.valid() && ahead_frame_ == f) {
    std::future<void> done = std::move(ahead_);
    done.get();  // a camera's error comes out here, on the caller's thread
  } else {
    if (ahead_.valid()) ahead_.wait();  // another frame was asked for: the cameras are free once it is read
    ahead_ = {};
    read_now(f, sets_[next]);
  }
  current_ = next;
  // One frame ahead, never more; into the set the caller just let go of.
  if (f + 1 < frames_) {
    ahead_frame_ = f + 1;
    std::vector<cv::Mat>* into = &sets_[1 - current_];
    ahead_ = std::async(std::launch::async, [this, f, into] { read_now(f + 1, *into); });
  }
  return sets_[current_];
}

void TakeReader::read_now(size_t f, std::vector<cv::Mat>& into) {
  for (size_t c = 0; c < cameras_.size(); ++c) read_camera(cameras_[c], f, into[c]);
}

void TakeReader::read_camera(Camera& cam, size_t f, cv::Mat& into) {
  // A picture folder jumps to any frame; a video jumps back, and forward decodes the frames between (exact where a
  // codec's seek lands on a key frame, and cheaper than a seek for the one frame a take reads next).
  if (f < cam.next || (f > cam.next && cam.pictures)) {
    if (!cam.source->seek(static_cast<int64_t>(f)))
      throw Error(Errc::io, "camera '" + cam.name + "': cannot go to frame " + std::to_string(f));
    cam.next = f;
  }
  int64_t stream_us = 0;
  for (; cam.next <= f; ++cam.next) {
    const uint64_t bad_before = cam.source->bad_pictures();
    // A folder's source steps over a picture it cannot read (as a camera drops one); a take's frame would then be
    // another frame's picture, so here it is an error.
    if (!cam.source->read(into, stream_us) || cam.source->bad_pictures() != bad_before)
      throw Error(Errc::io, "camera '" + cam.name + "': cannot read frame " + std::to_string(cam.next));
  }
}

}  // namespace octocap::internal
