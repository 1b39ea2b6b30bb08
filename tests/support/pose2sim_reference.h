// Scoring solved keypoints of Pose2Sim's demo take against Pose2Sim's own 3D (its output, not ground truth):
// the reference TRC (Y up) matched to a layout's keypoints by name, our Z-up world turned as Pose2Sim turns it.
// Shared by the real-data tests and the detection benchmark.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/axes.h"
#include "io/motion_files.h"
#include "octocap/octocap.h"

namespace testing {

class Pose2SimReference {
 public:
  Pose2SimReference(const std::string& trc_path, octocap_layout_t layout)
      : reference_(octocap::internal::read_trc(trc_path)), index_(octocap_layout_keypoint_count(layout), -1) {
    for (size_t k = 0; k < index_.size(); ++k)
      for (size_t m = 0; m < reference_.markers.size(); ++m)
        if (reference_.markers[m] == octocap_layout_keypoint_name(layout, static_cast<uint32_t>(k)))
          index_[k] = static_cast<int>(m);
  }

  // One solved frame: `keypoints` holds the layout's keypoints in the calibration world (Z up).
  void add(size_t frame, const octocap_joint_t* keypoints) {
    for (size_t k = 0; k < index_.size(); ++k) {
      const octocap_joint_t& j = keypoints[k];
      if (!j.valid) continue;
      ++solved;
      reprojection_px.push_back(j.reprojection_error_px);
      if (index_[k] < 0 || frame >= reference_.frames.size()) continue;
      const Eigen::Vector3d ours = octocap::internal::zup_to_yup({j.position[0], j.position[1], j.position[2]});
      const Eigen::Vector3d theirs = reference_.frames[frame][index_[k]];
      if (theirs.allFinite()) distance_m.push_back((ours - theirs).norm());
    }
  }

  size_t solved = 0;
  std::vector<double> reprojection_px, distance_m;

 private:
  octocap::internal::MotionTrack reference_;
  std::vector<int> index_;
};

}  // namespace testing
