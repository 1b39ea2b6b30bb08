// Session::solve_images: the detect stage in front of the keypoint solve, and the feedback of each solved frame
// to the next detection (crops and person picking follow the reprojected joints).
#include <cmath>

#include "core/error.h"
#include "pipeline/session.h"

namespace octocap {

std::vector<Person2D> Session::reprojected_keypoints() const {
  std::vector<Person2D> hints(calib_.size());
  if (!solved_any_ || frame_.info.keypoints_solved == 0) return hints;
  for (size_t v = 0; v < calib_.size(); ++v) {
    Person2D& p = hints[v];
    p.resize(frame_.keypoints.size());
    for (size_t k = 0; k < frame_.keypoints.size(); ++k) {
      if (!frame_.keypoints[k].valid) continue;
      const Eigen::Vector2d px = calib_[v].project(frame_.keypoints[k].position);
      if (std::isfinite(px.x()) && std::isfinite(px.y())) p[k] = {px.x(), px.y(), 1.0};
    }
  }
  return hints;
}

void Session::set_detector(const DetectorConfig& config) {
  auto detector = std::make_unique<Detector>(config);
  if (detector->card().layout != layout_->id)
    throw Error(Errc::invalid_argument, "model " + detector->card().name + " gives " +
                                            layout(detector->card().layout).name + " keypoints; create the session "
                                            "with that layout (it has " + layout_->name + ")");
  detector_ = std::move(detector);
  detections_.clear();
}

bool Session::solve_images(const std::vector<ImageView>& images, int64_t timestamp_us) {
  if (images.size() != calib_.size())
    throw Error(Errc::camera_mismatch, "got " + std::to_string(images.size()) + " images, the calibration has " +
                                           std::to_string(calib_.size()) + " cameras");
  if (!detector_) set_detector(config_.detector);
  // Images at another size than the calibration's (a preview stream, a downscaled render) are fine when the
  // aspect matches: keypoints are scaled to calibration pixels for the solve; detections stay in image pixels.
  std::vector<Eigen::Vector2d> scale(images.size(), Eigen::Vector2d::Ones());
  for (size_t v = 0; v < images.size(); ++v) {
    const Camera& cam = calib_[v];
    if (absent(images[v]) || cam.width <= 0 || cam.height <= 0 ||
        (cam.width == images[v].width && cam.height == images[v].height))
      continue;
    scale[v] = {static_cast<double>(cam.width) / images[v].width, static_cast<double>(cam.height) / images[v].height};
    if (std::abs(scale[v].x() / scale[v].y() - 1) > 0.01)
      throw Error(Errc::invalid_argument, "image " + std::to_string(v) + " is " + std::to_string(images[v].width) + "x" +
                                              std::to_string(images[v].height) + ", camera " + cam.name + " was calibrated at " +
                                              std::to_string(cam.width) + "x" + std::to_string(cam.height) +
                                              " (another aspect ratio: not the same picture)");
  }
  std::vector<Person2D> hints = reprojected_keypoints();
  for (size_t v = 0; v < hints.size(); ++v)
    for (Keypoint2D& k : hints[v]) k.x = (k.x + 0.5) / scale[v].x() - 0.5, k.y = (k.y + 0.5) / scale[v].y() - 0.5;
  detector_->set_hints(std::move(hints));
  detections_ = detector_->detect(images);
  std::vector<std::vector<Person2D>> people(detections_.size());
  for (size_t v = 0; v < detections_.size(); ++v)
    for (const DetectedPerson& d : detections_[v]) {
      Person2D p = d.keypoints;
      for (Keypoint2D& k : p) k.x = (k.x + 0.5) * scale[v].x() - 0.5, k.y = (k.y + 0.5) * scale[v].y() - 0.5;
      people[v].push_back(std::move(p));
    }
  return solve(people, timestamp_us);
}

}  // namespace octocap
