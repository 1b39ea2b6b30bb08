// A build without ONNX Runtime (-DOCTOCAP_WITH_ONNX=OFF) says so, by name, wherever detection is asked for.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <string>
#include <vector>

#include "octocap/octocap.h"

using Catch::Matchers::ContainsSubstring;

TEST_CASE("without ONNX Runtime, detection is UNSUPPORTED with a clear message and the rest works", "[detect]") {
  CHECK(std::string(octocap_onnxruntime_version()).empty());
  octocap_detector_config_t cfg;
  octocap_detector_config_init(&cfg);
  octocap_detector_t* d = nullptr;
  CHECK(octocap_detector_create(&cfg, &d) == OCTOCAP_ERROR_UNSUPPORTED);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("ONNX"));
  CHECK(d == nullptr);
  octocap_calibration_t* calib = nullptr;
  REQUIRE(octocap_calibration_load((std::string(OCTOCAP_SOURCE_DIR) + "/data/sample/calibration.toml").c_str(), &calib) ==
          OCTOCAP_OK);
  octocap_session_config_t sc;
  octocap_session_config_init(&sc);
  sc.layout = OCTOCAP_LAYOUT_COCO_17;
  octocap_session_t* s = nullptr;
  REQUIRE(octocap_session_create(&sc, calib, &s) == OCTOCAP_OK);
  CHECK(octocap_session_set_detector(s, &cfg) == OCTOCAP_ERROR_UNSUPPORTED);
  std::vector<uint8_t> pixels(1280 * 720 * 3, 0);
  std::vector<octocap_image_t> views(5, octocap_image_t{pixels.data(), 1280, 720, 1280 * 3, OCTOCAP_PIXELS_RGB8});
  CHECK(octocap_session_solve_images(s, views.data(), 5, 0) == OCTOCAP_ERROR_UNSUPPORTED);
  octocap_session_destroy(s);
  octocap_calibration_destroy(calib);
}
