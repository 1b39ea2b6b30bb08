// Bad input through the public C ABI: the right error code, a message, and a session that still works.
#include <algorithm>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "octocap/octocap.h"
#include "support/capi_helpers.h"
#include "support/temp_dir.h"
#include "synth.h"

using Catch::Matchers::ContainsSubstring;

namespace {

struct Fixture {
  octocap::internal::Calibration cams = octocap::internal::synth::make_camera_ring({});
  testing::Calib calib = testing::make_calibration(cams);
  octocap_session_config_t cfg{};
  testing::Session session;
  std::vector<octocap_keypoint2d_t> frame;  // a good frame: one person per view, BODY_25

  Fixture() {
    octocap_session_config_init(&cfg);
    session = testing::make_session(calib.get(), cfg);
    const auto motion = octocap::internal::synth::load_cmu_motion(octocap::internal::synth::default_bvh_path(), 0, 1, 1);
    std::mt19937 rng(1);
    const auto views = octocap::internal::synth::observe(cams, motion.frames[0], octocap::internal::LayoutId::body25, {0.5, 0, 0, 0}, rng);
    for (const auto& v : views)
      for (const auto& k : v.at(0))
        frame.push_back({static_cast<float>(k.x), static_cast<float>(k.y), static_cast<float>(k.confidence)});
  }
  octocap_result_t solve(const std::vector<octocap_keypoint2d_t>& kps, uint32_t views, int64_t t = 0) {
    return octocap_session_solve_keypoints(session.get(), kps.data(), nullptr, views, t);
  }
  // After any misuse, a good frame still solves.
  void still_usable() {
    REQUIRE(solve(frame, static_cast<uint32_t>(cams.size()), 1000000) == OCTOCAP_OK);
    octocap_frame_info_t info;
    REQUIRE(octocap_session_get_frame_info(session.get(), &info) == OCTOCAP_OK);
    REQUIRE(info.keypoints_solved > 20);
  }
};

}  // namespace

TEST_CASE("version and ABI", "[capi]") {
  REQUIRE(octocap_abi_version() == OCTOCAP_ABI_VERSION);
  REQUIRE(std::string(octocap_version()).find('.') != std::string::npos);
  REQUIRE(std::string(octocap_result_name(OCTOCAP_ERROR_PARSE)) == "OCTOCAP_ERROR_PARSE");
}

