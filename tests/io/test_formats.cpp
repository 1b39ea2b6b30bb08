// File formats: calibration TOML, OpenPose JSON folders, TRC / CSV, BVH. Real files where we have them.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "core/error.h"
#include "io/bvh.h"
#include "io/calibration_toml.h"
#include "io/motion_files.h"
#include "io/openpose_json.h"
#include "support/temp_dir.h"
#include "synth.h"

using namespace octocap::internal;
using Catch::Matchers::ContainsSubstring;

namespace {

const std::string kFixture = std::string(OCTOCAP_SOURCE_DIR) + "/tests/data/pose2sim_calib_qualisys.toml";

// Runs fn and returns the Error it throws (fails the test if it throws nothing).
template <class F>
Error error_of(F&& fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e;
  }
  FAIL("expected an octocap::internal::Error");
  return Error(Errc::internal, "");
}

const char* kCamera = R"(
[cam_1]
name = "a"
size = [ 640.0, 480.0]
matrix = [ [ 500.0, 0.0, 320.0], [ 0.0, 500.0, 240.0], [ 0.0, 0.0, 1.0]]
distortions = [ 0.01, -0.02, 0.001, 0.002]
rotation = [ 0.1, 0.2, 0.3]
translation = [ 1.0, 2.0, 3.0]
fisheye = false
)";

std::string openpose_json(const std::vector<std::vector<double>>& people) {
  std::ostringstream s;
  s << R"({"version":1.3,"people":[)";
  for (size_t p = 0; p < people.size(); ++p) {
    s << (p ? "," : "") << R"({"person_id":[-1],"pose_keypoints_2d":[)";
    for (size_t i = 0; i < people[p].size(); ++i) s << (i ? "," : "") << people[p][i];
    s << "]}";
  }
  s << "]}";
  return s.str();
}

}  // namespace

TEST_CASE("Pose2Sim's real calibration file loads in file order", "[formats][toml]") {
  const Calibration c = read_calibration_toml(kFixture);
  REQUIRE(c.size() == 4);
  REQUIRE(c[0].name == "cam_01");
  REQUIRE(c[3].name == "cam_04");
  REQUIRE(c[0].width == 1088);
  REQUIRE(c[0].height == 1920);
  REQUIRE(c[0].K(0, 0) == Catch::Approx(1681.244873046875));
  REQUIRE(c[0].K(1, 2) == Catch::Approx(948.137390140625));
  REQUIRE(c[1].t.z() == Catch::Approx(3.0675519599999994));
  REQUIRE(c[0].dist[3] == Catch::Approx(1.078125e-05));
  REQUIRE(c[0].dist[4] == 0.0);  // Pose2Sim writes 4 coefficients; k3 is 0
  REQUIRE((matrix_to_rodrigues(c[2].R) - Eigen::Vector3d(0.8109654899999995, -2.1972129299999996,
                                                          1.3760277799999996)).norm() < 1e-9);
}

TEST_CASE("calibration TOML round-trips", "[formats][toml]") {
  testing::TempDir dir;
  synth::RigOptions rig;
  rig.cameras = 6;
  const Calibration a = synth::make_camera_ring(rig);
  write_calibration_toml(a, dir.file("c.toml"));
  const Calibration b = read_calibration_toml(dir.file("c.toml"));
  REQUIRE(b.size() == a.size());
  for (size_t i = 0; i < a.size(); ++i) {
    REQUIRE(b[i].name == a[i].name);
    REQUIRE((b[i].K - a[i].K).norm() < 1e-9);
    REQUIRE((b[i].R - a[i].R).norm() < 1e-12);
    REQUIRE((b[i].t - a[i].t).norm() < 1e-12);
    for (int k = 0; k < 5; ++k) REQUIRE(b[i].dist[k] == Catch::Approx(a[i].dist[k]).margin(1e-15));
  }
}

TEST_CASE("camera order is the file's, not the table names'", "[formats][toml]") {
  testing::TempDir dir;
  std::string two = std::string(kCamera);
  const std::string first = std::string(kCamera).replace(two.find("[cam_1]"), 7, "[zeta]");
  std::string second = std::string(kCamera).replace(two.find("[cam_1]"), 7, "[alpha]");
  second.replace(second.find("\"a\""), 3, "\"b\"");
  const Calibration c = read_calibration_toml(dir.write("c.toml", first + second));
  REQUIRE(c.size() == 2);
  REQUIRE(c[0].name == "a");
  REQUIRE(c[1].name == "b");
}

