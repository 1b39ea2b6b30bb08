// Several people at once: which 2D people of different views are the same 3D person.
#pragma once
#include <Eigen/Geometry>
#include <vector>

#include "core/camera.h"
#include "core/person2d.h"

namespace octocap::internal {

struct AssociationParams {
  double min_confidence = 0.3;
  double threshold_px = 30;  // a view whose person reprojects worse than this (median) is not that person
  int min_views = 2;         // fewest views that keep a tracked person
  int birth_views = 3;       // fewest views that make a new person (two views can agree on a chimera of two people)
  size_t max_people = 16;
  // People whose body (median keypoint) is outside it are bystanders, not people. Empty: no volume test.
  Eigen::AlignedBox3d volume;
};

// One 3D person: the 2D person chosen in each view (-1 none), and which prior it continues (-1: a new person).
struct PersonCluster {
  std::vector<int> choice;
  int prior = -1;
  std::vector<Eigen::Vector3d> pose;  // triangulated from the choice (NaN where unknown)
};

// people[view][person]. `priors`: the 3D keypoints (layout order, NaN unknown) of the people seen last, the
// strongest cue: each view's people are first given to the prior they reproject nearest (one person per prior and
// view, nearest pairs first), and kept where the views then agree. The people left are grouped from the pairs of
// views that agree best, each pair grown by the other views' people nearest its triangulation. Every 2D person
// belongs to one cluster at most (the clustering is consistent across views by construction); a new group that lies
// on a person already found (a view's detection that did not match, say) joins that person instead. At most
// params.max_people clusters, those seen by most views first.
std::vector<PersonCluster> associate_people(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                                            const std::vector<std::vector<Eigen::Vector3d>>& priors,
                                            const AssociationParams& params);

}  // namespace octocap::internal
