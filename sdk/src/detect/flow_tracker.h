// Keypoints followed from one picture of a view to the next by pyramidal Lucas-Kanade optical flow: what a view that
// is not detected this frame reports (detection scheduling, DetectorConfig::views_per_frame). A network costs tens of
// milliseconds a view on a CPU; flow on a downscaled grey picture costs about one. Each point is tracked forward and
// back again, and kept only when it comes back near where it started (a point on a limb that the flow slid off, onto the
// background or the other limb, does not), so a lost keypoint is dropped rather than reported wrong.
#pragma once
#include <memory>
#include <vector>

#include "detect/decoders.h"
#include "detect/image.h"

namespace octocap::internal {

class FlowTracker {
 public:
  FlowTracker();
  ~FlowTracker();
  FlowTracker(FlowTracker&&) noexcept;
  FlowTracker& operator=(FlowTracker&&) noexcept;

  // This frame's picture of the view (grey, halved until its longer side is at most 1.4 kTrackSide). Call it every
  // frame the view has a picture, detected or not: the next frame's flow starts from it.
  void advance(const ImageView& view);
  // No picture this frame (the camera dropped one): the next frame cannot be tracked from here.
  void reset();
  // Whether the last two pictures can be tracked between (both there, the same size).
  bool ready() const;
  // Whether `next`, once advanced to, could be tracked into from the current picture.
  bool follows(const ImageView& next) const;
  // `people` (keypoints in the previous picture's view pixels) moved into the current one. Keypoints that do not come
  // back within kBackError tracked pixels, or that leave the picture, keep their place with confidence 0. Tracked
  // keypoints keep their detection's confidence: lowering it each frame (x0.5) measured worse (42 mm from Pose2Sim's
  // 3D instead of 39), the fresh view alone then deciding depth.
  std::vector<DetectedPerson> track(const std::vector<DetectedPerson>& people, double min_confidence) const;

  // Measured on Pose2Sim's real take (octocap_bench_detect --accuracy followed; 1088x1920, two views of four detected
  // a frame): tracked at 960 px with a 21 px window, face points (small, on the head's edge) were lost in most tracks
  // and 95.5 % of keypoints solved; at 1920 px fewer still; at 480 px 98.2-99.4 % for windows of 11 to 31 px (15:
  // 99.2 %, 37 mm from Pose2Sim's 3D), the window then covering a body part's texture rather than a few pixels of
  // it. The way back is allowed 3 px there (12 view pixels): a point that slid is off by far more, and the 3D
  // solve's outlier-view test catches what passes; 5 px measured the same.
  static constexpr int kTrackSide = 480;
  static constexpr int kWindow = 15;
  static constexpr double kBackError = 3;

 private:
  struct Pictures;  // OpenCV's, kept out of this header (the C ABI layer includes it and builds without OpenCV)
  std::unique_ptr<Pictures> pictures_;
};

}  // namespace octocap::internal
