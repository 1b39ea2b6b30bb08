#include "detect/pose_network.h"

#include <algorithm>
#include <thread>

#include "core/error.h"
#include "detect/ort_model.h"
#include "detect/ov_model.h"

namespace octocap::internal {

const char* runtime_name(Runtime r) {
  switch (r) {
    case Runtime::automatic: return "auto";
    case Runtime::onnxruntime: return "onnxruntime";
    case Runtime::openvino: return "openvino";
  }
  return "?";
}

const char* precision_name(Precision p) {
  switch (p) {
    case Precision::automatic: return "auto";
    case Precision::f32: return "f32";
    case Precision::reduced: return "reduced";
  }
  return "?";
}

std::unique_ptr<PoseNetwork> load_pose_network(const std::string& path, const ModelCard& card, const NetworkOptions& o) {
  if (o.runtime == Runtime::openvino && o.device != Device::cpu)
    throw Error(Errc::unsupported, "OpenVINO runs octocap's models on the CPU only: use device cpu, or runtime auto "
                                   "or onnxruntime for a GPU");
  if (o.runtime == Runtime::openvino && !have_openvino()) openvino_version();  // throws, saying why
  if (o.runtime == Runtime::onnxruntime && o.precision == Precision::reduced)
    throw Error(Errc::unsupported, "ONNX Runtime runs octocap's models in f32 only: reduced precision needs OpenVINO "
                                   "(runtime openvino or auto)");
  // Quantised models stay in ONNX Runtime, which they were quantised and calibrated with: OpenVINO ran the INT8
  // Thunder 16 px (median) from the float model's keypoints on zidane.jpg, ONNX Runtime 1-3 px.
  const bool openvino = o.runtime == Runtime::openvino || (o.runtime == Runtime::automatic && o.device == Device::cpu &&
                                                           have_openvino() && !card.quantized);
  if (openvino) {
    const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const int callers = std::max(1, o.callers);
    const int threads = o.threads > 0 ? o.threads * callers : std::max(cores, callers);
    return std::make_unique<OvModel>(path, card, threads, callers, o.precision);
  }
  if (o.precision == Precision::reduced)
    throw Error(Errc::unsupported, "reduced precision needs OpenVINO, which this octocap was built without");
  auto ort = std::make_unique<OrtModel>(path, card, o.threads, o.device != Device::cpu, o.device == Device::cuda);
  // A GPU asked for where none answered: the CPU then, and there OpenVINO is the faster of the two.
  if (!ort->on_gpu() && o.device == Device::automatic && o.runtime == Runtime::automatic && have_openvino()) {
    NetworkOptions cpu = o;
    cpu.device = Device::cpu;
    return load_pose_network(path, card, cpu);
  }
  return ort;
}

}  // namespace octocap::internal
