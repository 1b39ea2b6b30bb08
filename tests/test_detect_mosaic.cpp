// The paper's mosaic: tiling views of mixed sizes and mapping keypoints back to each view's own pixels.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <random>

#include "detect/mosaic.h"

using namespace octocap;
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
