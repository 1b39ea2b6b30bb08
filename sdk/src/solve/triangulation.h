// Robust linear triangulation: confidence-weighted DLT with outlier-view rejection.
#pragma once
#include "solve/observation.h"

namespace octocap::internal {

struct TriangulationParams {
  int min_views = 2;
  double outlier_threshold_px = 15;
};

// DLT on all views, then, while the worst view reprojects farther than the threshold and more than
// min_views remain, drop the view whose removal leaves the smallest worst error.
PointResult solve_triangulation(const Calibration& calib, const std::vector<ViewRay>& rays,
                                const TriangulationParams& params);

}  // namespace octocap::internal
