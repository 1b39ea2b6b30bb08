// One ONNX pose model compiled by OpenVINO for the CPU, fed from an RGB canvas as its card describes. The only file
// that includes OpenVINO's headers (its C API: the C++ one carries the C++ ABI of the wheel's toolchain).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "detect/pose_network.h"

namespace octocap::internal {

// "2026.4.0-..." from the loaded library; throws Error(unsupported) in a build without OpenVINO.
std::string openvino_version();
// Whether this build has OpenVINO.
bool have_openvino();

class OvModel final : public PoseNetwork {
 public:
  // threads: OpenVINO's inference threads in all (0 = all cores); streams: how many callers run at once (each gets
  // its own stream of threads/streams threads, so that parallel views do not queue behind each other).
  // Throws Error(io) for a missing file, Error(parse) for a model OpenVINO cannot read or compile, Error(invalid_argument)
  // for a model whose input does not fit the card.
  OvModel(const std::string& path, const ModelCard& card, int threads, int streams, Precision precision);
  ~OvModel() override;
  OvModel(const OvModel&) = delete;
  OvModel& operator=(const OvModel&) = delete;

  std::vector<Tensor> run(const RgbCanvas& canvas) override;
  bool on_gpu() const override { return false; }
  Runtime runtime() const override { return Runtime::openvino; }
  Precision precision() const override { return precision_; }

 private:
  struct Impl;
  ModelCard card_;
  Precision precision_ = Precision::f32;
  std::unique_ptr<Impl> impl_;
};

}  // namespace octocap::internal
