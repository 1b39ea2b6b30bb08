// Everything one solved frame yields: a session produces it, a stream subscriber receives it, a motion file plays
// it; the C ABI's frame handle reads it the same way from each. Plain data, so every stage may hold one.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/layout.h"
#include "core/skeleton.h"

namespace octocap::internal {

struct PointResult {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  bool valid = false;
  double confidence = 0;
  double reprojection_error_px = 0;
  uint32_t views_used = 0;
  uint64_t view_mask = 0;  // bit v set when view v supported the point
};

struct BonePose {
  Eigen::Quaterniond local = Eigen::Quaterniond::Identity();   // relative to the parent bone
  Eigen::Quaterniond global = Eigen::Quaterniond::Identity();  // rig frame, from the T-pose
  Eigen::Vector3d head = Eigen::Vector3d::Zero();              // rig frame, metres
  double length = 0;
  bool valid = false;
};

using SkeletonPose = std::array<BonePose, kBoneCount>;

struct FrameInfo {
  int64_t frame_index = -1;
  int64_t timestamp_us = 0;
  uint32_t keypoints_solved = 0;
  uint32_t keypoints_total = 0;
  double mean_reprojection_error_px = 0;
  uint32_t views_with_person = 0;
  double solve_ms = 0;
};

// One person of a frame: what the C ABI's per-person queries read.
struct PersonResult {
  uint32_t id = 1;                                // stable within its source while tracked; never 0
  std::vector<PointResult> keypoints;             // layout order, calibration world frame
  std::array<PointResult, kJointCount> joints{};  // the paper's skeleton, calibration world frame
  SkeletonPose bones{};                           // rig frame (Y up)
  std::vector<int> selected;                      // per view, the 2D person (index in the solve's input); -1 none
  uint32_t keypoints_solved = 0;
  uint32_t views_with_person = 0;
  double mean_reprojection_error_px = 0;
  std::array<bool, 2> foot_contact{};  // right, left: planted this frame (rig/foot_lock.h)
  bool has_pose() const {
    for (const PointResult& p : keypoints) if (p.valid) return true;
    for (const PointResult& p : joints) if (p.valid) return true;
    return false;
  }
};

struct FrameResult {
  LayoutId layout = LayoutId::body25;
  FrameInfo info;                                 // the frame as a whole (all people)
  std::vector<PersonResult> people;               // the people solved, in increasing id order
  // What a query of person 0 reads when nobody was solved (the 0.x per-source queries allow it): every point
  // missing, each view's selection as the solve made it.
  PersonResult blank;
  uint32_t view_count = 0;                        // views given to the solve (0: not from a solve)
  uint32_t source_id = 0;                         // the publisher's id for received frames, 0 local
  uint32_t definition_counter = 0;                // see next_definition_counter()
  bool rig_frame_joints = false;                  // joints/keypoints in the rig frame (motion files)
  bool has_result() const { return info.frame_index >= 0; }
  size_t person_count() const { return people.size(); }
  bool has_person() const { return !people.empty(); }
  size_t keypoint_count() const { return blank.keypoints.size(); }
  const PersonResult& person_or_blank(size_t i) const { return i < people.size() ? people[i] : blank; }
};

// A process-wide, never-0, ever-increasing number: each source takes a new one whenever its skeleton definition
// (layout, bone table) is or may be new, so a consumer that reads frames of several sources notices every change.
uint32_t next_definition_counter();

}  // namespace octocap::internal
