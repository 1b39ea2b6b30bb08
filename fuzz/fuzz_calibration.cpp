// The calibration TOML reader, through the C ABI as a user calls it, then every query of what it accepted.
#include "fuzz_support.h"
#include "octocap/octocap.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = fuzz::write_input(data, size, ".toml");
  octocap_calibration_t* calib = nullptr;
  if (octocap_calibration_load(path.c_str(), &calib) != OCTOCAP_OK) return 0;
  uint32_t n = 0;
  octocap_calibration_camera_count(calib, &n);
  for (uint32_t i = 0; i < n; ++i) {
    octocap_camera_t cam;
    octocap_calibration_get_camera(calib, i, &cam);
    const double world[3] = {0.1, 1.0, 0.2};
    double px[2];
    octocap_calibration_project(calib, i, world, px);
  }
  octocap_calibration_save(calib, (path + ".out").c_str());
  octocap_calibration_t* back = nullptr;
  if (octocap_calibration_load((path + ".out").c_str(), &back) == OCTOCAP_OK) {
    uint32_t m = 0;
    octocap_calibration_camera_count(back, &m);
    if (m != n) __builtin_trap();  // what was written must read back
  }
  octocap_calibration_destroy(back);
  octocap_calibration_destroy(calib);
  return 0;
}
