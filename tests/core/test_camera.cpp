// The camera model against OpenCV's own implementation of the same models.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <opencv2/calib3d.hpp>
#include <random>

#include "core/camera.h"
#include "synth.h"

using namespace octocap::internal;

namespace {

cv::Mat K_of(const Camera& c) {
  cv::Mat K(3, 3, CV_64F);
  for (int i = 0; i < 9; ++i) K.at<double>(i / 3, i % 3) = c.K(i / 3, i % 3);
  return K;
}

}  // namespace

TEST_CASE("projection with distortion matches cv::projectPoints", "[camera]") {
  const Calibration calib = synth::make_camera_ring({});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const Camera& cam : calib) {
    cv::Mat rvec(3, 1, CV_64F), tvec(3, 1, CV_64F), dist(1, 5, CV_64F);
    const Eigen::Vector3d r = matrix_to_rodrigues(cam.R);
    for (int i = 0; i < 3; ++i) {
      rvec.at<double>(i) = r[i];
      tvec.at<double>(i) = cam.t[i];
    }
    for (int i = 0; i < 5; ++i) dist.at<double>(i) = cam.dist[i];
    std::vector<cv::Point3d> pts;
    for (int n = 0; n < 200; ++n) pts.emplace_back(u(rng), 1 + u(rng), u(rng));
    std::vector<cv::Point2d> ref;
    cv::projectPoints(pts, rvec, tvec, K_of(cam), dist, ref);
    for (size_t n = 0; n < pts.size(); ++n) {
      const Eigen::Vector2d p = cam.project({pts[n].x, pts[n].y, pts[n].z});
      REQUIRE(p.x() == Catch::Approx(ref[n].x).margin(1e-6));
      REQUIRE(p.y() == Catch::Approx(ref[n].y).margin(1e-6));
    }
  }
}

TEST_CASE("fisheye projection matches cv::fisheye::projectPoints", "[camera]") {
  Camera cam;
  cam.width = 1280;
  cam.height = 960;
  cam.K << 400, 0, 640, 0, 401, 480, 0, 0, 1;
  cam.fisheye = true;
  cam.dist = {0.05, -0.01, 0.002, -0.0005, 0};
  cam.R = rodrigues_to_matrix({0.1, -0.2, 0.05});
  cam.t = {0.1, 0.2, 2.0};
  cv::Mat rvec = (cv::Mat_<double>(3, 1) << 0.1, -0.2, 0.05), tvec = (cv::Mat_<double>(3, 1) << 0.1, 0.2, 2.0);
  cv::Mat D = (cv::Mat_<double>(4, 1) << 0.05, -0.01, 0.002, -0.0005);
  std::vector<cv::Point3d> pts = {{0, 0, 0}, {1, 0.5, 0.2}, {-1.5, 1, 0.5}, {0.3, -0.8, -0.4}};
  std::vector<cv::Point2d> ref;
  cv::fisheye::projectPoints(pts, ref, rvec, tvec, K_of(cam), D);
  for (size_t n = 0; n < pts.size(); ++n) {
    const Eigen::Vector2d p = cam.project({pts[n].x, pts[n].y, pts[n].z});
    CHECK(p.x() == Catch::Approx(ref[n].x).margin(1e-6));
    CHECK(p.y() == Catch::Approx(ref[n].y).margin(1e-6));
  }
}

TEST_CASE("undistortion inverts distortion across the image, like cv::undistortPoints", "[camera]") {
  const Camera cam = synth::make_camera_ring({}).front();
  cv::Mat dist(1, 5, CV_64F);
  for (int i = 0; i < 5; ++i) dist.at<double>(i) = cam.dist[i];
  std::vector<cv::Point2d> px;
  for (int x = 0; x <= cam.width; x += 160)
    for (int y = 0; y <= cam.height; y += 120) px.emplace_back(x, y);
  std::vector<cv::Point2d> ref;
  cv::undistortPoints(px, ref, K_of(cam), dist, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-14));
  for (size_t n = 0; n < px.size(); ++n) {
    const Eigen::Vector2d xn = cam.pixel_to_normalized({px[n].x, px[n].y});
    // Round trip to the pixel is exact; OpenCV's fixed-point answer agrees to well under a pixel.
    const Eigen::Vector2d back = cam.project(cam.R.transpose() * (Eigen::Vector3d(xn.x(), xn.y(), 1) - cam.t));
    REQUIRE((back - Eigen::Vector2d(px[n].x, px[n].y)).norm() < 1e-6);
    REQUIRE(std::abs(xn.x() - ref[n].x) * cam.K(0, 0) < 0.05);
    REQUIRE(std::abs(xn.y() - ref[n].y) * cam.K(1, 1) < 0.05);
  }
}

TEST_CASE("Rodrigues conversion matches cv::Rodrigues and round-trips", "[camera]") {
  for (const Eigen::Vector3d& r : {Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(1.6882, 1.0483, -0.4196),
                                  Eigen::Vector3d(0, 0, 3.0), Eigen::Vector3d(0, 0, 0)}) {
    cv::Mat rv = (cv::Mat_<double>(3, 1) << r.x(), r.y(), r.z()), R;
    cv::Rodrigues(rv, R);
    const Eigen::Matrix3d M = rodrigues_to_matrix(r);
    for (int i = 0; i < 9; ++i) REQUIRE(M(i / 3, i % 3) == Catch::Approx(R.at<double>(i / 3, i % 3)).margin(1e-12));
    REQUIRE((matrix_to_rodrigues(M) - r).norm() < 1e-9);
  }
}

TEST_CASE("a point behind the camera does not project", "[camera]") {
  const Camera cam = synth::make_camera_ring({}).front();
  const Eigen::Vector3d behind = cam.center() - 2.0 * (cam.R.transpose() * Eigen::Vector3d::UnitZ());
  REQUIRE_FALSE(cam.project(behind).allFinite());
}
