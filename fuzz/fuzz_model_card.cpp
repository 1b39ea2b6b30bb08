// Model cards (the JSON beside each .onnx that tells octocap how to feed and decode it).
#include "core/error.h"
#include "detect/model_card.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = fuzz::write_input(data, size, ".json");
  try {
    octocap::internal::read_model_card(path);
  } catch (const octocap::internal::Error&) {
  }
  return 0;
}
