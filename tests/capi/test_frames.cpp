// The one frame type: every source's frames read through octocap_frame_*, bit for bit what the 0.x per-source
// queries give; snapshots that outlive their source; output structs filled to the caller's size; statuses;
// the definition counter; sized defaults for every released struct size. Through the public ABI and octocap.hpp.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "octocap/octocap.hpp"
#include "support/temp_dir.h"

using Catch::Matchers::ContainsSubstring;

namespace {

const std::string kSample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// The built-in sample: its calibration, its recording, and one frame of its keypoints at a time.
struct Sample {
  octocap::Calibration calib = octocap::Calibration::load(kSample + "/calibration.toml");
  octocap::Recording rec{kSample + "/keypoints"};
  std::vector<octocap_keypoint2d_t> kps;
  std::vector<uint32_t> people;
  uint32_t views() const { return rec.view_count(); }
  void read(uint32_t frame) { rec.read_frame(frame, kps, people); }
  octocap_result_t solve(octocap::Session& s, uint32_t frame, int64_t t_us) {
    read(frame);
    return s.solve_keypoints(kps.data(), people.data(), views(), t_us);
  }
};

octocap_session_config_t body25_config() {
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.layout = OCTOCAP_LAYOUT_BODY_25;
  return cfg;
}

}  // namespace

TEST_CASE("session frames read through the frame family give exactly the 0.x queries' bytes", "[frames]") {
  Sample sample;
  octocap::Session session(body25_config(), sample.calib);
  std::vector<octocap::Frame> kept;
  for (uint32_t f = 0; f < 10; ++f) {
    REQUIRE(sample.solve(session, f, f * 33333) == OCTOCAP_OK);
    octocap::Frame frame = session.frame();
    const octocap_frame_summary_t s = frame.summary();
    CHECK(s.frame_index == f);
    CHECK(s.timestamp_us == f * 33333);
    CHECK(s.person_count == 1);
    CHECK(s.layout == OCTOCAP_LAYOUT_BODY_25);
    CHECK(s.keypoint_count == 25);
    CHECK(s.view_count == 5);
    CHECK(s.source_id == 0);
    CHECK(s.joints_in_rig_frame == 0);
    const octocap_person_t p = frame.person(0);
    CHECK(p.id == 1);
    CHECK(p.keypoints_total == 25);
    CHECK(p.keypoints_solved == 25);
    CHECK(p.joints_solved == OCTOCAP_JOINT_COUNT - 2);  // all but the knuckles: BODY_25 has no hand points
    CHECK(p.views_with_person >= 4);
    CHECK(p.mean_reprojection_error_px > 0);
    CHECK(p.mean_reprojection_error_px < 5);

    // The deprecated session queries, read the 0.x way.
    std::vector<octocap_joint_t> old_kp(25), old_joints(OCTOCAP_JOINT_COUNT);
    std::vector<octocap_bone_pose_t> old_bones(OCTOCAP_BONE_COUNT);
    std::vector<int32_t> old_views(5);
    uint32_t n = 0;
    REQUIRE(octocap_session_get_keypoints3d(session.get(), old_kp.data(), 25, &n) == OCTOCAP_OK);
    REQUIRE(octocap_session_get_joints(session.get(), old_joints.data(), OCTOCAP_JOINT_COUNT, &n) == OCTOCAP_OK);
    REQUIRE(octocap_session_get_bones(session.get(), OCTOCAP_FRAME_UNITY, old_bones.data(), OCTOCAP_BONE_COUNT, &n) ==
            OCTOCAP_OK);
    REQUIRE(octocap_session_get_selected_people(session.get(), old_views.data(), 5, &n) == OCTOCAP_OK);
    CHECK(same_bytes(frame.keypoints3d(0), old_kp));
    CHECK(same_bytes(frame.joints(0), old_joints));
    CHECK(same_bytes(frame.bones(0, OCTOCAP_FRAME_UNITY), old_bones));
    CHECK(same_bytes(frame.person_views(0), old_views));
    octocap_frame_info_t info;
    REQUIRE(octocap_session_get_frame_info(session.get(), &info) == OCTOCAP_OK);
    CHECK(info.keypoints_solved == p.keypoints_solved);
    CHECK(info.mean_reprojection_error_px == p.mean_reprojection_error_px);
    kept.push_back(std::move(frame));
  }
  // A frame is a snapshot: later solves do not change it.
  CHECK(kept.front().summary().frame_index == 0);
  CHECK(kept.back().summary().frame_index == 9);
  CHECK_FALSE(same_bytes(kept.front().joints(0), kept.back().joints(0)));
}

