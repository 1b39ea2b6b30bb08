#include "detect/ort_model.h"

#include <dirent.h>
#include <dlfcn.h>
#include <sys/stat.h>

#include <mutex>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/log.h"
#include "detect/network_input.h"

#ifdef OCTOCAP_HAVE_ONNXRUNTIME
// Manual init: the C++ wrapper otherwise asks for the API at static-initialisation time and crashes (null
// table) when the library is older than the headers. Here that becomes a clear error instead.
#define ORT_API_MANUAL_INIT
#include <onnxruntime_cxx_api.h>
#endif

namespace octocap::internal {

#ifdef OCTOCAP_HAVE_ONNXRUNTIME
namespace {

const OrtApi& ort_api() {
  static std::once_flag once;
  static const OrtApi* api = nullptr;
  std::call_once(once, [] {
    api = OrtGetApiBase()->GetApi(ORT_API_VERSION);
    if (api) Ort::InitApi(api);
  });
  if (!api)
    throw Error(Errc::unsupported, std::string("the ONNX Runtime library (") + OrtGetApiBase()->GetVersionString() +
                                       ") is older than the headers octocap was built with (API " +
                                       std::to_string(ORT_API_VERSION) + "); install a newer libonnxruntime");
  return *api;
}

Ort::Env& ort_env() {
  ort_api();
  static Ort::Env env(ORT_LOGGING_LEVEL_ERROR, "octocap");
  return env;
}

}  // namespace

std::string onnxruntime_version() {
  ort_api();
  return OrtGetApiBase()->GetVersionString();
}

struct OrtModel::Impl {
  Ort::Session session{nullptr};
  std::string input_name;
  std::vector<std::string> output_names;
  ONNXTensorElementDataType input_type = ONNX_TENSOR_ELEMENT_DATA_TYPE_FLOAT;
};

// The directory the loaded libonnxruntime is in ("" when unknown), with its trailing slash.
static std::string ort_directory() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&OrtGetApiBase), &info) || !info.dli_fname) return "";
  const std::string path = info.dli_fname;
  return path.substr(0, path.find_last_of('/') + 1);
}

// Why the CUDA provider is not there, in the user's terms, when it can be told: ONNX Runtime's own message is only
// "Failed to load shared library".
static std::string cuda_diagnosis() {
  const std::string dir = ort_directory();
  if (dir.empty()) return "";
  const std::string provider = dir + "libonnxruntime_providers_cuda.so";
  struct stat st {};
  if (stat(provider.c_str(), &st) != 0) return "the ONNX Runtime in " + dir + " is the CPU build";
  void* handle = dlopen(provider.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    return std::string("its CUDA provider cannot load (") + (why ? why : "?") + "; libcuda.so.1 comes with the NVIDIA driver)";
  }
  dlclose(handle);
  return "";
}

// The GPU build of ONNX Runtime (scripts/fetch-onnxruntime.sh --gpu) keeps the CUDA libraries its CUDA provider needs
// (cuBLAS, cuDNN, ... from NVIDIA's PyPI wheels) beside libonnxruntime. The provider finds them only on the loader's
// path, so they are loaded here first, from that directory, the way ONNX Runtime's Python package preloads them:
// nobody has to set LD_LIBRARY_PATH. Some need others: passes until none more loads. Nothing there: nothing done.
static void preload_cuda_libraries() {
  static std::once_flag once;
  std::call_once(once, [] {
    const std::string dir = ort_directory();
    if (dir.empty()) return;
    std::vector<std::string> pending;
    if (DIR* d = opendir(dir.c_str())) {
      while (const dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if ((name.rfind("libcu", 0) == 0 || name.rfind("libnv", 0) == 0) && name.find(".so") != std::string::npos)
          pending.push_back(dir + name);
      }
      closedir(d);
    }
    for (bool progress = true; progress && !pending.empty();) {
      progress = false;
      for (auto it = pending.begin(); it != pending.end();)
        if (dlopen(it->c_str(), RTLD_NOW | RTLD_GLOBAL)) {
          it = pending.erase(it);
          progress = true;
        } else {
          ++it;
        }
    }
  });
}

