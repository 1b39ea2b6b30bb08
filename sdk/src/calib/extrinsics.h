// Stage 1b: every camera's pose from a person walking through the volume (2D body keypoints as the common
// points): pairwise essential matrix for the first pair, cameras added by PnP, then bundle adjustment
// (Ceres); scale from the person's height or a known camera distance; world frame from the floor contact
// and the person's up direction.
#pragma once
#include <string>
#include <vector>

#include "calib/bundle_adjustment.h"
#include "core/camera.h"
#include "core/layout.h"
#include "io/openpose_json.h"

namespace octocap::internal {

struct ExtrinsicsOptions {
  double person_height_m = 0;  // scale from the person's height (anthropometric keypoint path), or
  int distance_camera_a = -1, distance_camera_b = -1;  // scale from a measured distance between two cameras
  double camera_distance_m = 0;
  double min_confidence = 0.4;
  size_t max_frames = 1500;    // frames beyond this are subsampled evenly
  bool z_up = false;           // output world frame: Y up (octocap) or Z up
  // Refine an existing calibration (a camera was nudged): start from the given poses, bundle-adjust, and keep
  // the original world frame and scale (no height or distance needed).
  bool refine = false;
};

struct ExtrinsicsReport {
  std::vector<double> rms_px;          // per camera, after bundle adjustment
  std::vector<size_t> observations;    // per camera, inliers used
  size_t points = 0;
  int iterations = 0;
  double initial_rms_px = 0, final_rms_px = 0;
};

// Fills `report` (when not null) from the fit: per-camera RMS and count of `observations` against
// `world_points` (the points in the output world frame), and the bundle adjustment passes' figures (pass the
// same BaResult twice for a single-pass fit).
void fill_extrinsics_report(const Calibration& calib, const std::vector<Eigen::Vector3d>& world_points,
                            const std::vector<BaObservation>& observations, size_t point_count,
                            const BaResult& first_pass, const BaResult& last_pass, ExtrinsicsReport* report);

// frames[f][view] = the people seen; the most prominent person per view is used. Intrinsics come from
// `intrinsics` (its poses are ignored). Throws Error with a clear message on too few views, disconnected
// camera groups (named), degenerate motion and a missing scale.
Calibration calibrate_extrinsics(const Calibration& intrinsics,
                                 const std::vector<std::vector<std::vector<Person2D>>>& frames, LayoutId layout,
                                 const ExtrinsicsOptions& options, ExtrinsicsReport* report);

// Anthropometric ratio: the keypoint path ankle-knee-hip-neck-head is this fraction of standing height
// (Drillis & Contini segment heights: 0.039, 0.285, 0.530, 0.818, ~0.93 of H).
constexpr double kKeypointPathOfHeight = 0.89;

}  // namespace octocap::internal
