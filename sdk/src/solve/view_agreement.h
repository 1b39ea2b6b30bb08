// How well 2D people of several views agree on one 3D person: the measures that person selection and the
// association of several people share.
#pragma once
#include <vector>

#include "core/camera.h"
#include "core/person2d.h"

namespace octocap::internal {

// Median pixel distance between a person's confident keypoints and the projection of known 3D keypoints (NaN where
// unknown); infinity with fewer than 3 keypoints to compare.
double distance_to_pose(const Camera& cam, const Person2D& person, const std::vector<Eigen::Vector3d>& pose,
                        double min_conf);

// Per-view median reprojection error of the keypoints triangulated from the chosen people (choice[view] = person
// index, -1 none); infinity for a view not chosen or with fewer than 3 keypoints. `pose` (when given) receives the
// triangulated keypoints, NaN where fewer than two views saw one.
std::vector<double> combination_errors(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                                       const std::vector<int>& choice, double min_conf,
                                       std::vector<Eigen::Vector3d>* pose = nullptr);

// Grows `choice` by the views it lacks: each takes, among its candidates (cands[view], indices into people[view]),
// the person nearest the reprojection of the choice's triangulation, when nearer than `max_px`.
void grow_by_nearest(const Calibration& calib, const std::vector<std::vector<Person2D>>& people,
                     const std::vector<std::vector<int>>& cands, double min_conf, double max_px,
                     std::vector<int>& choice);

}  // namespace octocap::internal
