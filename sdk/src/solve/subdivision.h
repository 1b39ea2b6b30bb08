// The paper's 3D joint estimate: iterative space subdivision (METHOD.md, stage 3).
#pragma once
#include <Eigen/Geometry>
#include <vector>

#include "solve/observation.h"

namespace octocap::internal {

struct SubdivisionParams {
  int sigma = 0;             // supporting views a cube needs (already resolved from the config)
  int min_views = 2;
  double delta = 0.01;       // stop once a cube's edge is below this, metres
  double pixel_tolerance = 4;
  int max_candidates = 8;    // candidate cubes kept per level
  double max_reprojection_error_px = 15;  // a result its own views disagree with is retried with fewer views
  Eigen::AlignedBox3d volume;
};

// Support test of one cube for one view: does the detection lie in the convex hull of the cube's 8
// projected corners? Checked as "does the detection's viewing ray meet the cube", which is the same
// statement for a cube in front of the camera (a convex body projects onto the hull of its projected
// corners), costs one slab test instead of 8 projections and a hull, and stays right when the camera sits
// inside the volume. `margin` widens the cube by a metric tolerance.
bool ray_meets_box(const Eigen::Vector3d& origin, const Eigen::Vector3d& inv_dir, const Eigen::Vector3d& lo,
                   const Eigen::Vector3d& hi, double margin);

// The literal test of the paper (projected corners, convex hull, point in polygon) in undistorted
// normalised coordinates. Slower; kept to check ray_meets_box against and for benchmarks.
bool hull_contains_detection(const Camera& cam, const Eigen::AlignedBox3d& cube, const Eigen::Vector2d& normalized);

PointResult solve_subdivision(const Calibration& calib, const std::vector<ViewRay>& rays,
                              const SubdivisionParams& params);

}  // namespace octocap::internal
