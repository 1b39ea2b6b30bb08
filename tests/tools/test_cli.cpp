// The `octocap` command line, run as a user runs it, on the built-in sample recording.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <Eigen/Geometry>

#include "io/bvh.h"
#include "io/calibration_toml.h"
#include "io/motion_files.h"
#include "io/openpose_json.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

using Catch::Matchers::ContainsSubstring;

namespace {

using testing::Run;

Run run(const std::string& args, const char* program = OCTOCAP_CLI_PATH) {
  return testing::run_command(std::string(program) + " " + args);
}

const std::string kSample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";

}  // namespace

TEST_CASE("octocap solve on the sample: TRC, CSV and accuracy against its ground truth", "[cli]") {
  testing::TempDir dir;
  for (const char* method : {"subdivision", "triangulation"}) {
    INFO(method);
    const Run r = run("solve --calibration " + kSample + "/calibration.toml --keypoints " + kSample +
                      "/keypoints --output " + dir.file("a.trc") + " --csv " + dir.file("a.csv") + " --bvh " +
                      dir.file("a.bvh") + " --ground-truth " + kSample + "/ground_truth.csv --method " + method +
                      " --quiet");
    INFO(r.output);
    REQUIRE(r.status == 0);
    REQUIRE_THAT(r.output, ContainsSubstring("layout BODY_25"));
    std::smatch m;
    REQUIRE(std::regex_search(r.output, m, std::regex("MPJPE ([0-9.]+) mm")));
    CHECK(std::stod(m[1]) < 15.0);
    REQUIRE(std::regex_search(r.output, m, std::regex("median ([0-9.]+) px")));
    CHECK(std::stod(m[1]) < 3.0);

    const octocap::internal::MotionTrack trc = octocap::internal::read_trc(dir.file("a.trc"));
    REQUIRE(trc.markers.size() == 25);
    REQUIRE(trc.markers[0] == "Nose");
    REQUIRE(trc.frames.size() == 90);
    std::ifstream csv(dir.file("a.csv"));
    std::string header;
    std::getline(csv, header);
    REQUIRE(header.rfind("frame,time,Nose_x,Nose_y,Nose_z,Neck_x,Neck_y,Neck_z,RShoulder_x", 0) == 0);
    size_t rows = 0;
    for (std::string line; std::getline(csv, line);) {
      // The sample has no picture times: frame f is at f / 30 s (the default rate), in both files.
      CHECK(std::stod(line.substr(line.find(',') + 1)) == Catch::Approx(rows / 30.0).margin(1e-6));
      CHECK(trc.time_of(rows) == Catch::Approx(rows / 30.0).margin(1e-6));
      ++rows;
    }
    REQUIRE(rows == 90);
    const octocap::internal::BvhMotion bvh = octocap::internal::read_bvh(dir.file("a.bvh"));
    REQUIRE(bvh.frames.size() == 90);
    REQUIRE(bvh.find("LeftForeArm") >= 0);
  }
}

TEST_CASE("octocap solve refuses bad input with a clear message", "[cli]") {
  testing::TempDir dir;
  Run r = run("solve --calibration " + kSample + "/calibration.toml --keypoints " + kSample +
              "/keypoints --output " + dir.file("a.trc") + " --method magic");
  REQUIRE(r.status != 0);
  REQUIRE_THAT(r.output, ContainsSubstring("--method"));
  const std::string bad = dir.write("bad.toml", "[cam_1]\nmatrix = 3\n");
  r = run("solve --calibration " + bad + " --keypoints " + kSample + "/keypoints --output " + dir.file("a.trc"));
  REQUIRE(r.status != 0);
  REQUIRE_THAT(r.output, ContainsSubstring("bad.toml"));
  // Four camera folders against a five-camera calibration.
  for (int c = 0; c < 4; ++c) dir.write("kp/cam" + std::to_string(c) + "/0.json", "{\"people\": []}");
  r = run("solve --calibration " + kSample + "/calibration.toml --keypoints " + dir.file("kp") +
          " --layout BODY_25 --output " + dir.file("a.trc"));
  REQUIRE(r.status != 0);
  REQUIRE_THAT(r.output, ContainsSubstring("4 camera folders") && ContainsSubstring("5 cameras"));
  // A mistyped option is named with the nearest real one, not hidden behind "--output is required".
  r = run("solve --calibration " + kSample + "/calibration.toml --keypoints " + kSample + "/keypoints --outptu " +
          dir.file("a.trc"));
  CHECK(WEXITSTATUS(r.status) == 2);
  CHECK_THAT(r.output, ContainsSubstring("unknown option --outptu; did you mean --output?"));
  r = run("live --calibration x.toml --camera 0 --duratoin=5");
  CHECK(WEXITSTATUS(r.status) == 2);
  CHECK_THAT(r.output, ContainsSubstring("unknown option --duratoin; did you mean --duration?"));
  r = run("sync --calibration x.toml --zzzqqqxx 3");
  CHECK(WEXITSTATUS(r.status) == 2);
  CHECK_THAT(r.output, ContainsSubstring("unknown option --zzzqqqxx (octocap sync --help lists them)"));
  // --output is TRC: a .csv or .bvh name would get TRC under it, so it is refused, naming the option that writes it.
  r = run("solve --calibration " + kSample + "/calibration.toml --keypoints " + kSample + "/keypoints --output " +
          dir.file("a.CSV"));
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("--output writes TRC; for CSV give --csv"));
  CHECK_FALSE(std::filesystem::exists(dir.file("a.CSV")));
  r = run("live --calibration " + kSample + "/calibration.toml --camera 0 --output " + dir.file("take.bvh"));
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("for BVH give --bvh"));
}

