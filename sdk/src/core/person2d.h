// The central 2D type: one person's keypoints in one view, in a layout's order. Detectors produce it, file
// readers parse it, the solve consumes it.
#pragma once
#include <vector>

namespace octocap::internal {

struct Keypoint2D {
  double x = 0, y = 0, confidence = 0;  // image pixels; confidence 0 = not detected
};
using Person2D = std::vector<Keypoint2D>;

}  // namespace octocap::internal

namespace octocap::internal {

// A person between two frames of one view (w in [0, 1]): linear where both frames have the keypoint confidently,
// else the nearer frame's keypoint.
Person2D interpolate_person(const Person2D& a, const Person2D& b, double w, double min_confidence);

}  // namespace octocap::internal
