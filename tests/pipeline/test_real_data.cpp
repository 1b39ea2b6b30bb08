// Real data: Pose2Sim's demo (4 real calibrated cameras, real OpenPose BODY_25B detections with a bystander),
// fetched by scripts/fetch-real-data.sh. Compared with Pose2Sim's published figures and its own 3D output
// (not ground truth: a peer's answer on the same input).
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "io/motion_files.h"
#include "octocap/octocap.h"
#include "support/capi_helpers.h"
#include "support/pose2sim_reference.h"

namespace {

const std::string kDemo = std::string(OCTOCAP_REAL_DATA_DIR) + "/Demo";

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

TEST_CASE("Pose2Sim's real demo solves as well as Pose2Sim does", "[real]") {
  INFO("real data missing: run scripts/fetch-real-data.sh (scripts/test.sh does)");
  REQUIRE(std::filesystem::exists(kDemo + "/calibration/Calib_qualisys.toml"));
  octocap_calibration_t* c = nullptr;
  REQUIRE(octocap_calibration_load((kDemo + "/calibration/Calib_qualisys.toml").c_str(), &c) == OCTOCAP_OK);
  testing::Calib calib(c);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open((kDemo + "/pose").c_str(), OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK);
  std::unique_ptr<octocap_recording_t, void (*)(octocap_recording_t*)> rec_guard(rec, octocap_recording_destroy);
  octocap_layout_t layout;
  REQUIRE(octocap_recording_layout(rec, &layout) == OCTOCAP_OK);
  REQUIRE(layout == OCTOCAP_LAYOUT_BODY_25B);  // told apart from BODY_25 by geometry
  uint32_t frames = 0, views = 0;
  REQUIRE(octocap_recording_frame_count(rec, &frames) == OCTOCAP_OK);
  REQUIRE(octocap_recording_view_count(rec, &views) == OCTOCAP_OK);
  REQUIRE(frames == 100);
  REQUIRE(views == 4);

  for (octocap_method_t method : {OCTOCAP_METHOD_SUBDIVISION, OCTOCAP_METHOD_TRIANGULATION}) {
    INFO("method " << method);
    octocap_session_config_t cfg;
    octocap_session_config_init(&cfg);
    cfg.layout = layout;
    cfg.method = method;
    cfg.filter = OCTOCAP_FILTER_NONE;
    testing::Session s = testing::make_session(calib.get(), cfg);
    octocap_up_axis_t up;
    REQUIRE(octocap_session_up_axis(s.get(), &up) == OCTOCAP_OK);
    REQUIRE(up == OCTOCAP_UP_Z);  // Qualisys lab frame, found from the cameras alone
    std::vector<octocap_keypoint2d_t> buf(25 * 4 * 8);
    std::vector<uint32_t> people(4);
    testing::Pose2SimReference score(kDemo + "/opensim/Balancing_for_IK.trc", layout);
    for (uint32_t f = 0; f < frames; ++f) {
      uint32_t needed = 0;
      REQUIRE(octocap_recording_read_frame(rec, f, buf.data(), static_cast<uint32_t>(buf.size()), &needed,
                                           people.data(), 4) == OCTOCAP_OK);
      REQUIRE(octocap_session_solve_keypoints(s.get(), buf.data(), people.data(), 4, f * 16667) == OCTOCAP_OK);
      octocap_joint_t j[25];
      uint32_t n = 0;
      REQUIRE(octocap_session_get_keypoints3d(s.get(), j, 25, &n) == OCTOCAP_OK);
      score.add(f, j);
    }
    const size_t solved = score.solved;
    const double med_px = median(score.reprojection_px), med_mm = 1000 * median(score.distance_m);
    INFO("solved " << solved << "/2500, median reprojection " << med_px << " px, median distance to Pose2Sim "
                   << med_mm << " mm");
    CHECK(solved > 0.95 * 2500);
    CHECK(med_px <= 10.7);  // Pose2Sim's median on these frames
    CHECK(med_mm < 40.0);   // "within a few cm" of Pose2Sim's own 3D
  }
}