TEST_CASE("octocap --help and layouts", "[cli]") {
  Run r = run("solve --help");
  REQUIRE(r.status == 0);
  REQUIRE_THAT(r.output, ContainsSubstring("--delta-mm") && ContainsSubstring("--filter"));
  r = run("layouts");
  REQUIRE(r.status == 0);
  REQUIRE_THAT(r.output, ContainsSubstring("BODY_25B (25 keypoints): Nose LEye REye"));
}

TEST_CASE("octocap-calibrate extrinsics recovers the sample's cameras from its keypoints", "[cli][calib]") {
  testing::TempDir dir;
  const octocap::internal::Calibration truth = octocap::internal::read_calibration_toml(kSample + "/calibration.toml");
  const double d = (truth[0].center() - truth[2].center()).norm();
  const Run r = run("extrinsics --calibration " + kSample + "/calibration.toml --keypoints " + kSample +
                        "/keypoints --camera-distance cam_1:cam_3:" + std::to_string(d) + " --output " +
                        dir.file("c.toml"),
                    OCTOCAP_CALIBRATE_PATH);
  INFO(r.output);
  REQUIRE(r.status == 0);
  REQUIRE_THAT(r.output, ContainsSubstring("bundle adjustment") && ContainsSubstring("RMS"));
  const octocap::internal::Calibration got = octocap::internal::read_calibration_toml(dir.file("c.toml"));
  REQUIRE(got.size() == truth.size());
  Eigen::Matrix3Xd A(3, truth.size()), B(3, got.size());
  for (size_t i = 0; i < truth.size(); ++i) {
    A.col(i) = truth[i].center();
    B.col(i) = got[i].center();
    REQUIRE((got[i].K - truth[i].K).norm() < 1e-9);  // intrinsics are kept as given
  }
  const Eigen::Matrix4d T = Eigen::umeyama(B, A, false);
  for (size_t i = 0; i < truth.size(); ++i)
    CHECK(((T * B.col(i).homogeneous()).head<3>() - A.col(i)).norm() < 0.02);
}

TEST_CASE("octocap-calibrate refuses what it cannot do, saying why", "[cli][calib]") {
  testing::TempDir dir;
  Run r = run("extrinsics --calibration " + kSample + "/calibration.toml --keypoints " + kSample + "/keypoints --output " +
                  dir.file("c.toml"),
              OCTOCAP_CALIBRATE_PATH);
  REQUIRE(r.status != 0);
  REQUIRE_THAT(r.output, ContainsSubstring("height") && ContainsSubstring("distance"));
  r = run("intrinsics --images " + dir.path().string() + " --board checkerboard:9x6 --output " + dir.file("i.toml"),
          OCTOCAP_CALIBRATE_PATH);
  REQUIRE(r.status != 0);
  REQUIRE_THAT(r.output, ContainsSubstring("COLSxROWS:SQUARE_M"));
  r = run("--help", OCTOCAP_CALIBRATE_PATH);
  REQUIRE(r.status == 0);
  REQUIRE_THAT(r.output, ContainsSubstring("intrinsics") && ContainsSubstring("extrinsics"));
}

#ifdef OCTOCAP_HAVE_ONNXRUNTIME  // needs the detector
TEST_CASE("octocap detect writes OpenPose JSON per camera that octocap reads back", "[cli]") {
  testing::TempDir dir;
  // Two "cameras", one real photo each: the street scene and the portrait.
  const std::string photos = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/photos/";
  std::filesystem::create_directories(dir.path() / "images/cam_a");
  std::filesystem::create_directories(dir.path() / "images/cam_b");
  std::filesystem::copy_file(photos + "bus.jpg", dir.path() / "images/cam_a/000.jpg");
  std::filesystem::copy_file(photos + "astronaut.png", dir.path() / "images/cam_b/000.png");
  const Run r = run("detect --images " + dir.file("images") + " --output " + dir.file("kp") +
                    " --model movenet-multipose --detect-mode per-view --detect-threads 1 --debug-images " + dir.file("dbg"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, ContainsSubstring("views with a person:  2 / 2"));
  for (const char* cam : {"cam_a", "cam_b"}) {
    const std::string json = dir.file(std::string("kp/") + cam + "_json/" + cam + "_000000000000_keypoints.json");
    const auto people = octocap::internal::read_openpose_file(json, 17);
    CHECK(!people.empty());
    CHECK(std::filesystem::exists(dir.file(std::string("dbg/") + cam + "_frame_000000.png")));
  }
  CHECK(octocap::internal::read_openpose_file(dir.file("kp/cam_a_json/cam_a_000000000000_keypoints.json"), 17).size() >= 2);
  const Run bad = run("detect --images " + dir.file("images") + " --output " + dir.file("kp2") + " --model " + dir.file("none.onnx"));
  CHECK(bad.status != 0);
  CHECK_THAT(bad.output, ContainsSubstring("none"));
}
#endif

