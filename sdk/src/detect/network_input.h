// The network's input tensor from a canvas, as the model card describes it: shared by every inference back end, so
// that they are fed the same numbers (and the same size checks) and differ only in how they run the network.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "detect/image.h"
#include "detect/model_card.h"

namespace octocap::internal {

// Throws Error(invalid_argument) when the canvas's size does not suit the card (its size, or a multiple of
// size_multiple for a dynamic model).
void check_input_size(const ModelCard& card, const RgbCanvas& canvas);
// Whether a model's declared input (-1: a dynamic dimension) is a 3-channel image tensor of the card's layout and
// size; Error(invalid_argument) naming `path` and what misfits. Both back ends check at load with this one rule.
void check_model_input(const std::string& path, const ModelCard& card, const std::vector<int64_t>& shape);
// {1,3,H,W} or {1,H,W,3} as the card's tensor layout says.
std::vector<int64_t> input_shape(const ModelCard& card, const RgbCanvas& canvas);

// The tensor's elements in the card's element type, channel order and normalisation. One of the three is filled.
struct InputTensor {
  std::vector<int32_t> i32;
  std::vector<uint8_t> u8;
  std::vector<float> f32;
  void* data();
  size_t bytes() const;
};
InputTensor fill_input(const ModelCard& card, const RgbCanvas& canvas);

}  // namespace octocap::internal
