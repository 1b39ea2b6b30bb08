// A take written to disk frame by frame: TRC / CSV of the layout keypoints, or BVH of the bone animation.
// Nothing is written until close() (TRC's header needs the frame count); a failed take is simply dropped.
#pragma once
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/layout.h"
#include "io/motion_files.h"

namespace octocap {

enum class MotionFormat : int { trc = 0, csv = 1, bvh = 2, csv_people = 3 };

class MotionWriter {
 public:
  // Throws Error(invalid_argument) for a rate that is not a positive, finite, sane frame rate.
  MotionWriter(std::string path, MotionFormat format, LayoutId layout, bool z_up, double rate_hz);
  // The person's keypoints (and bones); a frame without that person is an empty frame (csv_people: no row).
  // Throws when the frame's layout is not the writer's.
  void add(const FrameResult& frame, size_t person);
  // Layout keypoints given directly (NaN where missing); not for BVH.
  void add_keypoints(const std::vector<Eigen::Vector3d>& keypoints);
  void add_empty();
  void close() const;
  MotionFormat format() const { return format_; }
  size_t keypoint_count() const { return track_.markers.size(); }

 private:
  void add_person(const PersonResult& person, int64_t frame_index);

  std::string path_;
  MotionFormat format_;
  LayoutId layout_;
  bool z_up_;
  MotionTrack track_;
  std::vector<SkeletonPose> poses_;  // BVH
};

}  // namespace octocap
