// Internal error type: C++ code throws it, the C boundary turns it into a result code + message.
#pragma once
#include <stdexcept>
#include <string>

namespace octocap::internal {

enum class Errc : int {
  invalid_argument = -1,
  invalid_handle = -2,
  struct_size = -3,
  io = -4,
  parse = -5,
  buffer_too_small = -6,
  camera_mismatch = -7,
  not_enough_views = -8,
  no_result = -9,
  unsupported = -10,
  out_of_memory = -11,
  internal = -99,
};

class Error : public std::runtime_error {
 public:
  Error(Errc code, const std::string& message) : std::runtime_error(message), code_(code) {}
  Errc code() const noexcept { return code_; }

 private:
  Errc code_;
};

}  // namespace octocap::internal
