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

void Session::solve_images(const std::vector<ImageView>& images, int64_t timestamp_us) {
  if (images.size() != calib_.size())
    throw Error(Errc::camera_mismatch, "got " + std::to_string(images.size()) + " images, the calibration has " +
                                           std::to_string(calib_.size()) + " cameras");
  if (!detector_) {
    auto detector = std::make_unique<Detector>(config_.detector);
    if (detector->card().layout != layout_->id)
      throw Error(Errc::invalid_argument, "model " + detector->card().name + " gives " +
                                              layout(detector->card().layout).name + " keypoints; create the session "
                                              "with that layout (it has " + layout_->name + ")");
    detector_ = std::move(detector);
  }
  detector_->set_hints(reprojected_keypoints());
  detections_ = detector_->detect(images);
  std::vector<std::vector<Person2D>> people(detections_.size());
  for (size_t v = 0; v < detections_.size(); ++v)
    for (const DetectedPerson& d : detections_[v]) people[v].push_back(d.keypoints);
  solve(people, timestamp_us);
}

}  // namespace octocap
