#include "detect/turned_crop.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace octocap::internal {
namespace {

// The mean of the first alternative of `sources` whose keypoints are all confident.
std::optional<std::pair<double, double>> joint(const Person2D& p, const std::vector<std::vector<int>>& sources,
                                               double min_confidence) {
  const std::vector<int>* alt = first_present_alternative(sources, [&](int k) {
    return k >= 0 && static_cast<size_t>(k) < p.size() && p[k].confidence >= min_confidence;
  });
  if (!alt) return std::nullopt;
  double x = 0, y = 0;
  for (int k : *alt) x += p[k].x, y += p[k].y;
  return std::make_pair(x / alt->size(), y / alt->size());
}

// Source -> crop frame: the offset from the centre turned back by the angle.
void to_crop(double angle, double dx, double dy, double& u, double& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  u = c * dx + s * dy;
  v = -s * dx + c * dy;
}

// Crop frame -> source: the offset (u, v) turned by the angle, added to the centre (cx, cy).
void from_crop(double angle, double cx, double cy, double u, double v, double& x, double& y) {
  const double c = std::cos(angle), s = std::sin(angle);
  x = cx + c * u - s * v;
  y = cy + s * u + c * v;
}

}  // namespace

std::optional<double> body_lean(const Person2D& person, const KeypointLayout& layout, double min_confidence) {
  const auto shoulders = joint(person, layout.joint_sources[kNeck], min_confidence);
  const auto hips = joint(person, layout.joint_sources[kRoot], min_confidence);
  if (!shoulders || !hips) return std::nullopt;
  const double ux = shoulders->first - hips->first, uy = shoulders->second - hips->second;
  if (std::hypot(ux, uy) < 1) return std::nullopt;  // no length: no direction
  return std::atan2(ux, -uy);
}

TurnedCrop turned_crop_around(const Person2D& person, double angle, double aspect, double pad, double min_confidence) {
  // The keypoints' box in the turned frame, around their mean.
  double mx = 0, my = 0;
  int n = 0;
  for (const Keypoint2D& k : person)
    if (k.confidence >= min_confidence) mx += k.x, my += k.y, ++n;
  TurnedCrop crop;
  crop.angle = angle;
  if (n < 2) return crop;
  mx /= n, my /= n;
  double u0 = INFINITY, v0 = INFINITY, u1 = -INFINITY, v1 = -INFINITY;
  for (const Keypoint2D& k : person) {
    if (!(k.confidence >= min_confidence)) continue;
    double u, v;
    to_crop(angle, k.x - mx, k.y - my, u, v);
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  }
  crop.height = std::max(v1 - v0, (u1 - u0) / aspect) * pad;
  crop.width = crop.height * aspect;
  // The box's centre, back in source pixels.
  from_crop(angle, mx, my, (u0 + u1) / 2, (v0 + v1) / 2, crop.centre_x, crop.centre_y);
  // Keypoints too far out to make a crop of (no picture is a million pixels tall): none; the caller crops level.
  if (!std::isfinite(crop.centre_x) || !std::isfinite(crop.centre_y) || !(crop.height < 1e6)) crop.width = crop.height = 0;
  return crop;
}

void turned_to_source(const TurnedCrop& crop, int canvas_width, int canvas_height, double& x, double& y) {
  const double scale = canvas_height / crop.height;  // canvas pixels per source pixel
  from_crop(crop.angle, crop.centre_x, crop.centre_y, (x - (canvas_width - 1) / 2.0) / scale,
            (y - (canvas_height - 1) / 2.0) / scale, x, y);
}

void draw_turned(const ImageView& image, const TurnedCrop& crop, RgbCanvas& canvas) {
  const int type = image.format == PixelFormat::rgba8 ? CV_8UC4 : CV_8UC3;
  const cv::Mat src(image.height, image.width, type, const_cast<uint8_t*>(image.pixels), static_cast<size_t>(image.stride));
  // The source area the turned crop covers (its corners' box), clipped to the image.
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (int corner = 0; corner < 4; ++corner) {
    double x = corner % 2 ? canvas.width - 0.5 : -0.5, y = corner / 2 ? canvas.height - 0.5 : -0.5;
    turned_to_source(crop, canvas.width, canvas.height, x, y);
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  // Clamped as doubles first: a crop from a wild hint (a point reprojected near a camera's plane) may lie far outside
  // int's range.
  auto clamped = [](double v, int hi) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi))); };
  const int ax0 = clamped(std::floor(x0) - 1, image.width), ay0 = clamped(std::floor(y0) - 1, image.height);
  const int ax1 = clamped(std::ceil(x1) + 2, image.width), ay1 = clamped(std::ceil(y1) + 2, image.height);
  cv::Mat out(canvas.height, canvas.width, CV_8UC3, canvas.pixels.data());
  if (!std::isfinite(x0 + x1 + y0 + y1) || ax1 <= ax0 || ay1 <= ay0) return;  // nothing of the image: black
  // Shrinking by more than 2x aliases with bilinear sampling: the area is first shrunk to at most twice the canvas.
  const double scale = canvas.height / crop.height;
  const double f = std::min(1.0, 2 * scale);
  cv::Mat area = src(cv::Rect(ax0, ay0, ax1 - ax0, ay1 - ay0)), small;
  if (f < 1)
    cv::resize(area, small, cv::Size(std::max(1, static_cast<int>(std::lround(area.cols * f))),
                                     std::max(1, static_cast<int>(std::lround(area.rows * f)))), 0, 0, cv::INTER_AREA);
  else small = area;
  const double kx = static_cast<double>(small.cols) / area.cols, ky = static_cast<double>(small.rows) / area.rows;
  // Canvas pixel (x, y) samples source (turned_to_source), in `small`'s pixels: an affine map, inverted for OpenCV.
  double px = 0, py = 0, qx = 1, qy = 0, rx = 0, ry = 1;
  turned_to_source(crop, canvas.width, canvas.height, px, py);
  turned_to_source(crop, canvas.width, canvas.height, qx, qy);
  turned_to_source(crop, canvas.width, canvas.height, rx, ry);
  auto sx = [&](double x) { return (x + 0.5 - ax0) * kx - 0.5; };
  auto sy = [&](double y) { return (y + 0.5 - ay0) * ky - 0.5; };
  const cv::Matx23d dst_to_src(sx(qx) - sx(px), sx(rx) - sx(px), sx(px), sy(qy) - sy(py), sy(ry) - sy(py), sy(py));
  cv::Mat sampled;
  cv::warpAffine(small, sampled, dst_to_src, out.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT,
                 cv::Scalar::all(0));
  switch (image.format) {
    case PixelFormat::rgb8: sampled.copyTo(out); break;
    case PixelFormat::bgr8: cv::cvtColor(sampled, out, cv::COLOR_BGR2RGB); break;
    case PixelFormat::rgba8: cv::cvtColor(sampled, out, cv::COLOR_RGBA2RGB); break;
  }
}

}  // namespace octocap::internal
