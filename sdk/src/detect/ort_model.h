// One ONNX pose model loaded in ONNX Runtime, fed from an RGB canvas as its card describes. The only file that
// includes ONNX Runtime's headers.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "detect/pose_network.h"

namespace octocap::internal {

// "1.32.0" from the loaded library; throws Error(unsupported) when the library is older than the headers octocap
// was built with (or the build has no ONNX Runtime).
std::string onnxruntime_version();

class OrtModel final : public PoseNetwork {
 public:
  // intra_threads: ONNX Runtime's intra-op threads (0 = its default, all cores). gpu: try ONNX Runtime's CUDA
  // execution provider first; required: fail (Error(unsupported), saying why) rather than fall back to the CPU.
  // Throws Error(io) for a missing file, Error(invalid_argument) for a model whose input does not fit the card.
  OrtModel(const std::string& path, const ModelCard& card, int intra_threads, bool gpu = false, bool gpu_required = false);
  ~OrtModel() override;
  OrtModel(const OrtModel&) = delete;
  OrtModel& operator=(const OrtModel&) = delete;

  std::vector<Tensor> run(const RgbCanvas& canvas) override;
  // Whether the network runs on the GPU (the CUDA execution provider took it).
  bool on_gpu() const override { return on_gpu_; }
  Runtime runtime() const override { return Runtime::onnxruntime; }
  Precision precision() const override { return Precision::f32; }

 private:
  struct Impl;
  ModelCard card_;
  bool on_gpu_ = false;
  std::unique_ptr<Impl> impl_;
};

}  // namespace octocap::internal
