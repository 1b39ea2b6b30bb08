// Stage 1a: a camera's intrinsics and distortion from images of a checkerboard (OpenCV).
#pragma once
#include <string>
#include <vector>

#include "core/camera.h"

namespace octocap::internal {

struct BoardSpec {
  int cols = 0, rows = 0;   // checkerboard: inner corners; ChArUco: squares
  double square_m = 0;
  bool charuco = false;
  double marker_m = 0;      // ChArUco marker side
  int dictionary = 10;      // ChArUco: cv::aruco predefined dictionary (10 = DICT_6X6_250)
};
// "checkerboard:COLSxROWS:SQUARE_M" or "charuco:COLSxROWS:SQUARE_M:MARKER_M[:DICT_6X6_250]"; throws
// Error(invalid_argument) naming what is wrong.
BoardSpec parse_board(const std::string& spec);

struct IntrinsicsReport {
  double rms_px = 0;
  std::vector<std::string> used, rejected;  // image files, and why each rejected one was
};

// Every image file in `directory` (png, jpg, jpeg, bmp, tif). Images that are unreadable, blurred, or where
// the whole board is not found are rejected with a reason; at least 3 good views are required.
// With `overlay_png`, also writes the first good view with the detected corners (green rings) and the corners
// reprojected through the result (red dots), so a person can see the fit.
Camera calibrate_intrinsics(const std::string& directory, const BoardSpec& board, IntrinsicsReport* report,
                            const std::string& overlay_png = "");

}  // namespace octocap::internal
