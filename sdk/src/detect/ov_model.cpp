#include "detect/ov_model.h"

#include <sys/stat.h>

#include <mutex>
#include <string>
#include <vector>

#include "core/error.h"
#include "detect/network_input.h"

#ifdef OCTOCAP_HAVE_OPENVINO
#include <openvino/c/openvino.h>
#endif

namespace octocap::internal {

#ifdef OCTOCAP_HAVE_OPENVINO
namespace {

// OpenVINO's own words for a failed call (its C API keeps the last message per thread).
std::string ov_message(ov_status_e status) {
  const char* last = ov_get_last_err_msg();
  std::string why = last && *last ? last : ov_get_error_info(status);
  while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
  return why;
}

void check(ov_status_e status, Errc errc, const std::string& what) {
  if (status != OK) throw Error(errc, what + ": OpenVINO says: " + ov_message(status));
}

// One core per process: its plugins are loaded once (a core per model would load the CPU plugin per detector).
ov_core_t* ov_core() {
  static std::once_flag once;
  static ov_core_t* core = nullptr;
  static ov_status_e status = OK;
  std::call_once(once, [] { status = ov_core_create(&core); });
  if (status != OK) throw Error(Errc::unsupported, "OpenVINO cannot start: " + ov_message(status));
  return core;
}

ov_element_type_e element_of(ElementType e) {
  switch (e) {
    case ElementType::int32: return I32;
    case ElementType::uint8: return U8;
    case ElementType::float32: return F32;
  }
  return F32;
}

template <class T, void (*Free)(T*)>
struct Owned {
  T* p = nullptr;
  ~Owned() {
    if (p) Free(p);
  }
};

}  // namespace

bool have_openvino() { return true; }

std::string openvino_version() {
  ov_version_t v{};
  if (ov_get_openvino_version(&v) != OK) return "?";
  std::string s = v.buildNumber ? v.buildNumber : "?";
  ov_version_free(&v);
  return s;
}

struct OvModel::Impl {
  ov_compiled_model_t* compiled = nullptr;
  size_t outputs = 0;
  // Infer requests not in use: a request runs one inference at a time; a caller takes one (or makes one) per run.
  std::mutex pool_mutex;
  std::vector<ov_infer_request_t*> idle;
  ~Impl() {
    for (ov_infer_request_t* r : idle) ov_infer_request_free(r);
    if (compiled) ov_compiled_model_free(compiled);
  }
};

OvModel::OvModel(const std::string& path, const ModelCard& card, int threads, int streams, Precision precision)
    : card_(card) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) throw Error(Errc::io, "model file not found: " + path);
  ov_core_t* core = ov_core();
  impl_ = std::make_unique<Impl>();
  Owned<ov_model_t, ov_model_free> model;
  check(ov_core_read_model(core, path.c_str(), nullptr, &model.p), Errc::parse, path + ": OpenVINO cannot read it");
  size_t inputs = 0;
  check(ov_model_inputs_size(model.p, &inputs), Errc::parse, path);
  if (inputs != 1)
    throw Error(Errc::invalid_argument, path + ": a pose model needs exactly one input, this one has " +
                                            std::to_string(inputs));
  {
    Owned<ov_output_const_port_t, ov_output_const_port_free> port;
    check(ov_model_const_input(model.p, &port.p), Errc::parse, path);
    ov_element_type_e type = DYNAMIC;
    check(ov_port_get_element_type(port.p, &type), Errc::parse, path);
    if (type != element_of(card.element))
      throw Error(Errc::invalid_argument, path + ": the model's input element type differs from its card's \"element_type\"");
    ov_partial_shape_t shape{};
    check(ov_port_get_partial_shape(port.p, &shape), Errc::parse, path);
    const int64_t rank = shape.rank.max;
    std::vector<int64_t> dims;
    for (int64_t i = 0; i < rank && shape.dims; ++i)
      dims.push_back(shape.dims[i].min == shape.dims[i].max ? shape.dims[i].min : -1);
    ov_partial_shape_free(&shape);
    check_model_input(path, card, dims);
  }
  // LATENCY with a stream per concurrent caller: each view's inference runs on its share of the cores, none waits
  // for another's. No pinning: the threads share the machine with the cameras' decoders and the solver.
  const std::string nthreads = std::to_string(std::max(0, threads));
  const std::string nstreams = std::to_string(std::max(1, streams));
  // automatic is f32: the CPU plugin's own default (bf16 on CPUs with AVX-512 BF16 or AMX) moved MoveNet Thunder's
  // confident keypoints by 1-9 px on real photos and lost a player's hips on zidane.jpg, where f32 gives ONNX
  // Runtime's keypoints to a hundredth of a pixel. bf16 stays a choice (reduced) for who wants the time.
  const char* hint = precision == Precision::reduced ? "bf16" : "f32";
  const ov_status_e status = ov_core_compile_model(
      core, model.p, "CPU", 10, &impl_->compiled, ov_property_key_hint_performance_mode, "LATENCY",
      ov_property_key_num_streams, nstreams.c_str(), ov_property_key_inference_num_threads, nthreads.c_str(),
      ov_property_key_hint_enable_cpu_pinning, "NO", ov_property_key_hint_inference_precision, hint);
  check(status, Errc::parse, path + ": OpenVINO cannot compile it for the CPU");
  check(ov_compiled_model_outputs_size(impl_->compiled, &impl_->outputs), Errc::parse, path);
  // What the CPU plugin chose: bf16 where the CPU has it (AVX-512 BF16, AMX), else f32 whatever was asked.
  char* chosen = nullptr;
  if (ov_compiled_model_get_property(impl_->compiled, ov_property_key_hint_inference_precision, &chosen) == OK && chosen) {
    const std::string p = chosen;
    ov_free(chosen);
    precision_ = p == "f32" ? Precision::f32 : Precision::reduced;
  }
}

