// OpenPose JSON keypoints: one file per frame and camera, `people[].pose_keypoints_2d` = x, y, c triples.
#pragma once
#include <string>
#include <vector>

#include "core/layout.h"
#include "core/person2d.h"

namespace octocap::internal {

// Every person of one file. keypoint_count 0 accepts any count (all people must agree), else it is enforced.
// Throws Error(io / parse) naming the file.
std::vector<Person2D> read_openpose_file(const std::string& path, size_t keypoint_count);
// OpenPose's own JSON (version 1.3) with every person's keypoints, written to `path` (10 significant digits: what
// read_openpose_file() reads back is what was written). Throws Error(io).
void write_openpose_file(const std::string& path, const std::vector<Person2D>& people);

// A Pose2Sim-style folder: one sub-folder per camera (sorted by name), frames = files sorted by name.
class OpenPoseRecording {
 public:
  OpenPoseRecording(const std::string& directory, LayoutId layout);
  size_t view_count() const { return views_.size(); }
  size_t frame_count() const { return frame_count_; }
  LayoutId layout() const { return layout_; }
  const std::string& view_name(size_t v) const { return view_names_[v]; }
  // people[view] for one frame (with time offsets set: each view at its own fractional frame, interpolated).
  std::vector<std::vector<Person2D>> read_frame(size_t frame) const;
  // Camera v's frame i was captured at (i + offsets[v]) on the first camera's clock (octocap sync): reading frame f
  // then gives each view at its frame f - offsets[v], interpolated between its two nearest frames. Empty: none.
  void set_time_offsets(std::vector<double> offsets_frames);
  const std::vector<double>& time_offsets() const { return offsets_; }

 private:
  std::vector<std::vector<std::string>> views_;  // file paths per view
  std::vector<std::string> view_names_;
  size_t frame_count_ = 0;
  LayoutId layout_;
  std::vector<double> offsets_;
  std::vector<std::vector<Person2D>> read_raw(size_t frame) const;
};

}  // namespace octocap::internal
