// The paper's mosaic: tiling views of mixed sizes and mapping keypoints back to each view's own pixels.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <random>

#include <algorithm>
#include <cmath>

#include "core/layout.h"
#include "detect/mosaic.h"
#include "detect/turned_crop.h"

using namespace octocap::internal;
using Catch::Approx;

TEST_CASE("mosaic tiling round-trips view pixels exactly for 1..9 views of mixed sizes") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> side(90, 2000);
  for (int n = 1; n <= 9; ++n) {
    std::vector<ViewSize> views;
    for (int i = 0; i < n; ++i) views.push_back({side(rng), side(rng)});
    const MosaicLayout layout = plan_mosaic(views, 160, 256);
    CHECK(layout.columns * layout.rows >= n);
    CHECK(layout.columns * (layout.rows - 1) < n);  // no empty row
    CHECK(layout.width == layout.columns * 160);
    for (int v = 0; v < n; ++v) {
      const MosaicTile& t = layout.tiles[v];
      // The view fills its cell along one axis and is centred along the other.
      CHECK((t.content.width == Approx(160) || t.content.height == Approx(256)));
      CHECK(t.content.x >= t.cell.x - 1e-9);
      CHECK(t.content.x + t.content.width <= t.cell.x + t.cell.width + 1e-9);
      std::uniform_real_distribution<double> px(0, views[v].width - 1), py(0, views[v].height - 1);
      for (int i = 0; i < 200; ++i) {
        const double x = i == 0 ? 0 : i == 1 ? views[v].width - 1 : px(rng);
        const double y = i == 0 ? 0 : i == 1 ? views[v].height - 1 : py(rng);
        const double mx = t.box.to_dest_x(x), my = t.box.to_dest_y(y);
        REQUIRE(tile_at(layout, mx, my) == v);
        CHECK(t.box.to_source_x(mx) == Approx(x).margin(1e-9));
        CHECK(t.box.to_source_y(my) == Approx(y).margin(1e-9));
      }
    }
  }
}

TEST_CASE("mosaic people go to the tile holding most of their keypoints") {
  const MosaicLayout layout = plan_mosaic({{640, 480}, {1280, 720}, {480, 640}}, 256, 256);
  REQUIRE(layout.columns == 2);
  // Person in view 1 with two keypoints spilling into view 0's tile, one on padding.
  const MosaicTile& t1 = layout.tiles[1];
  DetectedPerson p;
  for (int k = 0; k < 5; ++k) p.keypoints.push_back({t1.box.to_dest_x(600.0 + 10 * k), t1.box.to_dest_y(300.0 + 5 * k), 0.9});
  p.keypoints.push_back({layout.tiles[0].box.to_dest_x(100), layout.tiles[0].box.to_dest_y(100), 0.9});
  p.keypoints.push_back({layout.tiles[0].box.to_dest_x(200), layout.tiles[0].box.to_dest_y(100), 0.9});
  p.keypoints.push_back({t1.cell.x + 3, t1.cell.y + 2, 0.9});  // padding above a landscape view
  p.keypoints.push_back({t1.box.to_dest_x(50), t1.box.to_dest_y(60), 0.1});  // weak but inside: kept as is
  const auto per_view = split_mosaic_people(layout, {p}, 0.3);
  REQUIRE(per_view.size() == 3);
  CHECK(per_view[0].empty());
  CHECK(per_view[2].empty());
  REQUIRE(per_view[1].size() == 1);
  const Person2D& got = per_view[1][0].keypoints;
  for (int k = 0; k < 5; ++k) {
    CHECK(got[k].x == Approx(600.0 + 10 * k).margin(1e-9));
    CHECK(got[k].y == Approx(300.0 + 5 * k).margin(1e-9));
    CHECK(got[k].confidence == Approx(0.9));
  }
  CHECK(got[5].confidence == 0);
  CHECK(got[6].confidence == 0);
  CHECK(got[7].confidence == 0);
  CHECK(got[8].confidence == Approx(0.1));
  CHECK(got[8].x == Approx(50).margin(1e-9));
}

// Crops turned with the body (detect/turned_crop.h): a picture's bright spot lands where the map says, and comes back.
TEST_CASE("turned crops: a body leaning 90 deg is turned upright, and pixels map back to where they were") {
  // A person lying along +x: hips at x 100, shoulders at x 300 (COCO_17: shoulders 5/6, hips 11/12).
  const KeypointLayout& coco = layout(LayoutId::coco17);
  Person2D lying(17);
  lying[5] = {300, 90, 1}, lying[6] = {300, 110, 1}, lying[11] = {100, 92, 1}, lying[12] = {100, 108, 1};
  lying[0] = {340, 100, 1}, lying[15] = {20, 95, 1}, lying[16] = {20, 105, 1};
  const std::optional<double> lean = body_lean(lying, coco, 0.3);
  REQUIRE(lean);
  CHECK(*lean * 180 / M_PI == Approx(90).margin(1e-9));  // up the body is the image's +x
  const TurnedCrop crop = turned_crop_around(lying, *lean, 1.0, 1.4, 0.3);
  // The crop's height runs along the body: feet (x 20) to nose (x 340), padded; centred on the span's middle.
  CHECK(crop.height == Approx(320 * 1.4));
  CHECK(crop.centre_x == Approx(180));
  CHECK(crop.centre_y == Approx(100));
  Person2D no_hips(17);
  no_hips[5] = lying[5], no_hips[6] = lying[6];
  CHECK_FALSE(body_lean(no_hips, coco, 0.3));

  // A BGR picture, black, with a white 3x3 spot near the nose: in the canvas it is up (the head), back it is there.
  const int W = 400, H = 200;
  std::vector<uint8_t> pixels(W * H * 3, 0);
  const int spot_x = 330, spot_y = 104;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      for (int c = 0; c < 3; ++c) pixels[((spot_y + dy) * W + spot_x + dx) * 3 + c] = 255;
  const ImageView image{pixels.data(), W, H, W * 3, PixelFormat::bgr8};
  RgbCanvas canvas;
  canvas.reset(448, 448);  // one canvas pixel per source pixel (crop height 448)
  draw_turned(image, crop, canvas);
  double x = 0, y = 0, weight = 0;  // the spot's centroid in the canvas
  for (int i = 0; i < canvas.width * canvas.height; ++i) {
    const double v = canvas.pixels[i * 3];
    x += v * (i % canvas.width), y += v * (i / canvas.width), weight += v;
  }
  REQUIRE(weight == Approx(9 * 255).epsilon(0.05));  // all of it, and nothing else
  x /= weight, y /= weight;
  CHECK(y < canvas.height / 2.0 - 100);  // the head end is up
  turned_to_source(crop, canvas.width, canvas.height, x, y);
  CHECK(x == Approx(spot_x).margin(0.05));
  CHECK(y == Approx(spot_y).margin(0.05));
  // Past the picture's edge the canvas stays black.
  CHECK(canvas.pixels[0] == 0);
  // Keypoints too far out to crop around (a hint reprojected near a camera's plane): no crop, nothing drawn.
  Person2D wild = lying;
  wild[0] = {1e300, -1e300, 1};
  const TurnedCrop none = turned_crop_around(wild, *lean, 1.0, 1.4, 0.3);
  CHECK(none.height == 0);
  TurnedCrop far = crop;
  far.centre_x = 1e15;
  canvas.reset(64, 64);
  draw_turned(image, far, canvas);
  CHECK(std::all_of(canvas.pixels.begin(), canvas.pixels.end(), [](uint8_t p) { return p == 0; }));
}