TEST_CASE("a frame outlives its session, and every frame query refuses what it cannot answer", "[frames][misuse]") {
  Sample sample;
  octocap_frame_t* frame = nullptr;
  std::vector<octocap_joint_t> before;
  {
    octocap::Session session(body25_config(), sample.calib);
    octocap_frame_t* none = reinterpret_cast<octocap_frame_t*>(0x1);
    CHECK(octocap_session_get_frame(session.get(), &none) == OCTOCAP_ERROR_NO_RESULT);
    CHECK(none == nullptr);
    sample.solve(session, 0, 0);
    REQUIRE(octocap_session_get_frame(session.get(), &frame) == OCTOCAP_OK);
    before.assign(25, octocap_joint_t{});
    uint32_t n = 0;
    REQUIRE(octocap_frame_get_keypoints3d(frame, 0, before.data(), 25, &n) == OCTOCAP_OK);
  }  // the session is gone
  std::vector<octocap_joint_t> after(25);
  uint32_t n = 0;
  REQUIRE(octocap_frame_get_keypoints3d(frame, 0, after.data(), 25, &n) == OCTOCAP_OK);
  CHECK(same_bytes(before, after));

  // Two-call pattern, short buffers, bad indices, bad frames.
  REQUIRE(octocap_frame_get_joints(frame, 0, nullptr, 0, &n) == OCTOCAP_OK);
  CHECK(n == OCTOCAP_JOINT_COUNT);
  octocap_joint_t few[3];
  CHECK(octocap_frame_get_joints(frame, 0, few, 3, &n) == OCTOCAP_ERROR_BUFFER_TOO_SMALL);
  CHECK(n == OCTOCAP_JOINT_COUNT);
  CHECK(octocap_frame_get_joints(frame, 1, nullptr, 0, &n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("person 1 out of range"));
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  CHECK(octocap_frame_get_bones(frame, 0, 7, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_frame_get_joints(frame, 0, few, 3, nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_frame_summary_t s{};
  s.struct_size = 8;  // smaller than any released summary
  CHECK(octocap_frame_get_summary(frame, &s) == OCTOCAP_ERROR_STRUCT_SIZE);
  CHECK(octocap_frame_get_summary(frame, nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_frame_release(frame);
  CHECK(octocap_frame_get_joints(frame, 0, nullptr, 0, &n) == OCTOCAP_ERROR_INVALID_HANDLE);  // released
  CHECK(octocap_frame_get_summary(nullptr, &s) == OCTOCAP_ERROR_INVALID_HANDLE);
  octocap_frame_release(nullptr);
}

TEST_CASE("a newer caller's bigger output struct is filled to what the library knows, never past it", "[frames]") {
  Sample sample;
  octocap::Session session(body25_config(), sample.calib);
  sample.solve(session, 0, 0);
  const octocap::Frame frame = session.frame();
  struct Bigger {
    octocap_frame_summary_t known;
    unsigned char future[64];
  } big;
  std::memset(&big, 0xA5, sizeof big);
  big.known.struct_size = sizeof big;
  REQUIRE(octocap_frame_get_summary(frame.get(), &big.known) == OCTOCAP_OK);
  CHECK(big.known.struct_size == sizeof(octocap_frame_summary_t));  // tells the caller what was filled
  CHECK(big.known.person_count == 1);
  for (unsigned char c : big.future) REQUIRE(c == 0xA5);
}

TEST_CASE("statuses are not errors, and every result has a name", "[frames]") {
  CHECK_FALSE(OCTOCAP_FAILED(OCTOCAP_OK));
  CHECK_FALSE(OCTOCAP_FAILED(OCTOCAP_STATUS_NO_PERSON));
  CHECK_FALSE(OCTOCAP_FAILED(OCTOCAP_STATUS_TIMEOUT));
  CHECK(OCTOCAP_FAILED(OCTOCAP_ERROR_OUT_OF_MEMORY));
  CHECK(std::string(octocap_result_name(OCTOCAP_STATUS_NO_PERSON)) == "OCTOCAP_STATUS_NO_PERSON");
  CHECK(std::string(octocap_result_name(OCTOCAP_STATUS_TIMEOUT)) == "OCTOCAP_STATUS_TIMEOUT");
  CHECK(std::string(octocap_result_name(OCTOCAP_ERROR_OUT_OF_MEMORY)) == "OCTOCAP_ERROR_OUT_OF_MEMORY");
  // The wrapper returns statuses and throws errors.
  CHECK(octocap::check(OCTOCAP_STATUS_NO_PERSON) == OCTOCAP_STATUS_NO_PERSON);
  CHECK_THROWS_AS(octocap::check(OCTOCAP_ERROR_IO, "x"), octocap::Error);
  try {
    octocap::Calibration::load("/nonexistent/calib.toml");
    FAIL("no exception");
  } catch (const octocap::Error& e) {
    CHECK(e.code() == OCTOCAP_ERROR_IO);
    CHECK_THAT(e.what(), ContainsSubstring("/nonexistent/calib.toml"));
  }
}

TEST_CASE("versions: header and library agree, every released struct size gets its defaults", "[frames][abi]") {
  CHECK(octocap_version_number() == OCTOCAP_VERSION_NUMBER);
  CHECK(std::string(octocap_version()) == std::to_string(OCTOCAP_VERSION_MAJOR) + "." +
                                              std::to_string(OCTOCAP_VERSION_MINOR) + "." +
                                              std::to_string(OCTOCAP_VERSION_PATCH));
  CHECK(octocap_abi_version() == OCTOCAP_ABI_VERSION);
  // Each released size is filled exactly; unknown sizes are refused without a write.
  for (uint32_t size : {84u, 152u, 216u, 760u}) {
    std::vector<unsigned char> box(size + 64, 0xA5);
    REQUIRE(octocap_session_config_defaults(reinterpret_cast<octocap_session_config_t*>(box.data()), size) == OCTOCAP_OK);
    uint32_t written = 0;
    std::memcpy(&written, box.data(), 4);
    CHECK(written == size);
    for (size_t i = size; i < box.size(); ++i) REQUIRE(box[i] == 0xA5);
    float delta = 0;
    std::memcpy(&delta, box.data() + offsetof(octocap_session_config_t, delta_m), sizeof delta);
    CHECK(delta == 0.01f);
  }
  std::vector<unsigned char> box(1024, 0xA5);
  auto* cfg = reinterpret_cast<octocap_session_config_t*>(box.data());
  CHECK(octocap_session_config_defaults(cfg, 100) == OCTOCAP_ERROR_STRUCT_SIZE);
  CHECK(box[0] == 0xA5);
  CHECK(octocap_session_config_defaults(nullptr, 216) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  auto* det = reinterpret_cast<octocap_detector_config_t*>(box.data());
  CHECK(octocap_detector_config_defaults(det, 540) == OCTOCAP_OK);
  CHECK(box[540] == 0xA5);
  CHECK(octocap_detector_config_defaults(det, 600) == OCTOCAP_ERROR_STRUCT_SIZE);
  auto* ext = reinterpret_cast<octocap_extrinsics_options_t*>(box.data());
  CHECK(octocap_extrinsics_options_defaults(ext, 32) == OCTOCAP_OK);
  CHECK(octocap_extrinsics_options_defaults(ext, 33) == OCTOCAP_ERROR_STRUCT_SIZE);
  auto* sub = reinterpret_cast<octocap_subscriber_config_t*>(box.data());
  CHECK(octocap_subscriber_config_defaults(sub, 52) == OCTOCAP_OK);
  CHECK(octocap_subscriber_config_defaults(sub, 48) == OCTOCAP_ERROR_STRUCT_SIZE);
}

TEST_CASE("the definition counter differs between sources and is never 0", "[frames]") {
  Sample sample;
  octocap::Session a(body25_config(), sample.calib);
  octocap_session_config_t coco = body25_config();
  coco.layout = OCTOCAP_LAYOUT_COCO_17;
  octocap::Session b(coco, sample.calib);
  sample.solve(a, 0, 0);
  const uint32_t ca = a.frame().summary().definition_counter;
  sample.solve(a, 1, 33333);
  CHECK(a.frame().summary().definition_counter == ca);  // same source, same definition
  std::vector<octocap_keypoint2d_t> none;
  std::vector<uint32_t> zero(sample.views(), 0);
  CHECK(b.solve_keypoints(none.data(), zero.data(), sample.views(), 0) == OCTOCAP_STATUS_NO_PERSON);
  const uint32_t cb = b.frame().summary().definition_counter;
  CHECK(ca != 0);
  CHECK(cb != 0);
  CHECK(ca != cb);
  uint32_t deprecated = 0;
  REQUIRE(octocap_session_definition_counter(a.get(), &deprecated) == OCTOCAP_OK);
  CHECK(deprecated == ca);
  const octocap::Motion motion("/usr/share/assimp/models/BVH/01_01.bvh");
  const uint32_t cm = motion.frame(0).summary().definition_counter;
  CHECK(cm != 0);
  CHECK(cm != ca);
  CHECK(cm != cb);
}

TEST_CASE("motion frames are frames: joints in the rig frame, bones as the 0.x motion queries give them", "[frames]") {
  const octocap::Motion motion("/usr/share/assimp/models/BVH/01_01.bvh");
  octocap_motion_t* raw = nullptr;
  REQUIRE(octocap_motion_open("/usr/share/assimp/models/BVH/01_01.bvh", &raw) == OCTOCAP_OK);
  for (uint32_t f : {0u, 500u, 2751u}) {
    const octocap::Frame frame = motion.frame(f);
    const octocap_frame_summary_t s = frame.summary();
    CHECK(s.frame_index == f);
    CHECK(s.person_count == 1);
    CHECK(s.joints_in_rig_frame == 1);
    CHECK(s.keypoint_count == 0);
    std::vector<octocap_joint_t> joints(OCTOCAP_JOINT_COUNT);
    std::vector<octocap_bone_pose_t> bones(OCTOCAP_BONE_COUNT);
    uint32_t n = 0;
    REQUIRE(octocap_motion_joints(raw, f, joints.data(), OCTOCAP_JOINT_COUNT, &n) == OCTOCAP_OK);
    REQUIRE(octocap_motion_bones(raw, f, OCTOCAP_FRAME_GODOT, bones.data(), OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
    CHECK(same_bytes(frame.joints(0), joints));
    CHECK(same_bytes(frame.bones(0, OCTOCAP_FRAME_GODOT), bones));
  }
  octocap_frame_t* out = nullptr;
  CHECK(octocap_motion_get_frame(raw, 2752, &out) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(out == nullptr);
  octocap_motion_destroy(raw);
}

TEST_CASE("a motion writer's journal holds every frame as it is added, and goes once the take is written", "[frames]") {
  Sample sample;
  octocap::Session session(body25_config(), sample.calib);
  testing::TempDir dir;
  const std::string journal = dir.file("take.trc.partial.csv");
  {
    octocap::MotionWriter w(dir.file("take.trc"), OCTOCAP_MOTION_TRC, OCTOCAP_LAYOUT_BODY_25, OCTOCAP_UP_Y, 0);
    w.set_journal(journal);
    for (uint32_t f = 0; f < 4; ++f) {
      sample.solve(session, f, 1000000 + f * 40000);  // 25 Hz
      w.add(session.frame());
      // Readable at once, every frame so far in it with its time: what a process killed now would leave.
      const octocap::Motion partial(journal);
      REQUIRE(partial.frame_count() == f + 1);
      const octocap::Frame last = partial.frame(f);
      CHECK(std::abs(static_cast<double>(last.summary().timestamp_us) - f * 40000.0) < 1.0);
      CHECK(last.person_count() == 1);
    }
    CHECK_THROWS_AS(w.set_journal(dir.file("late.csv")), octocap::Error);  // only before the first frame
    w.close();
  }
  CHECK(std::filesystem::exists(dir.file("take.trc")));
  CHECK_FALSE(std::filesystem::exists(journal));  // written: the journal has served
  {
    octocap::MotionWriter dropped(dir.file("dropped.trc"), OCTOCAP_MOTION_TRC, OCTOCAP_LAYOUT_BODY_25, OCTOCAP_UP_Y, 0);
    dropped.set_journal(dir.file("dropped.partial.csv"));
    sample.solve(session, 0, 0);
    dropped.add(session.frame());
    CHECK(std::filesystem::exists(dir.file("dropped.partial.csv")));
  }  // discarded, as on an error path
  CHECK_FALSE(std::filesystem::exists(dir.file("dropped.partial.csv")));
  CHECK_FALSE(std::filesystem::exists(dir.file("dropped.trc")));
  octocap_motion_writer_t* w = nullptr;
  REQUIRE(octocap_motion_writer_create(dir.file("x.trc").c_str(), OCTOCAP_MOTION_TRC, OCTOCAP_LAYOUT_BODY_25,
                                       OCTOCAP_UP_Y, 0, &w) == OCTOCAP_OK);
  CHECK(octocap_motion_writer_set_journal(w, "/proc/no-such-dir/x.csv") == OCTOCAP_ERROR_IO);
  CHECK(octocap_motion_writer_set_journal(w, nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_motion_writer_set_journal(nullptr, "x") == OCTOCAP_ERROR_INVALID_HANDLE);
  octocap_motion_writer_discard(w);
}

TEST_CASE("a motion writer that is discarded writes nothing; a closed one writes what its frames held", "[frames]") {
  Sample sample;
  octocap::Session session(body25_config(), sample.calib);
  const std::string tmp = std::filesystem::temp_directory_path().string();
  const std::string kept = tmp + "/octocap-test-kept.csv";
  const std::string dropped = tmp + "/octocap-test-dropped.csv";
  std::remove(kept.c_str());
  std::remove(dropped.c_str());
  {
    octocap::MotionWriter good(kept, OCTOCAP_MOTION_CSV, OCTOCAP_LAYOUT_BODY_25, OCTOCAP_UP_Y, 30);
    octocap::MotionWriter bad(dropped, OCTOCAP_MOTION_CSV, OCTOCAP_LAYOUT_BODY_25, OCTOCAP_UP_Y, 30);
    for (uint32_t f = 0; f < 3; ++f) {
      sample.solve(session, f, f * 33333);
      good.add(session.frame());
      bad.add(session.frame());
    }
    good.add(session.frame(), 1);  // no second person: an empty row
    good.close();
  }  // `bad` is destroyed without close(), as on an error path
  FILE* f = std::fopen(kept.c_str(), "r");
  REQUIRE(f != nullptr);
  int lines = 0;
  for (int c; (c = std::fgetc(f)) != EOF;) lines += c == '\n';
  std::fclose(f);
  CHECK(lines == 5);  // header + 4 frames
  CHECK(std::fopen(dropped.c_str(), "r") == nullptr);
  std::remove(kept.c_str());
  // Rates that no camera has are refused; 0 means "the frames' own timestamps".
  octocap_motion_writer_t* timed = nullptr;
  CHECK(octocap_motion_writer_create(dropped.c_str(), OCTOCAP_MOTION_TRC, OCTOCAP_LAYOUT_BODY_25, OCTOCAP_UP_Y, 0.0,
                                     &timed) == OCTOCAP_OK);
  octocap_motion_writer_discard(timed);
  CHECK(std::fopen(dropped.c_str(), "r") == nullptr);
  for (double rate : {-30.0, 1e-300, 1e300, std::nan("")}) {
    octocap_motion_writer_t* w = nullptr;
    CHECK(octocap_motion_writer_create(dropped.c_str(), OCTOCAP_MOTION_TRC, OCTOCAP_LAYOUT_BODY_25, OCTOCAP_UP_Y, rate,
                                       &w) == OCTOCAP_ERROR_INVALID_ARGUMENT);
    CHECK(w == nullptr);
  }
}
