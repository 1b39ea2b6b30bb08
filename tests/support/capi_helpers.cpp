#include "capi_helpers.h"

#include <catch2/catch_test_macros.hpp>
#include <cstring>

namespace testing {

octocap_camera_t to_c_camera(const octocap::internal::Camera& cam) {
  octocap_camera_t c{};
  std::strncpy(c.name, cam.name.c_str(), sizeof c.name - 1);
  c.width = static_cast<uint32_t>(cam.width);
  c.height = static_cast<uint32_t>(cam.height);
  for (int i = 0; i < 9; ++i) c.matrix[i] = cam.K(i / 3, i % 3);
  for (int i = 0; i < 5; ++i) c.distortion[i] = cam.dist[i];
  const Eigen::Vector3d r = octocap::internal::matrix_to_rodrigues(cam.R);
  for (int i = 0; i < 3; ++i) {
    c.rotation[i] = r[i];
    c.translation[i] = cam.t[i];
  }
  return c;
}

Calib make_calibration(const octocap::internal::Calibration& cams) {
  std::vector<octocap_camera_t> c;
  for (const auto& cam : cams) c.push_back(to_c_camera(cam));
  octocap_calibration_t* out = nullptr;
  REQUIRE(octocap_calibration_create(c.data(), static_cast<uint32_t>(c.size()), &out) == OCTOCAP_OK);
  return Calib(out);
}

Session make_session(const octocap_calibration_t* calib, const octocap_session_config_t& cfg) {
  octocap_session_t* s = nullptr;
  const octocap_result_t r = octocap_session_create(&cfg, calib, &s);
  INFO(octocap_last_error());
  REQUIRE(r == OCTOCAP_OK);
  return Session(s);
}

}  // namespace testing