TEST_CASE("malformed calibration files give errors naming the file and the fault", "[formats][toml]") {
  testing::TempDir dir;
  SECTION("missing file") {
    const Error e = error_of([&] { read_calibration_toml(dir.file("absent.toml")); });
    REQUIRE(e.code() == Errc::io);
    REQUIRE_THAT(e.what(), ContainsSubstring("absent.toml"));
  }
  SECTION("TOML syntax error, with its line") {
    const std::string p = dir.write("bad.toml", "[cam_1]\nname = \"a\nsize = [1, 2]\n");
    const Error e = error_of([&] { read_calibration_toml(p); });
    REQUIRE(e.code() == Errc::parse);
    REQUIRE_THAT(e.what(), ContainsSubstring("bad.toml:2"));
  }
  SECTION("no camera table") {
    const Error e = error_of([&] { read_calibration_toml(dir.write("x.toml", "[metadata]\nerror = 0.0\n")); });
    REQUIRE_THAT(e.what(), ContainsSubstring("no camera table"));
  }
  SECTION("missing key") {
    std::string t = kCamera;
    t.erase(t.find("rotation"), t.find("translation") - t.find("rotation"));
    const Error e = error_of([&] { read_calibration_toml(dir.write("x.toml", t)); });
    REQUIRE(e.code() == Errc::parse);
    REQUIRE_THAT(e.what(), ContainsSubstring("[cam_1]") && ContainsSubstring("rotation"));
  }
  SECTION("wrong shape") {
    std::string t = kCamera;
    t.replace(t.find("[ 1.0, 2.0, 3.0]"), 16, "[ 1.0, 2.0]");
    const Error e = error_of([&] { read_calibration_toml(dir.write("x.toml", t)); });
    REQUIRE_THAT(e.what(), ContainsSubstring("'translation' must have 3 numbers"));
  }
  SECTION("NaN") {
    std::string t = kCamera;
    t.replace(t.find("[ 0.1, 0.2, 0.3]"), 16, "[ nan, 0.2, 0.3]");
    const Error e = error_of([&] { read_calibration_toml(dir.write("x.toml", t)); });
    REQUIRE_THAT(e.what(), ContainsSubstring("NaN"));
  }
  SECTION("text where a number belongs") {
    std::string t = kCamera;
    t.replace(t.find("500.0"), 5, "\"f\"");
    const Error e = error_of([&] { read_calibration_toml(dir.write("x.toml", t)); });
    REQUIRE_THAT(e.what(), ContainsSubstring("non-number"));
  }
}

TEST_CASE("OpenPose JSON files are read, placeholders become missing", "[formats][json]") {
  testing::TempDir dir;
  const std::string p = dir.write("f.json", openpose_json({{10, 20, 0.9, 0, 0, 0.4, 30, 40, 0.7}, {1, 2, 0.5, 3, 4, 0.5, 5, 6, 0.5}}));
  const auto people = read_openpose_file(p, 0);
  REQUIRE(people.size() == 2);
  REQUIRE(people[0][0].x == 10);
  REQUIRE(people[0][0].confidence == Catch::Approx(0.9));
  REQUIRE(people[0][1].confidence == 0);  // (0, 0) is OpenPose's "not detected"
  REQUIRE(people[1][2].y == 6);
}

TEST_CASE("malformed OpenPose JSON gives errors naming the file", "[formats][json]") {
  testing::TempDir dir;
  auto code_of = [](const std::string& path, size_t k) { return error_of([&] { read_openpose_file(path, k); }); };
  REQUIRE_THAT(code_of(dir.write("a.json", "{\"people\": [ {"), 0).what(), ContainsSubstring("a.json: malformed JSON"));
  REQUIRE_THAT(code_of(dir.write("b.json", "{\"persons\": []}"), 0).what(), ContainsSubstring("no 'people'"));
  REQUIRE_THAT(code_of(dir.write("c.json", openpose_json({{1, 2}})), 0).what(), ContainsSubstring("not a multiple of 3"));
  REQUIRE_THAT(code_of(dir.write("d.json", openpose_json({{1, 2, 0.5}})), 25).what(),
               ContainsSubstring("has 1 keypoints, the layout has 25"));
  REQUIRE_THAT(code_of(dir.write("e.json", "{\"people\":[{\"pose_keypoints_2d\":[1,\"x\",0.5]}]}"), 0).what(),
               ContainsSubstring("not numeric"));
  REQUIRE(code_of(dir.file("none.json"), 0).code() == Errc::io);
}

TEST_CASE("a recording folder: cameras by name, frames by file name, layout detected", "[formats][json]") {
  testing::TempDir dir;
  const Calibration calib = synth::make_camera_ring({});
  const auto motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 3, 10);
  std::mt19937 rng(1);
  for (LayoutId id : {LayoutId::body25, LayoutId::body25b, LayoutId::coco17}) {
    const std::string root = dir.file(std::string(layout(id).name));
    for (size_t f = 0; f < motion.frames.size(); ++f) {
      const auto views = synth::observe(calib, synth::to_layout(motion.frames[f], id), id, {0.5, 0, 0, 0}, rng);
      for (size_t v = 0; v < 2; ++v) {
        std::vector<double> flat;
        for (const auto& k : views[v].at(0)) flat.insert(flat.end(), {k.x, k.y, k.confidence});
        dir.write(std::string(layout(id).name) + "/cam" + std::to_string(v) + "/f" + std::to_string(f) + ".json",
                  openpose_json({flat}));
      }
    }
    dir.write(std::string(layout(id).name) + "/cam1/f9.json", openpose_json({}));  // an extra, unmatched frame
    const OpenPoseRecording rec(root, LayoutId::automatic);
    REQUIRE(rec.layout() == id);
    REQUIRE(rec.view_count() == 2);
    REQUIRE(rec.frame_count() == 3);  // the shortest camera folder decides
    REQUIRE(rec.view_name(1) == "cam1");
    REQUIRE(rec.read_frame(2)[0].size() == 1);
  }
  REQUIRE(error_of([&] { OpenPoseRecording(dir.file("nothing"), LayoutId::automatic); }).code() == Errc::io);
}