TEST_CASE("NULL handles and pointers", "[capi][misuse]") {
  Fixture f;
  uint32_t n = 0;
  REQUIRE(octocap_calibration_camera_count(nullptr, &n) == OCTOCAP_ERROR_INVALID_HANDLE);
  REQUIRE_THAT(octocap_last_error(), ContainsSubstring("NULL"));
  REQUIRE(octocap_calibration_camera_count(f.calib.get(), nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE(octocap_session_solve_keypoints(nullptr, f.frame.data(), nullptr, 5, 0) == OCTOCAP_ERROR_INVALID_HANDLE);
  REQUIRE(octocap_session_solve_keypoints(f.session.get(), nullptr, nullptr, 5, 0) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE(octocap_session_create(nullptr, f.calib.get(), nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_session_t* s = reinterpret_cast<octocap_session_t*>(0x1);
  REQUIRE(octocap_session_create(&f.cfg, nullptr, &s) == OCTOCAP_ERROR_INVALID_HANDLE);
  REQUIRE(s == nullptr);  // out is cleared on failure
  REQUIRE(octocap_calibration_load(nullptr, nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_calibration_destroy(nullptr);
  octocap_session_destroy(nullptr);
  octocap_recording_destroy(nullptr);
  REQUIRE(octocap_motion_writer_close(nullptr) == OCTOCAP_OK);
  f.still_usable();
}

TEST_CASE("destroyed (dangling) and wrong-type handles are refused", "[capi][misuse]") {
  Fixture f;
  octocap_calibration_t* c = nullptr;
  auto cam = testing::to_c_camera(f.cams[0]);
  REQUIRE(octocap_calibration_create(&cam, 1, &c) == OCTOCAP_OK);
  octocap_calibration_destroy(c);
  uint32_t n = 0;
  REQUIRE(octocap_calibration_camera_count(c, &n) == OCTOCAP_ERROR_INVALID_HANDLE);
  REQUIRE_THAT(octocap_last_error(), ContainsSubstring("not a live handle"));
  octocap_calibration_destroy(c);  // a second destroy is ignored, not a double free
  auto* as_session = reinterpret_cast<octocap_session_t*>(f.calib.get());
  REQUIRE(octocap_session_reset(as_session) == OCTOCAP_ERROR_INVALID_HANDLE);
  f.still_usable();
}

TEST_CASE("config: wrong struct_size and bad values", "[capi][misuse]") {
  Fixture f;
  octocap_session_t* s = nullptr;
  octocap_session_config_t cfg = f.cfg;
  cfg.struct_size = 12;
  REQUIRE(octocap_session_create(&cfg, f.calib.get(), &s) == OCTOCAP_ERROR_STRUCT_SIZE);
  REQUIRE_THAT(octocap_last_error(), ContainsSubstring("struct_size"));
  cfg = f.cfg;
  cfg.delta_m = std::numeric_limits<float>::quiet_NaN();
  REQUIRE(octocap_session_create(&cfg, f.calib.get(), &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  cfg = f.cfg;
  cfg.sigma = 9;
  REQUIRE(octocap_session_create(&cfg, f.calib.get(), &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE_THAT(octocap_last_error(), ContainsSubstring("sigma"));
  cfg = f.cfg;
  cfg.layout = OCTOCAP_LAYOUT_AUTO;
  REQUIRE(octocap_session_create(&cfg, f.calib.get(), &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  cfg = f.cfg;
  cfg.volume_min[0] = 1;
  cfg.volume_max[0] = 0;
  REQUIRE(octocap_session_create(&cfg, f.calib.get(), &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  cfg = f.cfg;
  cfg.method = static_cast<octocap_method_t>(7);
  REQUIRE(octocap_session_create(&cfg, f.calib.get(), &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE(s == nullptr);
}

TEST_CASE("a calibration with one camera cannot make a session", "[capi][misuse]") {
  Fixture f;
  auto cam = testing::to_c_camera(f.cams[0]);
  octocap_calibration_t* one = nullptr;
  REQUIRE(octocap_calibration_create(&cam, 1, &one) == OCTOCAP_OK);
  testing::Calib guard(one);
  octocap_session_t* s = nullptr;
  REQUIRE(octocap_session_create(&f.cfg, one, &s) == OCTOCAP_ERROR_NOT_ENOUGH_VIEWS);
  cam.matrix[0] = std::nan("");
  octocap_calibration_t* bad = nullptr;
  REQUIRE(octocap_calibration_create(&cam, 1, &bad) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  REQUIRE_THAT(octocap_last_error(), ContainsSubstring("camera 0"));
}

// One rule for a camera, wherever it comes from: each value below is refused by octocap_calibration_create and by a
// calibration TOML alike, with the same reason.
TEST_CASE("an implausible camera is refused from the C ABI and from a calibration file, for the same reason",
          "[capi][misuse]") {
  struct Bad {
    const char* what;
    const char* reason;
    double width, fx, rotation, translation;
  };
  const Bad bads[] = {{"size 0", "size must be 1 to 100000", 0, 1000, 0.1, 1},
                      {"size 200000", "size must be 1 to 100000", 200000, 1000, 0.1, 1},
                      {"focal length 0", "focal length is not > 0", 640, 0, 0.1, 1},
                      {"rotation 2000 rad", "is not a rotation", 640, 1000, 2000, 1},
                      {"translation 2e6 m", "beyond a million metres", 640, 1000, 0.1, 2e6},
                      {"NaN translation", "NaN or infinite", 640, 1000, 0.1, std::nan("")}};
  testing::TempDir dir;
  for (const Bad& b : bads) {
    INFO(b.what);
    octocap_camera_t cam{};
    std::snprintf(cam.name, sizeof cam.name, "cam_1");
    cam.width = static_cast<uint32_t>(b.width);
    cam.height = 480;
    const double K[9] = {b.fx, 0, 320, 0, 1000, 240, 0, 0, 1};
    std::copy(K, K + 9, cam.matrix);
    cam.rotation[0] = b.rotation;
    cam.translation[2] = b.translation;
    octocap_calibration_t* c = nullptr;
    CHECK(octocap_calibration_create(&cam, 1, &c) == OCTOCAP_ERROR_INVALID_ARGUMENT);
    CHECK(c == nullptr);
    CHECK_THAT(octocap_last_error(), ContainsSubstring("camera 0: ") && ContainsSubstring(b.reason));
    const std::string file = dir.file("bad.toml");
    std::ofstream out(file);
    out << std::fixed << "[cam_1]\nname = \"cam_1\"\nsize = [ " << b.width << ", 480.0]\nmatrix = [ [ " << b.fx
                        << ", 0.0, 320.0], [ 0.0, 1000.0, 240.0], [ 0.0, 0.0, 1.0]]\ndistortions = [ 0.0, 0.0, 0.0, 0.0]\n"
                        << "rotation = [ " << b.rotation << ", 0.0, 0.0]\ntranslation = [ 0.0, 0.0, "
                        << (std::isnan(b.translation) ? std::string("nan") : std::to_string(b.translation)) << "]\n";
    out.close();
    CHECK(octocap_calibration_load(file.c_str(), &c) == OCTOCAP_ERROR_PARSE);
    CHECK(c == nullptr);
    CHECK_THAT(octocap_last_error(), ContainsSubstring("[cam_1]") && ContainsSubstring(b.reason));
  }
}

// A sync file is only written if it reads back: octocap_sync_save refuses what octocap_sync_load would.
TEST_CASE("sync files: what cannot be read back is not written", "[capi][misuse]") {
  Fixture f;
  testing::TempDir dir;
  const std::string file = dir.file("sync.toml");
  std::vector<double> offsets(f.cams.size(), 0.0);
  const uint32_t n = static_cast<uint32_t>(offsets.size());
  REQUIRE(octocap_sync_save(file.c_str(), 30, f.calib.get(), offsets.data(), n) == OCTOCAP_OK);
  std::vector<double> back(n, 7.0);
  double rate = 0;
  REQUIRE(octocap_sync_load(file.c_str(), f.calib.get(), back.data(), n, &rate) == OCTOCAP_OK);
  CHECK(rate == 30);
  CHECK(back == offsets);
  CHECK(octocap_sync_save(file.c_str(), 2e5, f.calib.get(), offsets.data(), n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_sync_save(file.c_str(), 0, f.calib.get(), offsets.data(), n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  offsets[1] = 2e6;
  CHECK(octocap_sync_save(file.c_str(), 30, f.calib.get(), offsets.data(), n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("million frames"));
  offsets[1] = std::nan("");
  CHECK(octocap_sync_save(file.c_str(), 30, f.calib.get(), offsets.data(), n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  // The file written first is still the one there.
  REQUIRE(octocap_sync_load(file.c_str(), f.calib.get(), back.data(), n, &rate) == OCTOCAP_OK);
  CHECK(rate == 30);
}

TEST_CASE("camera-count mismatch, NaN keypoints, too few views", "[capi][misuse]") {
  Fixture f;
  SECTION("view count differs from the calibration") {
    REQUIRE(f.solve(f.frame, 4) == OCTOCAP_ERROR_CAMERA_MISMATCH);
    REQUIRE_THAT(octocap_last_error(), ContainsSubstring("5 cameras"));
  }
  SECTION("NaN and infinite keypoints are treated as undetected, never solved into NaN") {
    auto kps = f.frame;
    for (size_t i = 0; i < kps.size(); i += 2) kps[i].x = std::numeric_limits<float>::quiet_NaN();
    for (size_t i = 1; i < kps.size(); i += 4) kps[i].confidence = std::numeric_limits<float>::infinity();
    REQUIRE(f.solve(kps, 5) == OCTOCAP_OK);
    std::vector<octocap_joint_t> j(25);
    uint32_t n = 0;
    REQUIRE(octocap_session_get_keypoints3d(f.session.get(), j.data(), 25, &n) == OCTOCAP_OK);
    for (const auto& p : j)
      if (p.valid) REQUIRE((std::isfinite(p.position[0]) && std::isfinite(p.position[1]) && std::isfinite(p.position[2])));
  }
  SECTION("fewer views than needed: a status (not an error), a frame with nobody, and the session goes on") {
    std::vector<uint32_t> people = {1, 0, 0, 0, 0};
    REQUIRE(octocap_session_solve_keypoints(f.session.get(), f.frame.data(), people.data(), 5, 0) ==
            OCTOCAP_STATUS_NO_PERSON);
    REQUIRE_FALSE(OCTOCAP_FAILED(OCTOCAP_STATUS_NO_PERSON));
    octocap_frame_t* frame = nullptr;
    REQUIRE(octocap_session_get_frame(f.session.get(), &frame) == OCTOCAP_OK);
    octocap_frame_summary_t summary{};
    summary.struct_size = sizeof summary;
    REQUIRE(octocap_frame_get_summary(frame, &summary) == OCTOCAP_OK);
    CHECK(summary.person_count == 0);
    octocap_joint_t none[15];
    uint32_t count = 0;
    CHECK(octocap_frame_get_joints(frame, 0, none, 15, &count) == OCTOCAP_ERROR_INVALID_ARGUMENT);
    octocap_frame_release(frame);
    octocap_frame_info_t info;
    REQUIRE(octocap_session_get_frame_info(f.session.get(), &info) == OCTOCAP_OK);
    REQUIRE(info.keypoints_solved == 0);
    octocap_joint_t j[15];
    uint32_t n = 0;
    REQUIRE(octocap_session_get_joints(f.session.get(), j, 15, &n) == OCTOCAP_OK);
    for (const auto& p : j) REQUIRE(p.valid == 0);
  }
  f.still_usable();
}

TEST_CASE("queries: before the first frame, short buffers, two-call pattern", "[capi][misuse]") {
  Fixture f;
  octocap_joint_t j[25];
  uint32_t n = 0;
  REQUIRE(octocap_session_get_keypoints3d(f.session.get(), j, 25, &n) == OCTOCAP_ERROR_NO_RESULT);
  f.still_usable();
  REQUIRE(octocap_session_get_keypoints3d(f.session.get(), nullptr, 0, &n) == OCTOCAP_OK);
  REQUIRE(n == 25);
  REQUIRE(octocap_session_get_keypoints3d(f.session.get(), j, 10, &n) == OCTOCAP_ERROR_BUFFER_TOO_SMALL);
  REQUIRE(n == 25);
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  REQUIRE(octocap_session_get_bones(f.session.get(), static_cast<octocap_coord_frame_t>(9), bones,
                                    OCTOCAP_BONE_COUNT, &n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_quat_t q;
  REQUIRE(octocap_session_get_bone_rotation(f.session.get(), 99, OCTOCAP_FRAME_RIG, &q) ==
          OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_bone_info_t info;
  REQUIRE(octocap_bone_info(OCTOCAP_BONE_COUNT, &info) == OCTOCAP_ERROR_INVALID_ARGUMENT);
}

TEST_CASE("malformed files through the C ABI", "[capi][misuse]") {
  testing::TempDir dir;
  octocap_calibration_t* c = nullptr;
  REQUIRE(octocap_calibration_load(dir.write("c.toml", "[cam_1\n").c_str(), &c) == OCTOCAP_ERROR_PARSE);
  REQUIRE_THAT(octocap_last_error(), ContainsSubstring("c.toml"));
  REQUIRE(c == nullptr);
  REQUIRE(octocap_calibration_load(dir.file("nope.toml").c_str(), &c) == OCTOCAP_ERROR_IO);
  octocap_recording_t* r = nullptr;
  dir.write("rec/cam1/0.json", "{\"people\": [{\"pose_keypoints_2d\": [1, 2]}]}");
  REQUIRE(octocap_recording_open(dir.file("rec").c_str(), OCTOCAP_LAYOUT_AUTO, &r) == OCTOCAP_ERROR_PARSE);
  REQUIRE_THAT(octocap_last_error(), ContainsSubstring("0.json"));
  dir.write("rec2/cam1/0.json", "{\"people\": []}");
  REQUIRE(octocap_recording_open(dir.file("rec2").c_str(), OCTOCAP_LAYOUT_COCO_17, &r) == OCTOCAP_OK);
  dir.write("rec2/cam1/0.json", "{\"people\": [{\"pose_keypoints_2d\": [1, 2, 0.5]}]}");  // now wrong for COCO_17
  uint32_t needed = 0, people = 0;
  REQUIRE(octocap_recording_read_frame(r, 0, nullptr, 0, &needed, &people, 1) == OCTOCAP_ERROR_PARSE);
  REQUIRE(octocap_recording_read_frame(r, 5, nullptr, 0, &needed, &people, 1) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_recording_destroy(r);
  octocap_motion_writer_t* w = nullptr;
  REQUIRE(octocap_motion_writer_create(dir.file("no/such/dir/x.trc").c_str(), OCTOCAP_MOTION_TRC,
                                       OCTOCAP_LAYOUT_COCO_17, OCTOCAP_UP_Y, 30, &w) == OCTOCAP_OK);
  REQUIRE(octocap_motion_writer_add_empty_frame(w) == OCTOCAP_OK);
  REQUIRE(octocap_motion_writer_close(w) == OCTOCAP_ERROR_IO);
}

TEST_CASE("the log callback receives messages and can be removed", "[capi]") {
  struct Seen {
    int count = 0;
  } seen;
  octocap_set_log_callback([](octocap_log_level_t, const char*, void* u) { static_cast<Seen*>(u)->count++; },
                           OCTOCAP_LOG_DEBUG, &seen);
  // Opening a recording whose camera folders differ in length logs a warning.
  testing::TempDir dir;
  dir.write("r/a/0.json", "{\"people\": []}");
  dir.write("r/a/1.json", "{\"people\": []}");
  dir.write("r/b/0.json", "{\"people\": []}");
  octocap_recording_t* r = nullptr;
  REQUIRE(octocap_recording_open(dir.file("r").c_str(), OCTOCAP_LAYOUT_BODY_25, &r) == OCTOCAP_OK);
  octocap_recording_destroy(r);
  REQUIRE(seen.count >= 1);
  octocap_set_log_callback(nullptr, OCTOCAP_LOG_DEBUG, nullptr);
  const int before = seen.count;
  REQUIRE(octocap_recording_open(dir.file("r").c_str(), OCTOCAP_LAYOUT_BODY_25, &r) == OCTOCAP_OK);
  octocap_recording_destroy(r);
  REQUIRE(seen.count == before);
}
