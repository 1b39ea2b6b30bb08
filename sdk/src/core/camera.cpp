#include "core/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace octocap::internal {

std::string implausible_camera(const CameraValues& v) {
  const bool finite = std::isfinite(v.width) && std::isfinite(v.height) && v.matrix.allFinite() &&
                      std::all_of(v.distortion.begin(), v.distortion.end(), [](double d) { return std::isfinite(d); }) &&
                      v.rotation.allFinite() && v.translation.allFinite();
  if (!finite) return "a value is NaN or infinite";
  if (!(v.width >= 1 && v.height >= 1 && v.width <= 100000 && v.height <= 100000))
    return "size must be 1 to 100000 pixels each side";
  if (v.matrix(0, 0) <= 0 || v.matrix(1, 1) <= 0) return "a focal length is not > 0";
  if (v.rotation.norm() > 1000) return "rotation is not a rotation (a Rodrigues vector of at most 1000 radians)";
  if (v.translation.cwiseAbs().maxCoeff() > 1e6) return "translation is beyond a million metres";
  return "";
}

Camera camera_of(const CameraValues& v) {
  Camera cam;
  cam.name = v.name;
  cam.width = static_cast<int>(std::lround(v.width));
  cam.height = static_cast<int>(std::lround(v.height));
  cam.K = v.matrix;
  cam.dist = v.distortion;
  cam.fisheye = v.fisheye;
  cam.R = rodrigues_to_matrix(v.rotation);
  cam.t = v.translation;
  return cam;
}

bool Camera::has_distortion() const {
  for (double d : dist)
    if (d != 0.0) return true;
  return false;
}

Eigen::Vector2d Camera::distort(const Eigen::Vector2d& xn) const {
  const double x = xn.x(), y = xn.y();
  const double r2 = x * x + y * y;
  if (fisheye) {
    const double r = std::sqrt(r2);
    if (r < 1e-12) return xn;
    const double th = std::atan(r), th2 = th * th;
    const double thd = th * (1 + th2 * (dist[0] + th2 * (dist[1] + th2 * (dist[2] + th2 * dist[3]))));
    return xn * (thd / r);
  }
  const double k1 = dist[0], k2 = dist[1], p1 = dist[2], p2 = dist[3], k3 = dist[4];
  const double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
  return {x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x),
          y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y};
}

Eigen::Vector2d Camera::undistort(const Eigen::Vector2d& xd) const {
  if (!has_distortion()) return xd;
  Eigen::Vector2d x = xd;
  // Gauss-Newton on distort(x) = xd with a numeric Jacobian; converges in a few steps for real lenses.
  for (int it = 0; it < 20; ++it) {
    const Eigen::Vector2d f = distort(x) - xd;
    if (f.squaredNorm() < 1e-24) break;
    const double h = 1e-7;
    Eigen::Matrix2d J;
    J.col(0) = (distort(x + Eigen::Vector2d(h, 0)) - distort(x - Eigen::Vector2d(h, 0))) / (2 * h);
    J.col(1) = (distort(x + Eigen::Vector2d(0, h)) - distort(x - Eigen::Vector2d(0, h))) / (2 * h);
    const double det = J.determinant();
    if (!std::isfinite(det) || std::abs(det) < 1e-12) break;
    x -= J.inverse() * f;
  }
  return x;
}

Eigen::Vector2d Camera::project(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d c = to_camera(world);
  if (c.z() <= 1e-9) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
  }
  const Eigen::Vector2d xd = distort(Eigen::Vector2d(c.x() / c.z(), c.y() / c.z()));
  return {K(0, 0) * xd.x() + K(0, 1) * xd.y() + K(0, 2), K(1, 1) * xd.y() + K(1, 2)};
}

Eigen::Vector2d Camera::pixel_to_normalized(const Eigen::Vector2d& pixel) const {
  const double yd = (pixel.y() - K(1, 2)) / K(1, 1);
  const double xd = (pixel.x() - K(0, 2) - K(0, 1) * yd) / K(0, 0);
  return undistort({xd, yd});
}

Eigen::Vector3d Camera::pixel_to_world_ray(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d xn = pixel_to_normalized(pixel);
  return (R.transpose() * Eigen::Vector3d(xn.x(), xn.y(), 1.0)).normalized();
}

Eigen::Matrix3d rodrigues_to_matrix(const Eigen::Vector3d& r) {
  const double angle = r.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, r / angle).toRotationMatrix();
}

Eigen::Vector3d matrix_to_rodrigues(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.axis() * aa.angle();
}

std::string picture_mismatch(const Camera& cam, int width, int height) {
  if (cam.width <= 0 || cam.height <= 0 || width <= 0 || height <= 0) return "";
  const double sx = static_cast<double>(cam.width) / width, sy = static_cast<double>(cam.height) / height;
  if (std::abs(sx / sy - 1) <= 0.01) return "";
  return "its pictures are " + std::to_string(width) + "x" + std::to_string(height) + ", camera " + cam.name +
         " was calibrated at " + std::to_string(cam.width) + "x" + std::to_string(cam.height) +
         " (another aspect ratio: not the same picture; is it the camera the calibration means?)";
}

}  // namespace octocap::internal
