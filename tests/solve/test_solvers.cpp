// The two 3D solvers on single points with known truth, and the hull test the paper states.
#include <catch2/catch_test_macros.hpp>
#include <random>

#include "solve/subdivision.h"
#include "solve/triangulation.h"
#include "solve/volume.h"
#include "synth.h"

using namespace octocap::internal;

namespace {

std::vector<ViewRay> rays_for(const Calibration& calib, const Eigen::Vector3d& X, double noise_px, std::mt19937& rng) {
  std::normal_distribution<double> g(0, noise_px);
  std::vector<ViewRay> rays;
  for (size_t v = 0; v < calib.size(); ++v) {
    const Eigen::Vector2d p = calib[v].project(X) + Eigen::Vector2d(g(rng), g(rng));
    rays.push_back(make_view_ray(calib[v], static_cast<int>(v), p, 0.9));
  }
  return rays;
}

SubdivisionParams params_for(const Calibration& calib) {
  SubdivisionParams p;
  p.sigma = static_cast<int>(calib.size()) - 1;
  p.volume = derive_capture_volume(calib);
  return p;
}

}  // namespace

TEST_CASE("the ray-meets-cube test is the paper's projected-hull test", "[solve][subdivision]") {
  const Calibration calib = synth::make_camera_ring({});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), size(0.01, 0.8);
  int inside = 0, outside = 0;
  for (int n = 0; n < 20000; ++n) {
    const Camera& cam = calib[n % calib.size()];
    const Eigen::Vector3d lo(u(rng), 1 + u(rng), u(rng));
    const Eigen::AlignedBox3d cube(lo, lo + Eigen::Vector3d::Constant(size(rng)));
    // Detections near the cube's image so both answers occur often.
    const Eigen::Vector2d px = cam.project(cube.center()) + Eigen::Vector2d(u(rng), u(rng)) * 150.0;
    const ViewRay ray = make_view_ray(cam, 0, px, 1);
    const bool hull = hull_contains_detection(cam, cube, ray.normalized);
    const bool slab = ray_meets_box(ray.origin, ray.direction.cwiseInverse(), cube.min(), cube.max(), 0);
    REQUIRE(hull == slab);
    (hull ? inside : outside)++;
  }
  REQUIRE(inside > 2000);
  REQUIRE(outside > 2000);
}

TEST_CASE("subdivision finds a point to within delta; triangulation to within noise", "[solve]") {
  const Calibration calib = synth::make_camera_ring({});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  SubdivisionParams sp = params_for(calib);
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d X(u(rng), 1 + u(rng), u(rng));
    const auto rays = rays_for(calib, X, 0.0, rng);
    const PointResult s = solve_subdivision(calib, rays, sp);
    REQUIRE(s.valid);
    REQUIRE((s.position - X).norm() < sp.delta);
    REQUIRE(s.views_used >= static_cast<uint32_t>(sp.sigma));
    const PointResult t = solve_triangulation(calib, rays, {});
    REQUIRE(t.valid);
    REQUIRE((t.position - X).norm() < 1e-6);
    REQUIRE(t.views_used == calib.size());
    REQUIRE(t.reprojection_error_px < 1e-3);
  }
}

TEST_CASE("a wrong detection in one view is out-voted by both methods", "[solve]") {
  const Calibration calib = synth::make_camera_ring({});
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  SubdivisionParams sp = params_for(calib);
  SECTION("sigma below the view count (the paper's robustness)") {}
  SECTION("sigma equal to the view count: retried with one view fewer") { sp.sigma = static_cast<int>(calib.size()); }
  for (int n = 0; n < 100; ++n) {
    const Eigen::Vector3d X(u(rng), 1 + u(rng), u(rng));
    auto rays = rays_for(calib, X, 1.0, rng);
    const int bad = n % static_cast<int>(calib.size());
    rays[bad] = make_view_ray(calib[bad], bad, calib[bad].project(X) + Eigen::Vector2d(120, -90), 0.95);
    const PointResult s = solve_subdivision(calib, rays, sp);
    REQUIRE(s.valid);
    REQUIRE((s.position - X).norm() < 0.02);
    REQUIRE_FALSE((s.view_mask >> bad & 1u));
    const PointResult t = solve_triangulation(calib, rays, {});
    REQUIRE(t.valid);
    REQUIRE((t.position - X).norm() < 0.02);
    REQUIRE(t.views_used == calib.size() - 1);
  }
}

TEST_CASE("too few views, or views that disagree, give a missing point, not a guess", "[solve]") {
  const Calibration calib = synth::make_camera_ring({});
  std::mt19937 rng(9);
  const Eigen::Vector3d X(0.1, 1.2, -0.2);
  auto rays = rays_for(calib, X, 0.5, rng);
  const SubdivisionParams sp = params_for(calib);
  REQUIRE_FALSE(solve_subdivision(calib, {rays[0]}, sp).valid);
  REQUIRE_FALSE(solve_triangulation(calib, {rays[0]}, {}).valid);
  // Every view sees something different: no cube is supported by two views at a consistent place.
  std::vector<ViewRay> scattered;
  for (size_t v = 0; v < calib.size(); ++v)
    scattered.push_back(make_view_ray(calib[v], static_cast<int>(v),
                                      {50.0 + 250.0 * v, 40.0 + 130.0 * v}, 0.9));
  TriangulationParams tp;
  tp.min_views = 3;
  REQUIRE_FALSE(solve_triangulation(calib, scattered, tp).valid);
  SubdivisionParams strict = sp;
  strict.min_views = 3;
  REQUIRE_FALSE(solve_subdivision(calib, scattered, strict).valid);
}

TEST_CASE("the derived capture volume holds the filmed space", "[solve]") {
  const Calibration calib = synth::make_camera_ring({});
  const Eigen::AlignedBox3d v = derive_capture_volume(calib);
  REQUIRE_FALSE(v.isEmpty());
  // A person standing anywhere within 1 m of the centre, feet to head, is inside.
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 1), Eigen::Vector3d(-1, 0, -1)})
    REQUIRE(v.contains(p));
  REQUIRE(v.sizes().maxCoeff() < 25.0);
}
