// Board specs ("checkerboard:COLSxROWS:SQUARE_M", "charuco:..."), as typed on a command line.
#include <string>

#include "calib/intrinsics.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const octocap::internal::BoardSpec b =
        octocap::internal::parse_board(std::string(reinterpret_cast<const char*>(data), size));
    if (b.cols < 2 || b.rows < 2 || !(b.square_m > 0)) __builtin_trap();  // accepted means usable
  } catch (const octocap::internal::Error&) {
  }
  return 0;
}
