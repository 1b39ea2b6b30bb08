// Pinhole camera with OpenCV's distortion models (standard k1,k2,p1,p2,k3 and fisheye k1..k4).
#pragma once
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace octocap::internal {

// A camera's values as a calibration file or a caller gives them, before they become a Camera.
struct CameraValues {
  std::string name;
  bool fisheye = false;
  double width = 0, height = 0;                        // pixels
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Identity();  // K
  std::array<double, 5> distortion{};
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();     // Rodrigues, world -> camera
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // metres
};

// Why these values cannot be a camera ("" when they can): a value NaN or infinite, a size of 0 or beyond 100000
// pixels a side, a focal length <= 0, a rotation vector longer than 1000 radians (its angle's last digits are gone:
// noise, not a rotation), a translation beyond a million metres. The one rule for every camera that comes in (the
// calibration TOML, the C ABI).
std::string implausible_camera(const CameraValues& v);

struct Camera;

// The camera of values implausible_camera() accepts (the size rounded to whole pixels).
Camera camera_of(const CameraValues& v);

// Why a picture of `width` x `height` cannot be this camera's ("" when it can): the same picture at another size (a
// preview stream, a downscaled render) is fine, another aspect ratio is another picture, or another camera. The one
// rule the offline solve and the live engine both apply.
std::string picture_mismatch(const Camera& cam, int width, int height);

struct Camera {
  std::string name;
  int width = 0;
  int height = 0;
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  // Standard model: k1, k2, p1, p2, k3. Fisheye model: k1, k2, k3, k4 (index 4 unused).
  std::array<double, 5> dist{};
  bool fisheye = false;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // world -> camera
  Eigen::Vector3d t = Eigen::Vector3d::Zero();      // world -> camera, metres

  Eigen::Vector3d center() const { return -R.transpose() * t; }
  Eigen::Vector3d to_camera(const Eigen::Vector3d& world) const { return R * world + t; }

  // Undistorted normalised image coordinates -> distorted normalised coordinates.
  Eigen::Vector2d distort(const Eigen::Vector2d& xn) const;
  // Inverse of distort(), by Gauss-Newton (robust where OpenCV's fixed-point iteration diverges).
  Eigen::Vector2d undistort(const Eigen::Vector2d& xd) const;

  // World point -> pixel, with distortion. Points behind the camera give NaN.
  Eigen::Vector2d project(const Eigen::Vector3d& world) const;
  // Pixel -> undistorted normalised coordinates (z = 1 ray in the camera frame).
  Eigen::Vector2d pixel_to_normalized(const Eigen::Vector2d& pixel) const;
  // Pixel -> unit ray direction in the world frame.
  Eigen::Vector3d pixel_to_world_ray(const Eigen::Vector2d& pixel) const;
  // Pixels per metre at a given depth (for converting a pixel tolerance into a metric one).
  double focal() const { return 0.5 * (K(0, 0) + K(1, 1)); }
  bool has_distortion() const;
};

using Calibration = std::vector<Camera>;

// Rodrigues vector <-> rotation matrix.
Eigen::Matrix3d rodrigues_to_matrix(const Eigen::Vector3d& r);
Eigen::Vector3d matrix_to_rodrigues(const Eigen::Matrix3d& R);

}  // namespace octocap::internal
