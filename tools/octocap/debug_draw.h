// What `--debug-images` writes: each view with the detector's keypoints (dots and limbs, one colour per person)
// and the solved 3D keypoints reprojected (white crosses), so a person can see what the pipeline did.
#pragma once
#include <opencv2/core.hpp>
#include <vector>

#include "octocap/octocap.h"

// people: keypoint_count keypoints per person, one after the other. reprojected: one per keypoint (NaN = none).
void draw_detections(cv::Mat& image, const std::vector<octocap_keypoint2d_t>& people, uint32_t keypoint_count,
                     octocap_layout_t layout, float min_confidence);
void draw_reprojection(cv::Mat& image, const std::vector<cv::Point2d>& reprojected);
