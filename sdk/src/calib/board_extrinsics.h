// Stage 1b, the classic way: a checkerboard seen by several cameras at once. Each camera's pose is found
// relative to the board (PnP), chained through shared board views into a layout, then bundle-adjusted (Ceres).
// The board fixes the scale (its square size) and the world: origin at the first view's first inner corner,
// X along the board's columns, up along the board's normal (the board lies on the floor in that view).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "calib/extrinsics.h"
#include "calib/intrinsics.h"

namespace octocap::internal {

// corners[set][camera] = the board's inner corners in that camera's image (row-major, board.cols per row),
// empty where the camera did not see the whole board in that set.
using BoardViews = std::vector<std::vector<std::vector<Eigen::Vector2d>>>;

Calibration calibrate_extrinsics_from_boards(const Calibration& intrinsics, const BoardViews& corners,
                                             const BoardSpec& board, bool z_up, ExtrinsicsReport* report);

// Finds the board in every image set: DIR holds one sub-folder per camera (sorted, matching the calibration's
// order); images with the same file name in different folders were taken at the same moment.
BoardViews detect_board_views(const std::string& directory, size_t cameras, const BoardSpec& board);

}  // namespace octocap::internal
