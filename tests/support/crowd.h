// Several people in one volume, for the multi-person tests and benchmarks: real motion clips (CMU mocap in Debian's
// assimp-testmodels) placed side by side, seen by the cameras with occlusion (a nearer body hides, or takes over, the
// keypoints behind it), people missed in some views, and each view's people in random order.
#pragma once
#include <random>
#include <string>
#include <vector>

#include "synth.h"

namespace octocap::internal::synth {

// `people` real motions of `frames` frames at 30 Hz: CMU clips 01_01 and 01_03 from different moments, each
// placed at its own spot (a ring of `spread` metres around the origin, turned to face a different way), its walk
// shrunk to stay near its spot. frames[person][frame] = BODY_25 keypoints.
std::vector<std::vector<std::vector<Eigen::Vector3d>>> make_crowd(size_t people, size_t frames, double spread = 1.5);

struct CrowdNoise {
  NoiseOptions noise;
  double occlusion_px = 0.06;  // a keypoint this close to a nearer body (times that body's pixel height) is occluded...
  double hidden = 0.7;         // ...and then hidden with this chance, else
  bool snap = true;            // detected on the occluder instead (a detector's typical confusion)
  double missed = 0.05;        // chance a person is not detected at all in a view
};

struct CrowdObservation {
  std::vector<std::vector<Person2D>> views;  // [view][person], shuffled
  std::vector<std::vector<int>> who;         // [view][person]: the index of the true person (-1: nobody's)
};

// One frame: truth[person] = keypoints in `layout` order (empty: not there this frame).
CrowdObservation observe_crowd(const Calibration& calib, const std::vector<std::vector<Eigen::Vector3d>>& truth,
                               LayoutId layout, const CrowdNoise& noise, std::mt19937& rng);

// A crowd take as a user's files: DIR/calibration.toml and DIR/keypoints/<camera>_json/NNNNNN.json (OpenPose), each
// view's people shuffled, no noise. Returns the truth (make_crowd's).
std::vector<std::vector<std::vector<Eigen::Vector3d>>> write_crowd_take(const Calibration& calib, size_t people,
                                                                        size_t frames, const std::string& dir,
                                                                        unsigned seed);

}  // namespace octocap::internal::synth
