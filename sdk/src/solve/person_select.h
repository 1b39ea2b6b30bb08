// Picks, per view, the person to solve when a view holds several (bystanders are real).
#pragma once
#include <vector>

#include "core/camera.h"
#include "core/person2d.h"
#include "solve/observation.h"

namespace octocap::internal {

struct PersonSelectParams {
  double min_confidence = 0.3;
  double association_threshold_px = 30;  // a view whose person reprojects worse than this gets none
};

// people[view][person] = 2D keypoints. `previous` = last frame's 3D keypoints (NaN when unknown), or empty.
// Returns a person index per view, -1 for none. With a previous frame, each view takes the person closest
// to the previous pose's reprojection; views it cannot match, and a first frame, are decided by the
// combination of people that agrees best across views (lowest reprojection error of their triangulation).
std::vector<int> select_people(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                               const std::vector<Eigen::Vector3d>& previous, const PersonSelectParams& params);

}  // namespace octocap::internal
