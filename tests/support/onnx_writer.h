// Writes tiny ONNX models for the tests, straight in protobuf's wire format (onnx.proto field numbers), so a test
// knows exactly what the network computes: one 1x1 convolution mapping the 3 input channels to heatmaps.
#pragma once
#include <string>
#include <vector>

namespace testing {

// A model with input "image" float [1,3,height,width] (NCHW) and output "heatmaps" float [1,out_channels,height,
// width] = a 1x1 Conv whose weights are `weights` (out_channels x 3, row-major), no bias.
void write_conv1x1_model(const std::string& path, int width, int height, int out_channels,
                         const std::vector<float>& weights);

}  // namespace testing
