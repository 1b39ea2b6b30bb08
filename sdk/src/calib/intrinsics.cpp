#include "calib/intrinsics.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <opencv2/aruco/charuco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <regex>

#include "core/error.h"
#include "io/directories.h"
#include "core/log.h"

namespace fs = std::filesystem;

namespace octocap::internal {

namespace {

struct DictName {
  const char* name;
  int id;
};
const DictName kDictionaries[] = {{"DICT_4X4_50", cv::aruco::DICT_4X4_50},     {"DICT_4X4_100", cv::aruco::DICT_4X4_100},
                                  {"DICT_4X4_250", cv::aruco::DICT_4X4_250},   {"DICT_5X5_50", cv::aruco::DICT_5X5_50},
                                  {"DICT_5X5_100", cv::aruco::DICT_5X5_100},   {"DICT_5X5_250", cv::aruco::DICT_5X5_250},
                                  {"DICT_6X6_50", cv::aruco::DICT_6X6_50},     {"DICT_6X6_100", cv::aruco::DICT_6X6_100},
                                  {"DICT_6X6_250", cv::aruco::DICT_6X6_250},   {"DICT_7X7_50", cv::aruco::DICT_7X7_50},
                                  {"DICT_7X7_250", cv::aruco::DICT_7X7_250}};

BoardSpec parse_charuco(const std::string& spec) {
  // Bounded repetitions: every number fits its type, and the regex engine's recursion stays shallow.
  static const std::regex re(R"(charuco:(\d{1,4})x(\d{1,4}):([0-9]{0,6}\.?[0-9]{1,9}):([0-9]{0,6}\.?[0-9]{1,9})(?::(\w{1,32}))?)");
  std::smatch m;
  if (!std::regex_match(spec, m, re))
    throw Error(Errc::invalid_argument, "board '" + spec +
                                            "' is not charuco:COLSxROWS:SQUARE_M:MARKER_M[:DICT_6X6_250] (squares, metres)");
  BoardSpec b{std::stoi(m[1]), std::stoi(m[2]), std::stod(m[3]), true, std::stod(m[4]), cv::aruco::DICT_6X6_250};
  if (m[5].matched) {
    bool found = false;
    for (const auto& d : kDictionaries)
      if (m[5] == d.name) b.dictionary = d.id, found = true;
    if (!found) throw Error(Errc::invalid_argument, "unknown ArUco dictionary '" + m[5].str() + "'");
  }
  if (b.cols < 3 || b.rows < 3 || !(b.marker_m > 0) || b.marker_m >= b.square_m)
    throw Error(Errc::invalid_argument, "board '" + spec + "' needs at least 3x3 squares and 0 < marker < square");
  return b;
}

}  // namespace

BoardSpec parse_board(const std::string& spec) {
  static const std::regex re(R"(checkerboard:(\d{1,4})x(\d{1,4}):([0-9]{0,6}\.?[0-9]{1,9}))");
  std::smatch m;
  // std::regex recurses per character: a spec of thousands of characters would overflow the stack before failing.
  if (spec.size() > 128) throw Error(Errc::invalid_argument, "board spec is " + std::to_string(spec.size()) +
                                                                 " characters; a board spec is at most 128");
  if (spec.rfind("charuco:", 0) == 0) return parse_charuco(spec);
  if (!std::regex_match(spec, m, re))
    throw Error(Errc::invalid_argument, "board '" + spec + "' is not checkerboard:COLSxROWS:SQUARE_M (inner corners, metres)");
  BoardSpec b{std::stoi(m[1]), std::stoi(m[2]), std::stod(m[3]), false, 0, 0};
  if (b.cols < 2 || b.rows < 2 || !(b.square_m > 0))
    throw Error(Errc::invalid_argument, "board '" + spec + "' needs at least 2x2 inner corners and a square size > 0");
  return b;
}

Camera calibrate_intrinsics(const std::string& directory, const BoardSpec& board, IntrinsicsReport* report,
                            const std::string& overlay_png) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) throw Error(Errc::io, directory + ": not a directory");
  const std::vector<std::string> files = sorted_files(directory, picture_extensions());
  if (files.empty()) throw Error(Errc::io, directory + ": no image files (png, jpg, bmp, tif)");

  std::vector<cv::Point3f> board_points;
  for (int r = 0; r < board.rows; ++r)
    for (int c = 0; c < board.cols; ++c)
      board_points.emplace_back(static_cast<float>(c * board.square_m), static_cast<float>(r * board.square_m), 0.f);

  cv::Ptr<cv::aruco::CharucoBoard> charuco;
  if (board.charuco)
    charuco = cv::aruco::CharucoBoard::create(board.cols, board.rows, static_cast<float>(board.square_m),
                                              static_cast<float>(board.marker_m),
                                              cv::aruco::getPredefinedDictionary(board.dictionary));
  std::vector<cv::Mat> charuco_corners, charuco_ids;
  IntrinsicsReport local;
  IntrinsicsReport& rep = report ? *report : local;
  std::vector<std::vector<cv::Point3f>> object;
  std::vector<std::vector<cv::Point2f>> image;
  cv::Size size;
  for (const std::string& f : files) {
    const cv::Mat gray = cv::imread(f, cv::IMREAD_GRAYSCALE);
    if (gray.empty()) {
      rep.rejected.push_back(f + ": unreadable image");
      continue;
    }
    if (size.area() == 0) size = gray.size();
    if (gray.size() != size) {
      rep.rejected.push_back(f + ": size differs from the first image");
      continue;
    }
    if (board.charuco) {
      // ChArUco: markers identify each corner, so partial views are usable; at least a third of the corners.
      std::vector<int> ids;
      std::vector<std::vector<cv::Point2f>> markers;
      cv::aruco::detectMarkers(gray, charuco->dictionary, markers, ids);
      cv::Mat cc, ci;
      const int n = ids.empty() ? 0 : cv::aruco::interpolateCornersCharuco(markers, ids, gray, charuco, cc, ci);
      const int total = (board.cols - 1) * (board.rows - 1);
      if (n < std::max(6, total / 3)) {
        rep.rejected.push_back(f + ": too few ChArUco corners (" + std::to_string(n) + " of " + std::to_string(total) + ")");
        continue;
      }
      charuco_corners.push_back(cc);
      charuco_ids.push_back(ci);
      rep.used.push_back(f);
      continue;
    }
    std::vector<cv::Point2f> corners;
    // The sector-based detector finds boards in blurred and low-contrast images and is accurate to subpixels.
    const bool found = cv::findChessboardCornersSB(gray, cv::Size(board.cols, board.rows), corners,
                                                   cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_EXHAUSTIVE |
                                                       cv::CALIB_CB_ACCURACY);
    if (!found || corners.size() != board_points.size()) {
      rep.rejected.push_back(f + ": the whole board was not found (partial or no view)");
      continue;
    }
    // Sharpness at the board: the width of its edges (OpenCV calls under 3 px sharp at VGA). Edges widen with
    // resolution, so the limit is relative: 0.5 % of the image diagonal, at least 4 px.
    const cv::Scalar sharp = cv::estimateChessboardSharpness(gray, cv::Size(board.cols, board.rows), corners);
    const double limit = std::max(4.0, 0.005 * std::hypot(gray.cols, gray.rows));
    if (sharp[0] > limit) {
      rep.rejected.push_back(f + ": blurred (edge width " + std::to_string(sharp[0]) + " px)");
      continue;
    }
    object.push_back(board_points);
    image.push_back(corners);
    rep.used.push_back(f);
  }
  for (const auto& r : rep.rejected) log(LogLevel::info, "intrinsics: rejected " + r);
  const size_t views = board.charuco ? charuco_corners.size() : image.size();
  if (views < 3)
    throw Error(Errc::not_enough_views, directory + ": " + std::to_string(views) +
                                            " usable board views, at least 3 are needed (" +
                                            std::to_string(rep.rejected.size()) + " rejected)");
  cv::Mat K = cv::Mat::eye(3, 3, CV_64F), dist = cv::Mat::zeros(1, 5, CV_64F);
  std::vector<cv::Mat> rvecs, tvecs;
  if (board.charuco)
    rep.rms_px = cv::aruco::calibrateCameraCharuco(charuco_corners, charuco_ids, charuco, size, K, dist, rvecs, tvecs);
  else
    rep.rms_px = cv::calibrateCamera(object, image, size, K, dist, rvecs, tvecs);
  if (board.charuco) {
    // Overlay: the detected ChArUco corners of the first view and their reprojection.
    object.assign(1, {});
    image.assign(1, {});
    const cv::Mat& ids = charuco_ids.front();
    for (int i = 0; i < ids.rows; ++i) {
      object[0].push_back(charuco->chessboardCorners[ids.at<int>(i)]);
      image[0].push_back(charuco_corners.front().at<cv::Point2f>(i));
    }
  }
  if (!overlay_png.empty()) {
    cv::Mat canvas = cv::imread(rep.used.front(), cv::IMREAD_COLOR);
    std::vector<cv::Point2f> reprojected;
    cv::projectPoints(object.front(), rvecs.front(), tvecs.front(), K, dist, reprojected);
    const int r = std::max(3, size.width / 200);
    for (size_t i = 0; i < reprojected.size(); ++i) {
      cv::circle(canvas, image.front()[i], 2 * r, cv::Scalar(0, 200, 0), std::max(1, r / 2));
      cv::circle(canvas, reprojected[i], r / 2 + 1, cv::Scalar(0, 0, 255), cv::FILLED);
    }
    cv::putText(canvas, "detected (green) vs reprojected (red), RMS " + std::to_string(rep.rms_px) + " px",
                cv::Point(10, 10 + 6 * r), cv::FONT_HERSHEY_SIMPLEX, r / 6.0, cv::Scalar(0, 0, 255), std::max(1, r / 3));
    if (!cv::imwrite(overlay_png, canvas)) throw Error(Errc::io, overlay_png + ": cannot write the overlay PNG");
  }
  Camera cam;
  cam.name = fs::path(directory).filename().string();
  cam.width = size.width;
  cam.height = size.height;
  for (int i = 0; i < 9; ++i) cam.K(i / 3, i % 3) = K.at<double>(i / 3, i % 3);
  for (int i = 0; i < 5; ++i) cam.dist[i] = dist.at<double>(i);
  return cam;
}

}  // namespace octocap::internal
