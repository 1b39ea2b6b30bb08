// Session::solve_images: the detect stage in front of the keypoint solve, and the feedback of each solved frame
// to the next detection (crops and person picking follow the reprojected joints).
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "pipeline/session.h"

namespace octocap::internal {

void Session::remember_whole_people() {
  std::map<uint32_t, std::vector<Eigen::Vector3d>> kept;
  for (const PersonResult& person : frame_.people) {
    const std::vector<Eigen::Vector3d> now = measured_keypoints(person);
    std::vector<Eigen::Vector3d> whole(now.size(), Eigen::Vector3d::Constant(NAN));
    if (auto it = whole_people_.find(person.id); it != whole_people_.end() && it->second.size() == whole.size())
      whole = std::move(it->second);
    // How far the person moved since the keypoints both frames have were seen: the ones this frame lacks move as much.
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    int common = 0;
    for (size_t k = 0; k < whole.size(); ++k)
      if (now[k].allFinite() && whole[k].allFinite()) shift += now[k] - whole[k], ++common;
    if (common > 0) shift /= common;
    for (size_t k = 0; k < whole.size(); ++k) whole[k] = now[k].allFinite() ? now[k] : Eigen::Vector3d(whole[k] + shift);
    kept[person.id] = std::move(whole);
  }
  whole_people_ = std::move(kept);  // someone no longer solved is no longer followed
}

std::vector<Eigen::Vector3d> Session::measured_keypoints(const PersonResult& person) const {
  const PersonState* state = state_of(person.id);
  const bool locked = state && state->lock_shift.size() == person.keypoints.size();
  std::vector<Eigen::Vector3d> out(person.keypoints.size(), Eigen::Vector3d::Constant(NAN));
  for (size_t k = 0; k < out.size(); ++k)
    if (person.keypoints[k].valid)
      out[k] = locked ? Eigen::Vector3d(person.keypoints[k].position - state->lock_shift[k]) : person.keypoints[k].position;
  return out;
}

const Session::PersonState* Session::state_of(uint32_t id) const {
  if (config_.max_people == 1) return &single_;
  const auto it = states_.find(id);
  return it == states_.end() ? nullptr : &it->second;
}

std::vector<std::vector<Person2D>> Session::reprojected_people() const {
  std::vector<std::vector<Person2D>> hints(calib_.size());
  if (!solved_any_ || frame_.info.keypoints_solved == 0) return hints;
  // Everyone solved (one person: the one followed), in id order: the crops follow each, the whole person. A frame
  // that solved only part of someone (two views lost their upper body) must not shrink the crops to that part: they
  // would show only legs, the network would find only legs, and the upper body stayed lost (seen in the RTSP live
  // test when its streams decoded corrupt: views kept only the legs for seconds after the pictures were whole again).
  // The keypoints this frame lacks are put where they were last seen, moved with the person, at a confidence that
  // only the crop's box counts (not the person picking).
  constexpr double kRemembered = 2 * Detector::kHintConfidence;
  for (const PersonResult& person : frame_.people) {
    const auto whole = whole_people_.find(person.id);
    const std::vector<Eigen::Vector3d> measured = measured_keypoints(person);
    for (size_t v = 0; v < calib_.size(); ++v) {
      Person2D p(person.keypoints.size());
      for (size_t k = 0; k < person.keypoints.size(); ++k) {
        const bool valid = person.keypoints[k].valid;
        const bool remembered = whole != whole_people_.end() && k < whole->second.size() && whole->second[k].allFinite();
        if (!valid && !remembered) continue;
        const Eigen::Vector2d px = calib_[v].project(valid ? measured[k] : whole->second[k]);
        if (std::isfinite(px.x()) && std::isfinite(px.y())) p[k] = {px.x(), px.y(), valid ? 1.0 : kRemembered};
      }
      hints[v].push_back(std::move(p));
    }
  }
  return hints;
}

void Session::set_detector(const DetectorConfig& given) {
  DetectorConfig config = given;
  if (config_.max_people != 1) {
    // Several people: up to as many per view as are solved; crops follow each and look for newcomers. Without a
    // model named, the multi-person model on whole views: on Pose2Sim's two-person take it kept both people in every
    // frame at 71 ms a frame, where crops of each kept them in 98 of 100 at 177 ms (README, "Several people").
    config.find_new_people = true;
    // A count of 0 stays 0: raised, the Detector (where the config is checked) would not see the caller's mistake.
    if (config.max_people > 0)
      config.max_people = std::max<size_t>(config.max_people, config_.max_people == 0 ? kMaxPeople : config_.max_people);
    if (config.model.empty()) {
      config.model = "movenet-multipose";
      config.mode = DetectMode::per_view;
    }
  }
  auto detector = std::make_unique<Detector>(config);
  if (detector->card().layout != layout_->id)
    throw Error(Errc::invalid_argument, "model " + detector->card().name + " gives " +
                                            layout(detector->card().layout).name + " keypoints; create the session "
                                            "with that layout (it has " + layout_->name + ")");
  detector_ = std::move(detector);
  detections_.clear();
}

bool Session::solve_images(const std::vector<ImageView>& images, int64_t timestamp_us,
                           const std::vector<GivenView>& given) {
  if (images.size() != calib_.size())
    throw Error(Errc::camera_mismatch, "got " + std::to_string(images.size()) + " images, the calibration has " +
                                           std::to_string(calib_.size()) + " cameras");
  if (!given.empty() && given.size() != images.size())
    throw Error(Errc::camera_mismatch, "given keypoints for " + std::to_string(given.size()) + " views, the calibration has " +
                                           std::to_string(calib_.size()) + " cameras");
  auto is_given = [&](size_t v) { return !given.empty() && given[v].people != nullptr; };
  bool any_image = false;
  for (size_t v = 0; v < images.size(); ++v) {
    if (is_given(v) && !absent(images[v]))
      throw Error(Errc::invalid_argument, "view " + std::to_string(v) + " has both an image and given keypoints");
    if (is_given(v)) {
      const size_t count = layout_->keypoints.size();
      for (const Person2D& p : *given[v].people)
        if (p.size() != count)
          throw Error(Errc::invalid_argument, "view " + std::to_string(v) + ": given people have " + std::to_string(p.size()) +
                                                  " keypoints, the session's layout " + std::to_string(count));
    }
    any_image = any_image || !absent(images[v]);
  }
  if (any_image && !detector_) set_detector(config_.detector);
  // Images at another size than the calibration's (a preview stream, a downscaled render) are fine when the
  // aspect matches: keypoints are scaled to calibration pixels for the solve; detections stay in image pixels.
  std::vector<Eigen::Vector2d> scale(images.size(), Eigen::Vector2d::Ones());
  for (size_t v = 0; v < images.size(); ++v) {
    const Camera& cam = calib_[v];
    const int width = is_given(v) ? given[v].width : images[v].width;
    const int height = is_given(v) ? given[v].height : images[v].height;
    if ((absent(images[v]) && !is_given(v)) || cam.width <= 0 || cam.height <= 0 || width <= 0 || height <= 0 ||
        (cam.width == width && cam.height == height))
      continue;
    scale[v] = {static_cast<double>(cam.width) / width, static_cast<double>(cam.height) / height};
    const std::string mismatch = picture_mismatch(cam, width, height);
    if (!mismatch.empty()) throw Error(Errc::invalid_argument, "image " + std::to_string(v) + ": " + mismatch);
  }
  if (any_image) {
    std::vector<std::vector<Person2D>> hints = reprojected_people();
    for (size_t v = 0; v < hints.size(); ++v)
      for (Person2D& person : hints[v])
        for (Keypoint2D& k : person) k.x = (k.x + 0.5) / scale[v].x() - 0.5, k.y = (k.y + 0.5) / scale[v].y() - 0.5;
    detector_->set_hints(std::move(hints));
    detections_ = detector_->detect(images);
  } else {
    detections_.assign(images.size(), {});
  }
  for (size_t v = 0; v < images.size(); ++v) {
    if (!is_given(v)) continue;
    detections_[v].clear();
    for (const Person2D& p : *given[v].people) {
      DetectedPerson d;
      d.keypoints = p;
      detections_[v].push_back(std::move(d));
    }
  }
  image_people_.assign(detections_.size(), {});
  for (size_t v = 0; v < detections_.size(); ++v)
    for (const DetectedPerson& d : detections_[v]) {
      Person2D p = d.keypoints;
      for (Keypoint2D& k : p) k.x = (k.x + 0.5) * scale[v].x() - 0.5, k.y = (k.y + 0.5) * scale[v].y() - 0.5;
      image_people_[v].push_back(std::move(p));
    }
  const bool solved = solve(image_people_, timestamp_us);
  remember_whole_people();
  return solved;
}

}  // namespace octocap::internal