// Asks ONNX Runtime to run the session on the first CUDA GPU. Throws Ort::Exception when it cannot: a CPU-only
// library ("not enabled in this build"), the provider library or a CUDA library it needs missing, no GPU.
static void append_cuda(Ort::SessionOptions& options) {
  const OrtApi& api = ort_api();
  preload_cuda_libraries();
  OrtCUDAProviderOptionsV2* cuda = nullptr;
  Ort::ThrowOnError(api.CreateCUDAProviderOptions(&cuda));
  std::unique_ptr<OrtCUDAProviderOptionsV2, void (*)(OrtCUDAProviderOptionsV2*)> owned(cuda, api.ReleaseCUDAProviderOptions);
  Ort::ThrowOnError(api.SessionOptionsAppendExecutionProvider_CUDA_V2(options, cuda));
}

OrtModel::OrtModel(const std::string& path, const ModelCard& card, int intra_threads, bool gpu, bool gpu_required)
    : card_(card) {
  // The API first: an Impl (its Ort::Session) must never be destroyed before the API table exists, or its
  // destructor calls through a null table (the first detector of a process, given a card without its model).
  Ort::Env& env = ort_env();
  struct stat st {};
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) throw Error(Errc::io, "model file not found: " + path);
  impl_ = std::make_unique<Impl>();
  try {
    auto make_options = [&] {
      Ort::SessionOptions options;
      options.SetIntraOpNumThreads(intra_threads);
      options.SetInterOpNumThreads(1);
      options.SetGraphOptimizationLevel(GraphOptimizationLevel::ORT_ENABLE_ALL);
      return options;
    };
    std::string gpu_failure;
    if (gpu) {
      // The GPU may fail when the provider is appended (no CUDA provider, a CUDA library missing) or only when the
      // session starts on it (no device): either way the CPU session below, unless the GPU was required.
      try {
        Ort::SessionOptions options = make_options();
        append_cuda(options);
        impl_->session = Ort::Session(env, path.c_str(), options);
        on_gpu_ = true;
      } catch (const Ort::Exception& e) {
        const std::string diagnosis = cuda_diagnosis();
        gpu_failure = diagnosis.empty() ? e.what() : diagnosis + "; ONNX Runtime says: " + e.what();
      }
      if (!on_gpu_ && gpu_required)
        throw Error(Errc::unsupported, "no GPU for model " + card.name + " (ONNX Runtime " +
                                           OrtGetApiBase()->GetVersionString() + "): " + gpu_failure +
                                           " (the GPU build of ONNX Runtime comes with scripts/install-deps.sh --gpu)");
      if (!on_gpu_)
        log(LogLevel::warning, "model " + card.name + " runs on the CPU: no GPU (" + gpu_failure + ")");
    }
    if (!on_gpu_) impl_->session = Ort::Session(env, path.c_str(), make_options());
    Ort::AllocatorWithDefaultOptions alloc;
    if (impl_->session.GetInputCount() != 1)
      throw Error(Errc::invalid_argument, path + ": a pose model needs exactly one input, this one has " +
                                              std::to_string(impl_->session.GetInputCount()));
    impl_->input_name = impl_->session.GetInputNameAllocated(0, alloc).get();
    for (size_t i = 0; i < impl_->session.GetOutputCount(); ++i)
      impl_->output_names.emplace_back(impl_->session.GetOutputNameAllocated(i, alloc).get());
    const Ort::TypeInfo type_info = impl_->session.GetInputTypeInfo(0);  // owns what `info` views
    auto info = type_info.GetTensorTypeAndShapeInfo();
    impl_->input_type = info.GetElementType();
    const ONNXTensorElementDataType want = card.element == ElementType::int32   ? ONNX_TENSOR_ELEMENT_DATA_TYPE_INT32
                                           : card.element == ElementType::uint8 ? ONNX_TENSOR_ELEMENT_DATA_TYPE_UINT8
                                                                                : ONNX_TENSOR_ELEMENT_DATA_TYPE_FLOAT;
    if (impl_->input_type != want)
      throw Error(Errc::invalid_argument, path + ": the model's input element type (" +
                                              std::to_string(static_cast<int>(impl_->input_type)) +
                                              ") differs from its card's \"element_type\"");
    const auto shape = info.GetShape();
    check_model_input(path, card, shape);
  } catch (const Ort::Exception& e) {
    throw Error(Errc::parse, path + ": ONNX Runtime cannot load it: " + e.what());
  }
}

