// RAII over the C ABI for tests, and a helper that builds a calibration handle from internal cameras.
#pragma once
#include <memory>
#include <vector>

#include "core/camera.h"
#include "octocap/octocap.h"

namespace testing {

struct CalibDeleter {
  void operator()(octocap_calibration_t* c) const { octocap_calibration_destroy(c); }
};
struct SessionDeleter {
  void operator()(octocap_session_t* s) const { octocap_session_destroy(s); }
};
using Calib = std::unique_ptr<octocap_calibration_t, CalibDeleter>;
using Session = std::unique_ptr<octocap_session_t, SessionDeleter>;

octocap_camera_t to_c_camera(const octocap::internal::Camera& cam);
Calib make_calibration(const octocap::internal::Calibration& cams);
Session make_session(const octocap_calibration_t* calib, const octocap_session_config_t& cfg);

}  // namespace testing
