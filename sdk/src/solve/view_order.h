// Whether the views are in the calibration's order: two cameras' pictures given in each other's place are outvoted
// by the others and solve quietly worse (Pose2Sim's take with cam02 and cam03 swapped solved 85 % of its keypoints at
// a lower reprojection error than the right order). Their 2D people still tell. A pair of views alone does not: the
// epipolar constraint tests one image direction only, and for cameras at one height around a person that is the
// height, which every camera sees alike. Three views do: a keypoint triangulated from two views lands, in the third
// camera, on that view's keypoint only if all three pictures were taken by the cameras assumed. The check scores
// every assignment of views to cameras by the share of such transfers that land within the tolerance, over the
// first frames with people in three views or more.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/person2d.h"

namespace octocap::internal {

class ViewOrderCheck {
 public:
  // The most views checked (8! orders are scored once; the per-frame work grows with the fifth power of the views).
  static constexpr size_t kMaxViews = 8;

  // `tolerance_px`: how far from a view's keypoint a transfer may land and still agree, at least (larger pictures
  // get a larger one); `frames`: how many frames
  // with people in three or more views the verdict waits for. Rigs of fewer than 3 or more than kMaxViews views are
  // never judged.
  ViewOrderCheck(Calibration calib, double min_confidence, double tolerance_px, size_t frames = 60);

  // One frame's usable 2D people per view (calibration order). Returns true once, on the frame that decides.
  bool add(const std::vector<std::vector<Person2D>>& people);
  bool decided() const { return decided_; }
  // After the deciding frame: "" when the calibration's order fits best, else what looks wrong, naming the cameras.
  const std::string& verdict() const { return verdict_; }
  // The assignment that fits best (best()[view] = camera), and the share of transfers agreeing under it and under
  // the calibration's order.
  const std::vector<int>& best() const { return best_; }
  double best_agreement() const { return best_share_; }
  double given_agreement() const { return given_share_; }

 private:
  void decide();
  size_t at(size_t a, size_t b, size_t c, size_t ca, size_t cb, size_t cc) const {
    return ((((a * n_ + b) * n_ + c) * n_ + ca) * n_ + cb) * n_ + cc;
  }

  Calibration calib_;
  size_t n_;
  double min_conf_;
  std::vector<double> tolerance_;  // per camera, pixels
  size_t frames_wanted_, frames_ = 0;
  // agree_[at(a, b, c, ca, cb, cc)]: keypoints triangulated from views a < b, taken as cameras ca and cb, that land
  // on view c's keypoint in camera cc. tested_[(a * n + b) * n + c]: keypoints confident in all three views.
  std::vector<double> agree_, tested_;
  bool decided_ = false;
  std::string verdict_;
  std::vector<int> best_;
  double best_share_ = 0, given_share_ = 0;
};

}  // namespace octocap::internal