OvModel::~OvModel() = default;

std::vector<Tensor> OvModel::run(const RgbCanvas& canvas) {
  InputTensor input = fill_input(card_, canvas);
  const std::vector<int64_t> dims = input_shape(card_, canvas);
  ov_infer_request_t* request = nullptr;
  {
    std::lock_guard<std::mutex> lock(impl_->pool_mutex);
    if (!impl_->idle.empty()) {
      request = impl_->idle.back();
      impl_->idle.pop_back();
    }
  }
  if (!request)
    check(ov_compiled_model_create_infer_request(impl_->compiled, &request), Errc::invalid_argument,
          "model " + card_.name + ": no infer request");
  // Back to the pool whatever happens below.
  struct Return {
    Impl& impl;
    ov_infer_request_t* r;
    ~Return() {
      std::lock_guard<std::mutex> lock(impl.pool_mutex);
      impl.idle.push_back(r);
    }
  } give_back{*impl_, request};
  const std::string where = "model " + card_.name + " failed on a " + std::to_string(canvas.width) + "x" +
                            std::to_string(canvas.height) + " input";
  ov_shape_t shape{};
  check(ov_shape_create(4, dims.data(), &shape), Errc::invalid_argument, where);
  Owned<ov_tensor_t, ov_tensor_free> tensor;
  const ov_status_e made = ov_tensor_create_from_host_ptr(element_of(card_.element), shape, input.data(), &tensor.p);
  ov_shape_free(&shape);
  check(made, Errc::invalid_argument, where);
  check(ov_infer_request_set_input_tensor(request, tensor.p), Errc::invalid_argument, where);
  check(ov_infer_request_infer(request), Errc::invalid_argument, where);
  std::vector<Tensor> result;
  for (size_t i = 0; i < impl_->outputs; ++i) {
    Owned<ov_tensor_t, ov_tensor_free> out;
    check(ov_infer_request_get_output_tensor_by_index(request, i, &out.p), Errc::invalid_argument, where);
    ov_shape_t s{};
    check(ov_tensor_get_shape(out.p, &s), Errc::invalid_argument, where);
    Tensor t;
    t.shape.assign(s.dims, s.dims + s.rank);
    ov_shape_free(&s);
    size_t count = 0;
    ov_element_type_e type = DYNAMIC;
    void* data = nullptr;
    check(ov_tensor_get_size(out.p, &count), Errc::invalid_argument, where);
    check(ov_tensor_get_element_type(out.p, &type), Errc::invalid_argument, where);
    check(ov_tensor_data(out.p, &data), Errc::invalid_argument, where);
    t.data.resize(count);
    switch (type) {
      case F32: std::copy_n(static_cast<const float*>(data), count, t.data.begin()); break;
      case I32: std::copy_n(static_cast<const int32_t*>(data), count, t.data.begin()); break;
      case I64: std::copy_n(static_cast<const int64_t*>(data), count, t.data.begin()); break;
      default: throw Error(Errc::invalid_argument, "model " + card_.name + " has an output that is not float/int");
    }
    result.push_back(std::move(t));
  }
  return result;
}

#else  // built without OpenVINO

bool have_openvino() { return false; }
std::string openvino_version() {
  throw Error(Errc::unsupported, "this octocap was built without OpenVINO (OCTOCAP_WITH_OPENVINO=OFF)");
}
struct OvModel::Impl {};
OvModel::OvModel(const std::string&, const ModelCard& card, int, int, Precision) : card_(card) { openvino_version(); }
OvModel::~OvModel() = default;
std::vector<Tensor> OvModel::run(const RgbCanvas&) { return {}; }

#endif

}  // namespace octocap::internal
