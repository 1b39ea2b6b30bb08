#include "calib/board_extrinsics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>

#include "calib/bundle_adjustment.h"
#include "core/error.h"
#include "core/log.h"
#include "io/directories.h"

namespace fs = std::filesystem;

namespace octocap::internal {
namespace {

Eigen::Vector3d board_point(const BoardSpec& b, int i) {
  return {(i % b.cols) * b.square_m, (i / b.cols) * b.square_m, 0.0};
}

// Board -> camera pose by PnP on undistorted normalised corners.
bool board_pose(const Camera& cam, const BoardSpec& b, const std::vector<Eigen::Vector2d>& px, Eigen::Matrix3d& R,
                Eigen::Vector3d& t) {
  std::vector<cv::Point3d> obj;
  std::vector<cv::Point2d> img;
  for (size_t i = 0; i < px.size(); ++i) {
    const Eigen::Vector3d p = board_point(b, static_cast<int>(i));
    obj.emplace_back(p.x(), p.y(), p.z());
    const Eigen::Vector2d n = cam.pixel_to_normalized(px[i]);
    img.emplace_back(n.x(), n.y());
  }
  cv::Mat rvec, tvec;
  if (!cv::solvePnP(obj, img, cv::Mat::eye(3, 3, CV_64F), cv::noArray(), rvec, tvec, false, cv::SOLVEPNP_IPPE))
    return false;
  R = rodrigues_to_matrix({rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2)});
  t = {tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2)};
  return true;
}

}  // namespace

Calibration calibrate_extrinsics_from_boards(const Calibration& intrinsics, const BoardViews& corners,
                                             const BoardSpec& board, bool z_up, ExtrinsicsReport* report) {
  const int V = static_cast<int>(intrinsics.size());
  const size_t N = static_cast<size_t>(board.cols * board.rows);
  if (V < 2) throw Error(Errc::not_enough_views, "extrinsics need at least 2 cameras");
  // Board pose in every camera that saw it whole.
  struct Pose {
    bool ok = false;
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
  };
  std::vector<std::vector<Pose>> pose(corners.size(), std::vector<Pose>(V));
  for (size_t s = 0; s < corners.size(); ++s)
    for (int v = 0; v < V && v < static_cast<int>(corners[s].size()); ++v)
      if (corners[s][v].size() == N) pose[s][v].ok = board_pose(intrinsics[v], board, corners[s][v], pose[s][v].R, pose[s][v].t);

  // Layout by breadth-first search over "saw the same board" from the camera of the first full view.
  int first_set = -1, root = -1;
  for (size_t s = 0; s < pose.size() && first_set < 0; ++s)
    for (int v = 0; v < V; ++v)
      if (pose[s][v].ok) {
        first_set = static_cast<int>(s);
        root = v;
        break;
      }
  if (first_set < 0) throw Error(Errc::not_enough_views, "no camera saw the whole board in any image set");
  // World = the first set's board frame. Camera v: X_cam = R_v X_world + t_v.
  Calibration calib = intrinsics;
  std::vector<bool> placed(V, false);
  std::vector<Eigen::Matrix3d> board_R(pose.size());
  std::vector<Eigen::Vector3d> board_t(pose.size());  // board s -> world
  std::vector<bool> board_known(pose.size(), false);
  calib[root].R = pose[first_set][root].R;
  calib[root].t = pose[first_set][root].t;
  placed[root] = true;
  for (bool grew = true; grew;) {
    grew = false;
    for (size_t s = 0; s < pose.size(); ++s) {
      if (!board_known[s])
        for (int v = 0; v < V; ++v)
          if (placed[v] && pose[s][v].ok) {
            // X_cam = R_v (Rb X_board + tb) + t_v = pose  ->  Rb = R_v^T R_p, tb = R_v^T (t_p - t_v)
            board_R[s] = calib[v].R.transpose() * pose[s][v].R;
            board_t[s] = calib[v].R.transpose() * (pose[s][v].t - calib[v].t);
            board_known[s] = grew = true;
            break;
          }
      if (!board_known[s]) continue;
      for (int v = 0; v < V; ++v)
        if (!placed[v] && pose[s][v].ok) {
          // pose: X_cam = R_p X_board + t_p, X_board = Rb^T (X_world - tb)
          calib[v].R = pose[s][v].R * board_R[s].transpose();
          calib[v].t = pose[s][v].t - calib[v].R * board_t[s];
          placed[v] = grew = true;
        }
    }
  }
  std::vector<int> missing;
  for (int v = 0; v < V; ++v)
    if (!placed[v]) missing.push_back(v);
  if (!missing.empty()) {
    std::string names;
    for (int v : missing) names += (names.empty() ? "" : ", ") + intrinsics[v].name;
    throw Error(Errc::not_enough_views, "cameras " + names + " never saw the whole board together with the others");
  }

  // Bundle adjustment over cameras and corners (corners free: a board is never perfectly flat).
  std::vector<Eigen::Vector3d> points;
  std::vector<BaObservation> obs;
  for (size_t s = 0; s < pose.size(); ++s) {
    if (!board_known[s]) continue;
    const int base = static_cast<int>(points.size());
    for (size_t i = 0; i < N; ++i) points.push_back(board_R[s] * board_point(board, static_cast<int>(i)) + board_t[s]);
    for (int v = 0; v < V; ++v)
      if (pose[s][v].ok)
        for (size_t i = 0; i < N; ++i) obs.push_back({v, base + static_cast<int>(i), corners[s][v][i]});
  }
  std::vector<bool> adjust(V, true);
  const BaResult r = bundle_adjust(calib, adjust, root, points, obs, 1.0, 100);
  // The board's square size fixes the scale that bundle adjustment leaves free.
  double measured = 0;
  int pairs = 0;
  for (size_t base = 0; base + N <= points.size(); base += N)
    for (size_t i = 0; i + 1 < N; ++i)
      if ((i + 1) % board.cols != 0) measured += (points[base + i + 1] - points[base + i]).norm(), ++pairs;
  const double scale = board.square_m / (measured / pairs);
  // World axes: board X, board Y; up = board normal (Z of the board frame), flipped toward the cameras.
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d toward = Eigen::Vector3d::Zero();
  for (const Camera& c : calib) toward += c.center();
  if (up.dot(toward) < 0) up = -up;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  Eigen::Matrix3d Q;  // rows: world axes in the board frame
  if (z_up) {
    Q.row(0) = x;
    Q.row(2) = up;
    Q.row(1) = up.cross(x);
  } else {
    Q.row(0) = x;
    Q.row(1) = up;
    Q.row(2) = x.cross(up);
  }
  for (Camera& c : calib) {
    c.R = c.R * Q.transpose();
    c.t = scale * c.t;
  }
  std::vector<Eigen::Vector3d> world(points.size());
  for (size_t p = 0; p < points.size(); ++p) world[p] = scale * Q * points[p];
  fill_extrinsics_report(calib, world, obs, points.size(), r, r, report);
  return calib;
}

