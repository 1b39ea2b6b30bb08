#include "detect/mosaic.h"

#include <cmath>

#include "core/error.h"

namespace octocap::internal {

MosaicLayout plan_mosaic(const std::vector<ViewSize>& views, int tile_width, int tile_height) {
  if (views.empty()) throw Error(Errc::invalid_argument, "a mosaic needs at least one view");
  if (tile_width <= 0 || tile_height <= 0) throw Error(Errc::invalid_argument, "mosaic tile size must be positive");
  MosaicLayout layout;
  const int n = static_cast<int>(views.size());
  layout.columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  layout.rows = (n + layout.columns - 1) / layout.columns;
  layout.width = layout.columns * tile_width;
  layout.height = layout.rows * tile_height;
  for (int i = 0; i < n; ++i) {
    if (views[i].width <= 0 || views[i].height <= 0)
      throw Error(Errc::invalid_argument, "view " + std::to_string(i) + " has an empty size");
    MosaicTile t;
    t.cell = {static_cast<double>((i % layout.columns) * tile_width), static_cast<double>((i / layout.columns) * tile_height),
              static_cast<double>(tile_width), static_cast<double>(tile_height)};
    const Rect whole{0, 0, static_cast<double>(views[i].width), static_cast<double>(views[i].height)};
    t.box = fit_letterbox(whole, t.cell);
    t.content = {t.box.offset_x, t.box.offset_y, views[i].width * t.box.scale, views[i].height * t.box.scale};
    layout.tiles.push_back(t);
  }
  return layout;
}

int tile_at(const MosaicLayout& layout, double x, double y) {
  x += 0.5, y += 0.5;  // pixel-centre coordinates to continuous ones, as the content rectangles are
  for (size_t i = 0; i < layout.tiles.size(); ++i) {
    const Rect& c = layout.tiles[i].content;
    if (x >= c.x && x < c.x + c.width && y >= c.y && y < c.y + c.height) return static_cast<int>(i);
  }
  return -1;
}

std::vector<std::vector<DetectedPerson>> split_mosaic_people(const MosaicLayout& layout,
                                                             const std::vector<DetectedPerson>& people,
                                                             double min_confidence) {
  std::vector<std::vector<DetectedPerson>> per_view(layout.tiles.size());
  for (const DetectedPerson& p : people) {
    std::vector<int> votes(layout.tiles.size(), 0);
    for (const Keypoint2D& k : p.keypoints)
      if (k.confidence >= min_confidence) {
        const int t = tile_at(layout, k.x, k.y);
        if (t >= 0) ++votes[t];
      }
    int best = -1;
    for (size_t t = 0; t < votes.size(); ++t)
      if (votes[t] > 0 && (best < 0 || votes[t] > votes[best])) best = static_cast<int>(t);
    if (best < 0) continue;
    const Letterbox& box = layout.tiles[best].box;
    DetectedPerson mapped = p;
    for (Keypoint2D& k : mapped.keypoints) {
      if (tile_at(layout, k.x, k.y) != best) k.confidence = 0;
      k.x = box.to_source_x(k.x);
      k.y = box.to_source_y(k.y);
    }
    mapped.box = {box.to_source_x(p.box.x), box.to_source_y(p.box.y), p.box.width / box.scale, p.box.height / box.scale};
    per_view[best].push_back(std::move(mapped));
  }
  return per_view;
}

}  // namespace octocap::internal
