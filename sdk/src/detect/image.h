// Camera images as the caller hands them (no copy), and the letterbox that fits one into a network input.
#pragma once
#include <cstdint>
#include <vector>

namespace octocap::internal {

enum class PixelFormat : int { rgb8 = 0, bgr8 = 1, rgba8 = 2 };

struct ImageView {
  const uint8_t* pixels = nullptr;
  int width = 0, height = 0;
  int stride = 0;  // bytes per row
  PixelFormat format = PixelFormat::rgb8;
};

// A view with no picture this frame (a camera that lagged, dropped or is reconnecting): no pixels, no size.
inline bool absent(const ImageView& v) { return v.pixels == nullptr && v.width == 0 && v.height == 0; }

int bytes_per_pixel(PixelFormat f);
// Throws Error(invalid_argument) naming `what` for null pixels, zero size, a stride shorter than a row, or an
// unknown format.
void validate_image(const ImageView& image, const char* what);

// A rectangle of a source image scaled uniformly (aspect kept) and centred in a destination rectangle.
// In continuous coordinates (pixel i covers [i, i+1)): dst = src * scale + offset. Keypoints use OpenPose's
// convention, pixel i's centre at i, so the mappings below shift by half a pixel on each side; without it every
// back-mapped keypoint would be off by (1/scale - 1) / 2 pixels.
struct Letterbox {
  double scale = 1, offset_x = 0, offset_y = 0;
  double to_source_x(double x) const { return (x + 0.5 - offset_x) / scale - 0.5; }
  double to_source_y(double y) const { return (y + 0.5 - offset_y) / scale - 0.5; }
  double to_dest_x(double x) const { return (x + 0.5) * scale + offset_x - 0.5; }
  double to_dest_y(double y) const { return (y + 0.5) * scale + offset_y - 0.5; }
};

struct Rect {
  double x = 0, y = 0, width = 0, height = 0;
};

// Placement of `src` (a rectangle of a source image) centred inside `dst`, aspect kept.
Letterbox fit_letterbox(const Rect& src, const Rect& dst);

// An RGB8 canvas the network input is built in (packed rows, zero = black padding).
struct RgbCanvas {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;
  void reset(int w, int h);
};

// Draws `src_rect` of `image` into `canvas` at `dst_rect` through `box` (from fit_letterbox), converting to RGB.
// Parts of src_rect outside the image stay black (crops may reach past the border).
void draw_letterboxed(const ImageView& image, const Rect& src_rect, const Rect& dst_rect, const Letterbox& box,
                      RgbCanvas& canvas);

}  // namespace octocap::internal
