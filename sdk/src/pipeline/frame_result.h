// Everything one solved frame yields. A local session produces it; a stream subscriber receives it; the C
// ABI's queries read it the same way from either.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/layout.h"
#include "rig/bone_solver.h"
#include "solve/observation.h"

namespace octocap {

struct FrameInfo {
  int64_t frame_index = -1;
  int64_t timestamp_us = 0;
  uint32_t keypoints_solved = 0;
  uint32_t keypoints_total = 0;
  double mean_reprojection_error_px = 0;
  uint32_t views_with_person = 0;
  double solve_ms = 0;
};

struct FrameResult {
  LayoutId layout = LayoutId::body25;
  FrameInfo info;
  std::vector<PointResult> keypoints;             // layout order, calibration world frame
  std::array<PointResult, kJointCount> joints{};  // the paper's skeleton, calibration world frame
  SkeletonPose bones{};                           // rig frame (Y up)
  std::vector<int> selected;                      // person per view, -1 none
  bool has_result() const { return info.frame_index >= 0; }
};

}  // namespace octocap
