#include "io/calibration_yaml.h"

#include <opencv2/core.hpp>

#include "core/error.h"

namespace octocap::internal {

void write_calibration_opencv_yaml(const Calibration& calib, const std::string& path) {
  cv::FileStorage fs;
  try {
    fs.open(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw Error(Errc::io, path + ": cannot open for writing: " + e.what());
  }
  if (!fs.isOpened()) throw Error(Errc::io, path + ": cannot open for writing");
  fs << "camera_count" << static_cast<int>(calib.size());
  for (size_t i = 0; i < calib.size(); ++i) {
    const Camera& c = calib[i];
    cv::Mat K(3, 3, CV_64F), R(3, 3, CV_64F), d(1, c.fisheye ? 4 : 5, CV_64F), r(3, 1, CV_64F), t(3, 1, CV_64F);
    for (int k = 0; k < 9; ++k) {
      K.at<double>(k / 3, k % 3) = c.K(k / 3, k % 3);
      R.at<double>(k / 3, k % 3) = c.R(k / 3, k % 3);
    }
    for (int k = 0; k < d.cols; ++k) d.at<double>(k) = c.dist[k];
    const Eigen::Vector3d rv = matrix_to_rodrigues(c.R);
    for (int k = 0; k < 3; ++k) {
      r.at<double>(k) = rv[k];
      t.at<double>(k) = c.t[k];
    }
    fs << ("cam_" + std::to_string(i + 1)) << "{";
    fs << "name" << c.name << "image_width" << c.width << "image_height" << c.height;
    fs << "camera_matrix" << K << "distortion_coefficients" << d << "fisheye" << (c.fisheye ? 1 : 0);
    fs << "rvec" << r << "rotation_matrix" << R << "tvec" << t;
    fs << "}";
  }
  fs.release();
}

}  // namespace octocap::internal
