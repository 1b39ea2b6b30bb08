#include "detect/network_input.h"

#include <cmath>
#include <string>
#include <type_traits>

#include "core/error.h"
#include "detect/decoders.h"

namespace octocap::internal {

void check_input_size(const ModelCard& card, const RgbCanvas& canvas) {
  const int W = canvas.width, H = canvas.height;
  const bool ok = card.dynamic_size ? (W > 0 && H > 0 && W % card.size_multiple == 0 && H % card.size_multiple == 0)
                                    : (W == card.input_width && H == card.input_height);
  if (!ok)
    throw Error(Errc::invalid_argument, "network input " + std::to_string(W) + "x" + std::to_string(H) +
                                            " does not suit model " + card.name);
}

void check_model_input(const std::string& path, const ModelCard& card, const std::vector<int64_t>& shape) {
  if (shape.size() != 4)
    throw Error(Errc::invalid_argument, path + ": input " + shape_string(shape) + " is not a 4D image tensor");
  const int64_t h = shape[card.nchw ? 2 : 1], w = shape[card.nchw ? 3 : 2], c = shape[card.nchw ? 1 : 3];
  if (c != 3 && c != -1)
    throw Error(Errc::invalid_argument, path + ": input " + shape_string(shape) + " has " + std::to_string(c) +
                                            " channels, 3 expected (is the card's tensor_layout right?)");
  if (!card.dynamic_size && ((h > 0 && h != card.input_height) || (w > 0 && w != card.input_width)))
    throw Error(Errc::invalid_argument, path + ": input " + shape_string(shape) + " differs from the card's " +
                                            std::to_string(card.input_width) + "x" + std::to_string(card.input_height));
}

std::vector<int64_t> input_shape(const ModelCard& card, const RgbCanvas& canvas) {
  const int64_t W = canvas.width, H = canvas.height;
  return card.nchw ? std::vector<int64_t>{1, 3, H, W} : std::vector<int64_t>{1, H, W, 3};
}

void* InputTensor::data() {
  if (!i32.empty()) return i32.data();
  if (!u8.empty()) return u8.data();
  return f32.data();
}

size_t InputTensor::bytes() const {
  return i32.size() * sizeof(int32_t) + u8.size() + f32.size() * sizeof(float);
}

InputTensor fill_input(const ModelCard& card, const RgbCanvas& canvas) {
  check_input_size(card, canvas);
  const size_t plane = static_cast<size_t>(canvas.width) * canvas.height;
  // Element at(p, c) of the tensor from canvas pixel p, channel c (after the card's channel order and normalisation).
  auto fill = [&](auto& buffer) {
    buffer.resize(plane * 3);
    const uint8_t* px = canvas.pixels.data();
    using T = typename std::decay_t<decltype(buffer)>::value_type;
    for (size_t p = 0; p < plane; ++p)
      for (int c = 0; c < 3; ++c) {
        const int source = card.bgr ? 2 - c : c;
        const float v = (px[p * 3 + source] - card.mean[c]) * card.scale[c];
        const size_t at = card.nchw ? c * plane + p : p * 3 + c;
        buffer[at] = std::is_integral_v<T> ? static_cast<T>(std::lround(v)) : static_cast<T>(v);
      }
  };
  InputTensor t;
  switch (card.element) {
    case ElementType::int32: fill(t.i32); break;
    case ElementType::uint8: fill(t.u8); break;
    case ElementType::float32: fill(t.f32); break;
  }
  return t;
}

}  // namespace octocap::internal
