#include "onnx_writer.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace testing {
namespace {

// Protobuf wire format: a key is (field << 3) | type; type 0 = varint, 2 = length-delimited.
struct Message {
  std::string bytes;
  void varint(uint64_t v) {
    while (v >= 0x80) {
      bytes.push_back(static_cast<char>((v & 0x7f) | 0x80));
      v >>= 7;
    }
    bytes.push_back(static_cast<char>(v));
  }
  Message& integer(int field, uint64_t v) {
    varint(static_cast<uint64_t>(field) << 3);
    varint(v);
    return *this;
  }
  Message& string(int field, const std::string& s) {
    varint((static_cast<uint64_t>(field) << 3) | 2);
    varint(s.size());
    bytes += s;
    return *this;
  }
  Message& message(int field, const Message& m) { return string(field, m.bytes); }
};

// ValueInfoProto of a float tensor with a fixed shape.
Message tensor_value(const std::string& name, const std::vector<int64_t>& dims) {
  Message shape;
  for (int64_t d : dims) shape.message(1, Message().integer(1, static_cast<uint64_t>(d)));  // Dimension.dim_value
  Message tensor;
  tensor.integer(1, 1).message(2, shape);  // TypeProto.Tensor: elem_type FLOAT, shape
  Message type;
  type.message(1, tensor);  // TypeProto.tensor_type
  Message value;
  value.string(1, name).message(2, type);
  return value;
}

}  // namespace

void write_conv1x1_model(const std::string& path, int width, int height, int out_channels,
                         const std::vector<float>& weights) {
  if (weights.size() != static_cast<size_t>(out_channels) * 3) throw std::invalid_argument("weights: out_channels x 3");
  Message w;  // TensorProto
  for (int64_t d : {static_cast<int64_t>(out_channels), int64_t{3}, int64_t{1}, int64_t{1}}) w.integer(1, static_cast<uint64_t>(d));
  w.integer(2, 1);  // FLOAT
  w.string(8, "weights");
  std::string raw(weights.size() * sizeof(float), '\0');
  std::memcpy(raw.data(), weights.data(), raw.size());  // little-endian, as ONNX's raw_data requires
  w.string(9, raw);

  Message node;
  node.string(1, "image").string(1, "weights").string(2, "heatmaps").string(3, "conv").string(4, "Conv");
  Message graph;
  graph.message(1, node).string(2, "octocap_test_conv1x1").message(5, w);
  graph.message(11, tensor_value("image", {1, 3, height, width}));
  graph.message(12, tensor_value("heatmaps", {1, out_channels, height, width}));
  Message opset;
  opset.string(1, "").integer(2, 13);
  Message model;
  model.integer(1, 8).string(2, "octocap-tests").message(7, graph).message(8, opset);
  std::ofstream out(path, std::ios::binary);
  out.write(model.bytes.data(), static_cast<std::streamsize>(model.bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace testing
