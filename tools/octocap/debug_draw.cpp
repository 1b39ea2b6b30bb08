#include "debug_draw.h"

#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <string>

namespace {

// Limbs by keypoint names, so any layout that has the names gets lines.
const char* kLimbs[][2] = {
    {"LShoulder", "RShoulder"}, {"LShoulder", "LElbow"}, {"LElbow", "LWrist"}, {"RShoulder", "RElbow"},
    {"RElbow", "RWrist"}, {"LShoulder", "LHip"}, {"RShoulder", "RHip"}, {"LHip", "RHip"}, {"LHip", "LKnee"},
    {"LKnee", "LAnkle"}, {"RHip", "RKnee"}, {"RKnee", "RAnkle"}, {"Nose", "LEye"}, {"Nose", "REye"},
    {"LEye", "LEar"}, {"REye", "REar"}};

int keypoint_index(octocap_layout_t layout, uint32_t count, const char* name) {
  for (uint32_t k = 0; k < count; ++k) {
    const char* n = octocap_layout_keypoint_name(layout, k);
    if (n && std::strcmp(n, name) == 0) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

void draw_detections(cv::Mat& image, const std::vector<octocap_keypoint2d_t>& people, uint32_t K,
                     octocap_layout_t layout, float min_confidence) {
  static const cv::Scalar colours[] = {{0, 200, 255}, {255, 120, 0}, {80, 220, 80}, {200, 80, 255}};
  const int thickness = std::max(1, image.cols / 400);
  for (size_t p = 0; K && p < people.size() / K; ++p) {
    const octocap_keypoint2d_t* kp = &people[p * K];
    const cv::Scalar colour = colours[p % 4];
    for (const auto& limb : kLimbs) {
      const int a = keypoint_index(layout, K, limb[0]), b = keypoint_index(layout, K, limb[1]);
      if (a < 0 || b < 0 || kp[a].confidence < min_confidence || kp[b].confidence < min_confidence) continue;
      cv::line(image, {static_cast<int>(kp[a].x), static_cast<int>(kp[a].y)},
               {static_cast<int>(kp[b].x), static_cast<int>(kp[b].y)}, colour, thickness, cv::LINE_AA);
    }
    for (uint32_t k = 0; k < K; ++k)
      if (kp[k].confidence >= min_confidence)
        cv::circle(image, {static_cast<int>(kp[k].x), static_cast<int>(kp[k].y)}, 2 * thickness + 1, colour, cv::FILLED,
                   cv::LINE_AA);
  }
}

void draw_reprojection(cv::Mat& image, const std::vector<cv::Point2d>& reprojected) {
  const int size = std::max(4, image.cols / 150), thickness = std::max(1, image.cols / 500);
  for (const cv::Point2d& p : reprojected)
    if (std::isfinite(p.x) && std::isfinite(p.y))
      cv::drawMarker(image, {static_cast<int>(p.x), static_cast<int>(p.y)}, {255, 255, 255}, cv::MARKER_CROSS, size,
                     thickness, cv::LINE_AA);
}