BoardViews detect_board_views(const std::string& directory, size_t cameras, const BoardSpec& board) {
  std::error_code ec;
  const std::vector<fs::path> dirs = sorted_subdirectories(directory);
  if (dirs.size() != cameras)
    throw Error(Errc::camera_mismatch, directory + " has " + std::to_string(dirs.size()) + " camera folders, the calibration " +
                                           std::to_string(cameras) + " cameras");
  std::set<std::string> names;
  for (const auto& d : dirs)
    for (const auto& e : fs::directory_iterator(d, ec))
      if (e.is_regular_file()) names.insert(e.path().filename().string());
  BoardViews views;
  for (const std::string& n : names) {
    std::vector<std::vector<Eigen::Vector2d>> set(cameras);
    for (size_t v = 0; v < cameras; ++v) {
      const fs::path p = dirs[v] / n;
      if (!fs::exists(p)) continue;
      const cv::Mat gray = cv::imread(p.string(), cv::IMREAD_GRAYSCALE);
      if (gray.empty()) {
        log(LogLevel::warning, p.string() + ": unreadable image");
        continue;
      }
      std::vector<cv::Point2f> c;
      if (!cv::findChessboardCornersSB(gray, cv::Size(board.cols, board.rows), c, cv::CALIB_CB_NORMALIZE_IMAGE))
        continue;
      for (const auto& q : c) set[v].emplace_back(q.x, q.y);
    }
    views.push_back(std::move(set));
  }
  return views;
}

}  // namespace octocap::internal
