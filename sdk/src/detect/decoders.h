// Turns a pose network's raw outputs into people with keypoints in network-input pixels. One function per
// output kind of the model card; each checks the tensor shapes it is given and names what it expected.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "detect/image.h"
#include "detect/model_card.h"
#include "core/person2d.h"

namespace octocap::internal {

struct Tensor {
  std::vector<int64_t> shape;
  std::vector<float> data;
};
std::string shape_string(const std::vector<int64_t>& shape);

struct DetectedPerson {
  Person2D keypoints;  // network-input pixels (x right, y down), confidence 0..1
  double score = 0;    // the model's person score (mean keypoint score where the model has none)
  Rect box;            // around the person, same pixels
};

// Input of the decoders: outputs of one inference over an input of in_width x in_height pixels.
// Throws Error(invalid_argument) when the outputs do not have the shape the card's kind implies.
std::vector<DetectedPerson> decode_pose(const ModelCard& card, const std::vector<Tensor>& outputs, int in_width,
                                        int in_height, size_t keypoint_count);

// The individual decoders (tested against hand-built tensors).
std::vector<DetectedPerson> decode_movenet(const Tensor& t, int in_width, int in_height, size_t K);
std::vector<DetectedPerson> decode_movenet_multipose(const Tensor& t, int in_width, int in_height, size_t K,
                                                     double min_score);
std::vector<DetectedPerson> decode_heatmaps(const Tensor& t, int in_width, int in_height, size_t K);
std::vector<DetectedPerson> decode_simcc(const Tensor& x, const Tensor& y, int in_width, int in_height, size_t K,
                                         double ratio);
// BlazePose GHUM landmarks ([1,195]: 39 x (x, y, z, visibility, presence), input pixels) and its person flag ([1,1]).
std::vector<DetectedPerson> decode_blazepose(const Tensor& landmarks, const Tensor& flag, size_t K, double min_score);
std::vector<DetectedPerson> decode_yolo_pose(const Tensor& t, size_t K, double min_score, size_t max_people);

// Peak of a sampled 1D/2D signal refined by a parabola through the peak and its neighbours (at most half a bin).
double parabolic_offset(double left, double centre, double right);
// The box around a person's keypoints of at least `min_confidence`; empty when there are fewer than two.
Rect keypoint_box(const Person2D& person, double min_confidence);

}  // namespace octocap::internal