TEST_CASE("TRC and CSV writers", "[formats][trc]") {
  testing::TempDir dir;
  MotionTrack t;
  t.markers = {"A", "B"};
  t.rate_hz = 60;
  const double nan = std::nan("");
  t.frames = {{{1, 2, 3}, {4, 5, 6}}, {{7, 8, 9}, {nan, nan, nan}}};
  SECTION("TRC round trip, Z-up turned to Y-up as Pose2Sim does") {
    write_trc(dir.file("a.trc"), t, true);
    const MotionTrack r = read_trc(dir.file("a.trc"));
    REQUIRE(r.markers == t.markers);
    REQUIRE(r.rate_hz == 60);
    REQUIRE(r.frames.size() == 2);
    REQUIRE((r.frames[0][0] - Eigen::Vector3d(2, 3, 1)).norm() < 1e-12);
    REQUIRE(std::isnan(r.frames[1][1].x()));
  }
  SECTION("CSV header and empty cells") {
    write_csv(dir.file("a.csv"), t);
    std::ifstream in(dir.file("a.csv"));
    std::string header, row0, row1;
    std::getline(in, header);
    std::getline(in, row0);
    std::getline(in, row1);
    REQUIRE(header == "frame,time,A_x,A_y,A_z,B_x,B_y,B_z");
    REQUIRE(row0 == "0,0,1,2,3,4,5,6");
    REQUIRE(row1 == "1,0.0166666667,7,8,9,,,");
  }
  SECTION("the frames' own times go into TRC's Time column and the CSV's time column, and come back") {
    t.times_s = {0, 0.05};  // the second frame came 50 ms after the first, not 1/60 s
    write_trc(dir.file("t.trc"), t, false);
    write_csv(dir.file("t.csv"), t);
    const MotionTrack trc = read_trc(dir.file("t.trc"));
    REQUIRE(trc.times_s.size() == 2);
    CHECK(trc.times_s[1] == Catch::Approx(0.05));
    const MotionTrack csv = read_csv(dir.file("t.csv"), 60);
    REQUIRE(csv.times_s.size() == 2);
    CHECK(csv.times_s[1] == Catch::Approx(0.05));
    CHECK((csv.frames[0][1] - Eigen::Vector3d(4, 5, 6)).norm() < 1e-12);
    CHECK(std::isnan(csv.frames[1][1].x()));
  }
  SECTION("a CSV from before the time column still reads, its times from the rate") {
    const MotionTrack old = read_csv(dir.write("old.csv", "frame,A_x,A_y,A_z\n0,1,2,3\n1,4,5,6\n"), 25);
    REQUIRE(old.frames.size() == 2);
    CHECK(old.time_of(1) == Catch::Approx(0.04));
    CHECK((old.frames[1][0] - Eigen::Vector3d(4, 5, 6)).norm() < 1e-12);
  }
  SECTION("a CSV whose time is not a number is refused with its line") {
    const Error e = error_of([&] { read_csv(dir.write("bad.csv", "frame,time,A_x,A_y,A_z\n0,soon,1,2,3\n"), 25); });
    CHECK(e.code() == Errc::parse);
    CHECK_THAT(e.what(), ContainsSubstring("soon"));
  }
}

TEST_CASE("BVH: CMU motion parses and forward kinematics keeps bone lengths", "[formats][bvh]") {
  const BvhMotion m = read_bvh(synth::default_bvh_path());
  REQUIRE(m.frames.size() == 2752);
  REQUIRE(m.frame_time == Catch::Approx(1.0 / 120).epsilon(0.01));
  const int knee = m.find("LeftLeg"), hip = m.find("LeftUpLeg");
  REQUIRE(knee > hip);
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Matrix3d> R;
  m.pose(0, P, R);
  const double len0 = (P[knee] - P[hip]).norm();
  m.pose(1500, P, R);
  REQUIRE((P[knee] - P[hip]).norm() == Catch::Approx(len0).epsilon(1e-9));
  REQUIRE(len0 == Catch::Approx(m.joints[knee].offset.norm()).epsilon(1e-9));

  testing::TempDir dir;
  const Error e = error_of([&] { read_bvh(dir.write("x.bvh", "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 zero\n")); });
  REQUIRE(e.code() == Errc::parse);
  REQUIRE_THAT(e.what(), ContainsSubstring("x.bvh") && ContainsSubstring("zero"));
}
