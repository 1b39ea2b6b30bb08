// The paper's merged input: every view down-sampled into its own tile of one image, the network run once, each
// keypoint mapped back to its view by the tile it fell in.
#pragma once
#include <vector>

#include "detect/decoders.h"
#include "detect/image.h"

namespace octocap::internal {

struct MosaicTile {
  Rect cell;     // the tile in the mosaic
  Rect content;  // where the view's pixels land inside the cell, continuous coordinates (the rest is padding)
  Letterbox box; // view pixels <-> mosaic pixels
};

struct MosaicLayout {
  int width = 0, height = 0, columns = 0, rows = 0;
  std::vector<MosaicTile> tiles;  // one per view, row-major
};

struct ViewSize {
  int width = 0, height = 0;
};

// A grid of ceil(sqrt(N)) columns of tile_width x tile_height cells; each view is letterboxed into its cell.
MosaicLayout plan_mosaic(const std::vector<ViewSize>& views, int tile_width, int tile_height);
// The view whose content holds mosaic point (x, y) (pixel centres at integers), or -1 (padding or outside).
int tile_at(const MosaicLayout& layout, double x, double y);

// People found in the mosaic, given to the views their keypoints fell in: each person goes to the tile holding
// most of its keypoints of at least min_confidence; keypoints outside that tile's content are dropped (zero
// confidence: they belong to a neighbour's picture). Coordinates come back in view pixels.
std::vector<std::vector<DetectedPerson>> split_mosaic_people(const MosaicLayout& layout,
                                                             const std::vector<DetectedPerson>& people,
                                                             double min_confidence);

}  // namespace octocap::internal
