// A pose network loaded in one inference back end: what the detector runs, whichever runtime holds it. The model
// card stays the one description of a model; a back end only turns a canvas into the network's output tensors.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "detect/decoders.h"
#include "detect/image.h"
#include "detect/model_card.h"

namespace octocap::internal {

// The inference back end (octocap_runtime_t). automatic: OpenVINO on the CPU where the build has it (measured
// faster at the same keypoints, docs/detecting.md "Inference back ends"), ONNX Runtime for a GPU, a quantised
// model, or where OpenVINO is absent.
enum class Runtime : int { automatic = 0, onnxruntime = 1, openvino = 2 };
// The arithmetic the network runs in (octocap_precision_t). automatic: f32 (measured: bf16 moves keypoints by pixels
// on real photos); reduced: bf16 where the back end and CPU have it (OpenVINO on AVX-512 BF16 / AMX CPUs; elsewhere
// OpenVINO keeps f32 and says so through precision()).
enum class Precision : int { automatic = 0, f32 = 1, reduced = 2 };

// Where the network runs (octocap_device_t): auto is the GPU when there is one, else the CPU.
enum class Device : int { cpu = 0, automatic = 1, cuda = 2 };

const char* runtime_name(Runtime r);
const char* precision_name(Precision p);

class PoseNetwork {
 public:
  virtual ~PoseNetwork() = default;
  // Runs the network on `canvas` (its size must be the card's, or any multiple of size_multiple for dynamic
  // models) and returns every output as float. Safe to call from several threads at once.
  virtual std::vector<Tensor> run(const RgbCanvas& canvas) = 0;
  virtual bool on_gpu() const = 0;
  virtual Runtime runtime() const = 0;
  // The precision it runs in, resolved (f32 or reduced).
  virtual Precision precision() const = 0;
};

struct NetworkOptions {
  Runtime runtime = Runtime::automatic;
  Precision precision = Precision::automatic;
  Device device = Device::cpu;
  int threads = 0;   // inference threads of one caller; 0: the back end's default (all cores)
  int callers = 1;   // how many threads call run() at once
};

// The network at `path` in the back end the options choose (see Runtime::automatic). Throws Error(unsupported) for
// a back end this build lacks or a combination it cannot run (OpenVINO on a GPU, ONNX Runtime in reduced
// precision), and what the back end throws for a missing or unfit model.
std::unique_ptr<PoseNetwork> load_pose_network(const std::string& path, const ModelCard& card, const NetworkOptions& o);

}  // namespace octocap::internal
