#include "detect/model_card.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace octocap::internal {
namespace {

using nlohmann::json;

const json& member(const json& object, const char* key, const std::string& where) {
  auto it = object.find(key);
  if (it == object.end()) throw Error(Errc::parse, where + ": missing \"" + key + "\"");
  return *it;
}

// A positive integer up to `max`: a card's sizes are bounded where they are read, so that no edited card can ask the
// detector for a canvas or a person count no machine holds.
int positive_int(const json& object, const char* key, const std::string& where, int max) {
  const json& v = member(object, key, where);
  if (!v.is_number_integer() || v.get<int64_t>() <= 0 || v.get<int64_t>() > max)
    throw Error(Errc::parse, where + ": \"" + key + "\" must be a whole number from 1 to " + std::to_string(max));
  return v.get<int>();
}

// Network inputs beyond 4096 pixels a side exist nowhere in pose estimation (MoveNet takes 192-256, RTMPose 384).
constexpr int kMaxInputSide = 4096;

std::array<float, 3> triple(const json& object, const char* key, const std::string& where, float fallback) {
  auto it = object.find(key);
  if (it == object.end()) return {fallback, fallback, fallback};
  if (!it->is_array() || it->size() != 3) throw Error(Errc::parse, where + ": \"" + key + "\" must be 3 numbers");
  return {(*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>()};
}

template <typename T>
T choice(const json& object, const char* key, const std::string& where,
         std::initializer_list<std::pair<const char*, T>> options) {
  const json& v = member(object, key, where);
  std::string allowed;
  if (v.is_string())
    for (const auto& [name, value] : options)
      if (v.get<std::string>() == name) return value;
  for (const auto& o : options) allowed += std::string(allowed.empty() ? "" : ", ") + o.first;
  throw Error(Errc::parse, where + ": \"" + key + "\" must be one of " + allowed);
}

}  // namespace

const char* output_kind_name(OutputKind kind) {
  switch (kind) {
    case OutputKind::movenet: return "movenet";
    case OutputKind::movenet_multipose: return "movenet_multipose";
    case OutputKind::heatmap: return "heatmap";
    case OutputKind::simcc: return "simcc";
    case OutputKind::yolo_pose: return "yolo_pose";
    case OutputKind::blazepose: return "blazepose";
  }
  return "?";
}

std::string model_card_path(const std::string& model_path) {
  const size_t dot = model_path.rfind('.');
  const size_t slash = model_path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return model_path + ".json";
  return model_path.substr(0, dot) + ".json";
}

ModelCard read_model_card(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(Errc::io, "cannot open model card " + path + " (every .onnx needs one beside it, see models/README.md)");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    throw Error(Errc::parse, path + ": not JSON: " + e.what());
  }
  try {
    ModelCard card;
    card.name = doc.value("name", std::string("model"));
    const std::string layout = member(doc, "keypoint_layout", path).get<std::string>();
    if (!layout_from_name(layout, &card.layout) || card.layout == LayoutId::automatic)
      throw Error(Errc::parse, path + ": unknown keypoint_layout \"" + layout + "\"");
    const std::string in_where = path + " input";
    const json& input = member(doc, "input", path);
    card.input_width = positive_int(input, "width", in_where, kMaxInputSide);
    card.input_height = positive_int(input, "height", in_where, kMaxInputSide);
    card.dynamic_size = input.value("dynamic_size", false);
    card.upright = input.value("upright", false);
    card.quantized = doc.value("quantized", false);
    card.size_multiple = input.contains("size_multiple") ? positive_int(input, "size_multiple", in_where, 1024) : 1;
    card.element = choice<ElementType>(input, "element_type", in_where,
                                       {{"int32", ElementType::int32}, {"uint8", ElementType::uint8}, {"float32", ElementType::float32}});
    card.nchw = choice<bool>(input, "tensor_layout", in_where, {{"NHWC", false}, {"NCHW", true}});
    card.bgr = choice<bool>(input, "channel_order", in_where, {{"RGB", false}, {"BGR", true}});
    card.mean = triple(input, "mean", in_where, 0.f);
    card.scale = triple(input, "scale", in_where, 1.f);
    const std::string out_where = path + " output";
    const json& output = member(doc, "output", path);
    card.output = choice<OutputKind>(output, "kind", out_where,
                                     {{"movenet", OutputKind::movenet}, {"movenet_multipose", OutputKind::movenet_multipose},
                                      {"heatmap", OutputKind::heatmap}, {"simcc", OutputKind::simcc}, {"yolo_pose", OutputKind::yolo_pose},
                                      {"blazepose", OutputKind::blazepose}});
    card.max_people = output.contains("max_people") ? positive_int(output, "max_people", out_where, 1000) : 1;
    card.simcc_ratio = output.value("simcc_ratio", 2.0);
    card.score_threshold = output.value("score_threshold", 0.25);
    card.lighter = doc.value("lighter", std::string());
    return card;
  } catch (const json::exception& e) {
    throw Error(Errc::parse, path + ": " + e.what());
  }
}

}  // namespace octocap::internal