OrtModel::~OrtModel() = default;

std::vector<Tensor> OrtModel::run(const RgbCanvas& canvas) {
  // Per call, not per model: views may run on several threads at once (Ort::Session::Run is thread-safe).
  InputTensor tensor = fill_input(card_, canvas);
  const std::vector<int64_t> shape = input_shape(card_, canvas);
  const int W = canvas.width, H = canvas.height;
  const size_t n = static_cast<size_t>(W) * H * 3;
  Ort::MemoryInfo memory = Ort::MemoryInfo::CreateCpu(OrtArenaAllocator, OrtMemTypeDefault);
  Ort::Value input{nullptr};
  switch (card_.element) {
    case ElementType::int32:
      input = Ort::Value::CreateTensor<int32_t>(memory, tensor.i32.data(), n, shape.data(), shape.size());
      break;
    case ElementType::uint8:
      input = Ort::Value::CreateTensor<uint8_t>(memory, tensor.u8.data(), n, shape.data(), shape.size());
      break;
    case ElementType::float32:
      input = Ort::Value::CreateTensor<float>(memory, tensor.f32.data(), n, shape.data(), shape.size());
      break;
  }
  std::vector<const char*> names;
  for (const auto& s : impl_->output_names) names.push_back(s.c_str());
  const char* input_name = impl_->input_name.c_str();
  std::vector<Ort::Value> outputs;
  try {
    outputs = impl_->session.Run(Ort::RunOptions{nullptr}, &input_name, &input, 1, names.data(), names.size());
  } catch (const Ort::Exception& e) {
    throw Error(Errc::invalid_argument, "model " + card_.name + " failed on a " + std::to_string(W) + "x" +
                                            std::to_string(H) + " input: " + e.what());
  }
  std::vector<Tensor> result;
  for (Ort::Value& v : outputs) {
    if (!v.IsTensor()) throw Error(Errc::invalid_argument, "model " + card_.name + " has a non-tensor output");
    auto info = v.GetTensorTypeAndShapeInfo();
    Tensor t;
    t.shape = info.GetShape();
    const size_t count = info.GetElementCount();
    t.data.resize(count);
    switch (info.GetElementType()) {
      case ONNX_TENSOR_ELEMENT_DATA_TYPE_FLOAT: std::copy_n(v.GetTensorData<float>(), count, t.data.begin()); break;
      case ONNX_TENSOR_ELEMENT_DATA_TYPE_INT32: std::copy_n(v.GetTensorData<int32_t>(), count, t.data.begin()); break;
      case ONNX_TENSOR_ELEMENT_DATA_TYPE_INT64: std::copy_n(v.GetTensorData<int64_t>(), count, t.data.begin()); break;
      default: throw Error(Errc::invalid_argument, "model " + card_.name + " has an output that is not float/int");
    }
    result.push_back(std::move(t));
  }
  return result;
}

#else  // built without ONNX Runtime

std::string onnxruntime_version() {
  throw Error(Errc::unsupported, "this octocap was built without ONNX Runtime (OCTOCAP_WITH_ONNX=OFF)");
}
struct OrtModel::Impl {};
OrtModel::OrtModel(const std::string&, const ModelCard& card, int, bool, bool) : card_(card) { onnxruntime_version(); }
OrtModel::~OrtModel() = default;
std::vector<Tensor> OrtModel::run(const RgbCanvas&) { return {}; }

#endif

}  // namespace octocap::internal
