#include "detect/image.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/error.h"

namespace octocap::internal {

int bytes_per_pixel(PixelFormat f) {
  switch (f) {
    case PixelFormat::rgb8:
    case PixelFormat::bgr8: return 3;
    case PixelFormat::rgba8: return 4;
  }
  return 0;
}

void validate_image(const ImageView& image, const char* what) {
  const std::string name(what);
  const int bpp = bytes_per_pixel(image.format);
  if (bpp == 0) throw Error(Errc::invalid_argument, name + ": unknown pixel format " + std::to_string(static_cast<int>(image.format)));
  if (!image.pixels) throw Error(Errc::invalid_argument, name + ": pixels is NULL");
  if (image.width <= 0 || image.height <= 0)
    throw Error(Errc::invalid_argument, name + ": size " + std::to_string(image.width) + "x" +
                                            std::to_string(image.height) + " is empty");
  if (image.width > 16384 || image.height > 16384)
    throw Error(Errc::invalid_argument, name + ": size " + std::to_string(image.width) + "x" +
                                            std::to_string(image.height) + " is larger than 16384");
  if (image.stride < image.width * bpp)
    throw Error(Errc::invalid_argument, name + ": stride " + std::to_string(image.stride) + " bytes is shorter than a row (" +
                                            std::to_string(image.width) + " x " + std::to_string(bpp) + " bytes)");
}

Letterbox fit_letterbox(const Rect& src, const Rect& dst) {
  Letterbox box;
  box.scale = std::min(dst.width / src.width, dst.height / src.height);
  box.offset_x = dst.x + (dst.width - src.width * box.scale) / 2 - src.x * box.scale;
  box.offset_y = dst.y + (dst.height - src.height * box.scale) / 2 - src.y * box.scale;
  return box;
}

void RgbCanvas::reset(int w, int h) {
  width = w;
  height = h;
  pixels.assign(static_cast<size_t>(w) * h * 3, 0);
}

void draw_letterboxed(const ImageView& image, const Rect& src_rect, const Rect& dst_rect, const Letterbox& box,
                      RgbCanvas& canvas) {
  // The part of src_rect inside the image, and where it lands in the canvas (clipped to dst_rect).
  const double sx0 = std::max(0.0, src_rect.x), sy0 = std::max(0.0, src_rect.y);
  const double sx1 = std::min<double>(image.width, src_rect.x + src_rect.width);
  const double sy1 = std::min<double>(image.height, src_rect.y + src_rect.height);
  if (sx1 <= sx0 || sy1 <= sy0) return;
  // Continuous edges: sx0..sx1 land on sx * scale + offset.
  const int dx0 = std::max<int>(static_cast<int>(std::lround(sx0 * box.scale + box.offset_x)), static_cast<int>(dst_rect.x));
  const int dy0 = std::max<int>(static_cast<int>(std::lround(sy0 * box.scale + box.offset_y)), static_cast<int>(dst_rect.y));
  const int dx1 = std::min<int>(static_cast<int>(std::lround(sx1 * box.scale + box.offset_x)), static_cast<int>(dst_rect.x + dst_rect.width));
  const int dy1 = std::min<int>(static_cast<int>(std::lround(sy1 * box.scale + box.offset_y)), static_cast<int>(dst_rect.y + dst_rect.height));
  if (dx1 <= dx0 || dy1 <= dy0) return;

  const int type = image.format == PixelFormat::rgba8 ? CV_8UC4 : CV_8UC3;
  const cv::Mat src(image.height, image.width, type, const_cast<uint8_t*>(image.pixels), static_cast<size_t>(image.stride));
  cv::Mat dst(canvas.height, canvas.width, CV_8UC3, canvas.pixels.data());
  cv::Mat roi = dst(cv::Rect(dx0, dy0, dx1 - dx0, dy1 - dy0));
  // Sample through the exact inverse map so that back-mapped keypoints line up with the pixels the network saw.
  cv::Mat map_x(roi.rows, roi.cols, CV_32F), map_y(roi.rows, roi.cols, CV_32F);
  for (int r = 0; r < roi.rows; ++r) {
    float* mx = map_x.ptr<float>(r);
    float* my = map_y.ptr<float>(r);
    const double sy = box.to_source_y(dy0 + r);
    for (int c = 0; c < roi.cols; ++c) {
      mx[c] = static_cast<float>(box.to_source_x(dx0 + c));
      my[c] = static_cast<float>(sy);
    }
  }
  // Downscaling by more than 2x aliases with bilinear sampling: blur the source first by pre-shrinking it.
  cv::Mat sampled;
  if (box.scale < 0.5) {
    const cv::Rect area(static_cast<int>(sx0), static_cast<int>(sy0), static_cast<int>(std::ceil(sx1)) - static_cast<int>(sx0),
                        static_cast<int>(std::ceil(sy1)) - static_cast<int>(sy0));
    const double f = std::min(1.0, 2 * box.scale);
    cv::Mat small;
    cv::resize(src(area), small, cv::Size(), f, f, cv::INTER_AREA);
    const double kx = static_cast<double>(small.cols) / area.width, ky = static_cast<double>(small.rows) / area.height;
    for (int r = 0; r < roi.rows; ++r) {
      float* mx = map_x.ptr<float>(r);
      float* my = map_y.ptr<float>(r);
      for (int c = 0; c < roi.cols; ++c) {
        mx[c] = static_cast<float>((mx[c] + 0.5 - area.x) * kx - 0.5);
        my[c] = static_cast<float>((my[c] + 0.5 - area.y) * ky - 0.5);
      }
    }
    cv::remap(small, sampled, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  } else {
    cv::remap(src, sampled, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  }
  switch (image.format) {
    case PixelFormat::rgb8: sampled.copyTo(roi); break;
    case PixelFormat::bgr8: cv::cvtColor(sampled, roi, cv::COLOR_BGR2RGB); break;
    case PixelFormat::rgba8: cv::cvtColor(sampled, roi, cv::COLOR_RGBA2RGB); break;
  }
}

}  // namespace octocap::internal
