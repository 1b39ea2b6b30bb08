// The OpenPose JSON reader (one file per camera and frame: the most exposed input of all).
#include "core/error.h"
#include "fuzz_support.h"
#include "io/openpose_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = fuzz::write_input(data, size, ".json");
  try {
    for (size_t count : {size_t{0}, size_t{25}}) octocap::internal::read_openpose_file(path, count);
  } catch (const octocap::internal::Error&) {
  }
  return 0;
}
