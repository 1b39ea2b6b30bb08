// What octocap needs to know about a pose model, read from the JSON card beside the .onnx (models/README.md).
// The detector is written against this card only, never against a model's name.
#pragma once
#include <array>
#include <string>

#include "core/layout.h"

namespace octocap::internal {

enum class OutputKind : int { movenet, movenet_multipose, heatmap, simcc, yolo_pose, blazepose };
enum class ElementType : int { int32, uint8, float32 };

struct ModelCard {
  std::string name;
  LayoutId layout = LayoutId::coco17;
  int input_width = 0, input_height = 0;
  bool dynamic_size = false;
  int size_multiple = 1;
  ElementType element = ElementType::float32;
  bool nchw = false;
  bool bgr = false;
  bool upright = false;  // the model wants the body upright in its input: crops turn with the person
  bool quantized = false;  // INT8 weights and activations: fast and accurate only where the CPU has VNNI
  std::array<float, 3> mean{0, 0, 0}, scale{1, 1, 1};
  OutputKind output = OutputKind::movenet;
  int max_people = 1;
  double simcc_ratio = 2.0;
  double score_threshold = 0.25;
  // A faster model of the same layout (a shipped name, or a .onnx path relative to this card) that a governed live
  // capture steps down to when even one view detected a set is too slow; "" none.
  std::string lighter;
};

// Throws Error(io / parse) naming the file and the key.
ModelCard read_model_card(const std::string& path);
// "model.onnx" -> "model.json".
std::string model_card_path(const std::string& model_path);
const char* output_kind_name(OutputKind kind);

}  // namespace octocap::internal
