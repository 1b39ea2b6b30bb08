// Time offsets of unsynchronised cameras, from the person's own motion: with a calibration, the offset at which the
// views agree is the true one. Every pair of cameras measures its offset difference (the median epipolar distance of
// the best-agreeing pair of people per frame, at whole frames, refined by a symmetric V fit); cameras are placed one
// by one against the placed camera they agree with best, then all consistent pairs fix the offsets together by
// weighted least squares. All keypoints count, so it works whether or not the person moves vertically (Pose2Sim's
// speed correlation needs vertical motion).
#pragma once
#include <vector>

#include "core/camera.h"
#include "core/person2d.h"
#include "io/openpose_json.h"

namespace octocap::internal {

struct SyncOptions {
  double max_offset_frames = 120;  // searched on either side
  double min_confidence = 0.3;
};

struct SyncEstimate {
  // Camera c's frame i was captured at (i + offset[c]) / rate on the first camera's clock; offset[0] = 0.
  std::vector<double> offset_frames;
  std::vector<double> residual_px;  // median epipolar distance at the chosen offset (0 for the first camera)
};

// frames[f][v]: the people of view v at frame f, in one layout (bystanders welcome: per frame the pair of people
// that agrees best counts). Throws Error(invalid_argument) for view counts that differ from the calibration,
// Error(not_enough_views) when a camera never shares enough confident keypoints with the first to be placed in time.
SyncEstimate estimate_time_offsets(const Calibration& calib,
                                   const std::vector<std::vector<std::vector<Person2D>>>& frames,
                                   const SyncOptions& options);

// The same for a recording, as it is on disk (its own time offsets ignored).
SyncEstimate estimate_recording_offsets(const Calibration& calib, const OpenPoseRecording& recording,
                                        const SyncOptions& options);

}  // namespace octocap::internal
