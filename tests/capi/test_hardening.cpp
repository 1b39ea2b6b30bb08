// Regressions of what a fuzzing, sanitizer and soak campaign found: each input below once crashed, hung, allocated
// gigabytes, overflowed or came back as a wrong answer. Each must now be a clear error (or a bounded, right answer).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <sys/wait.h>

#include <opencv2/imgcodecs.hpp>

#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "octocap/octocap.h"
#include "support/capi_helpers.h"
#include "support/run_command.h"
#include "support/temp_dir.h"
#include "synth.h"

using Catch::Matchers::ContainsSubstring;
namespace fs = std::filesystem;

namespace {

const std::string kSample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";

void write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// Exit status of a command; a crash (signal) is reported as 128 + signal by the shell.
int exit_status(const testing::Run& r) { return WIFEXITED(r.status) ? WEXITSTATUS(r.status) : 128 + WTERMSIG(r.status); }

octocap_result_t open_motion(const std::string& path) {
  octocap_motion_t* m = nullptr;
  const octocap_result_t r = octocap_motion_open(path.c_str(), &m);
  octocap_motion_destroy(m);
  return r;
}

std::string bvh_header(const std::string& joints, const std::string& frames_line) {
  return "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n" +
         joints + "}\nMOTION\n" + frames_line + "\nFrame Time: 0.0083\n";
}

}  // namespace

#ifdef OCTOCAP_HAVE_ONNXRUNTIME  // needs the detector
TEST_CASE("hardening: a model card without its .onnx is an IO error, in a fresh process too", "[hardening]") {
  testing::TempDir dir;
  const std::string models = dir.file("models");
  fs::create_directories(models);
  // The shipped cards, without the models next to them.
  for (const auto& e : fs::directory_iterator(std::string(OCTOCAP_SOURCE_DIR) + "/models/cards"))
    if (e.path().extension() == ".json") fs::copy_file(e.path(), models + "/" + e.path().filename().string());
  REQUIRE(fs::exists(models + "/movenet-thunder.json"));
  const std::string images = dir.file("images");
  for (const char* cam : {"/cam1", "/cam2"}) {
    fs::create_directories(images + cam);
    cv::imwrite(images + cam + "/000.png", cv::Mat(48, 64, CV_8UC3, cv::Scalar(30, 60, 90)));
  }
  const testing::Run r = testing::run_command("OCTOCAP_MODELS_DIR=" + models + " " + OCTOCAP_CLI_PATH +
                                              " detect --images " + images + " --output " + dir.file("out"));
  INFO(r.output);
  CHECK(exit_status(r) == 1);  // an error message, not SIGSEGV (139)
  CHECK_THAT(r.output, ContainsSubstring("not found"));


  octocap_detector_config_t cfg;
  octocap_detector_config_init(&cfg);
  std::snprintf(cfg.model, sizeof cfg.model, "%s/movenet-thunder.onnx", models.c_str());
  octocap_detector_t* d = nullptr;
  CHECK(octocap_detector_create(&cfg, &d) == OCTOCAP_ERROR_IO);
  CHECK(d == nullptr);
}
#endif

TEST_CASE("hardening: hostile BVH files are parse errors, without deep recursion or huge allocations", "[hardening]") {
  testing::TempDir dir;
  std::string nested;
  for (int i = 0; i < 30000; ++i) nested += "JOINT j" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n";
  for (int i = 0; i < 30000; ++i) nested += "}\n";
  write(dir.file("nested.bvh"), bvh_header(nested, "Frames: 1") + "0 0 0 0 0 0\n");
  CHECK(open_motion(dir.file("nested.bvh")) == OCTOCAP_ERROR_PARSE);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("nested deeper than"));

  // 161 bytes that claim 5 million frames: fails at the end of the file, allocating nothing like the 0.5 GB
  // those frames would take (50 million is refused outright, below).
  write(dir.file("claims.bvh"), bvh_header("", "Frames: 5000000") + "0 0 0 0 0 0\n");
  CHECK(open_motion(dir.file("claims.bvh")) == OCTOCAP_ERROR_PARSE);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("end of file"));
  for (const char* frames : {"Frames: 1e300", "Frames: 0", "Frames: -3", "Frames: 2.5", "Frames: 50000000"}) {
    INFO(frames);
    write(dir.file("frames.bvh"), bvh_header("", frames) + "0 0 0 0 0 0\n");
    CHECK(open_motion(dir.file("frames.bvh")) == OCTOCAP_ERROR_PARSE);
    CHECK_THAT(octocap_last_error(), ContainsSubstring("Frames:"));
  }
}

TEST_CASE("hardening: board specs that overflow the regex stack or an int are invalid arguments", "[hardening]") {
  testing::TempDir dir;
  fs::create_directories(dir.file("empty"));
  octocap_camera_t cam;
  float rms = 0;
  uint32_t used = 0, rejected = 0;
  const std::string long_spec = "checkerboard:" + std::string(30000, '9') + "x5:0.02";
  for (const std::string& spec : {long_spec, std::string("checkerboard:99999999999x5:0.02"),
                                  std::string("charuco:5x99999999999:0.04:0.03"), std::string("charuco:") + std::string(30000, '5')}) {
    INFO(spec.substr(0, 40));
    CHECK(octocap_calibration_solve_intrinsics(dir.file("empty").c_str(), spec.c_str(), &cam, &rms, &used, &rejected,
                                               nullptr) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  }
}

TEST_CASE("hardening: octocap-calibrate refuses bad distances and report paths with a message", "[hardening]") {
  testing::TempDir dir;
  const std::string calib = kSample + "/calibration.toml";
  for (const char* distance : {"0:1:abc", "0:1:", "0:1:-2", "0:1:nan", "0:nosuchcam:1.5"}) {
    const testing::Run r = testing::run_command(std::string(OCTOCAP_CALIBRATE_PATH) + " extrinsics --calibration " +
                                                calib + " --keypoints " + kSample + "/keypoints --camera-distance " +
                                                distance + " --output " + dir.file("out.toml"));
    INFO(distance << ": " << r.output);
    CHECK(exit_status(r) == 2);
    CHECK_THAT(r.output, ContainsSubstring("--camera-distance"));
  }
  fs::create_directories(dir.file("boards/cam1"));
  write(dir.file("a_file"), "x");
  const testing::Run r = testing::run_command(std::string(OCTOCAP_CALIBRATE_PATH) + " intrinsics --images " +
                                              dir.file("boards") + " --board checkerboard:7x5:0.03 --output " +
                                              dir.file("i.toml") + " --report " + dir.file("a_file"));
  INFO(r.output);
  CHECK(exit_status(r) == 1);  // an error, not an abort (134)
  CHECK_THAT(r.output, ContainsSubstring("error"));
}

TEST_CASE("hardening: absurd cameras are refused; no NaN is ever reported as a solved point", "[hardening]") {
  octocap_calibration_t* calib = nullptr;
  REQUIRE(octocap_calibration_load((kSample + "/calibration.toml").c_str(), &calib) == OCTOCAP_OK);
  testing::Calib guard(calib);
  octocap_camera_t cam;
  REQUIRE(octocap_calibration_get_camera(calib, 0, &cam) == OCTOCAP_OK);
  octocap_camera_t bad = cam;
  bad.rotation[0] = 1e300;
  octocap_calibration_t* out = nullptr;
  CHECK(octocap_calibration_create(&bad, 1, &out) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("rotation"));
  bad = cam;
  bad.translation[2] = 1e300;
  CHECK(octocap_calibration_create(&bad, 1, &out) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  bad = cam;
  bad.width = 3000000000u;  // would wrap an int
  CHECK(octocap_calibration_create(&bad, 1, &out) == OCTOCAP_ERROR_INVALID_ARGUMENT);

  testing::TempDir dir;
  std::ifstream in(kSample + "/calibration.toml");
  std::string toml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = toml.find("rotation = [");
  REQUIRE(at != std::string::npos);
  std::string absurd = toml;
  absurd.replace(at, toml.find(']', at) - at + 1, "rotation = [ 1e300, 0.0, 0.0]");
  write(dir.file("absurd.toml"), absurd);
  CHECK(octocap_calibration_load(dir.file("absurd.toml").c_str(), &out) == OCTOCAP_ERROR_PARSE);
  std::string huge = toml;
  const size_t s = huge.find("size = [");
  huge.replace(s, huge.find(']', s) - s + 1, "size = [ 3000000000.0, 720.0]");
  write(dir.file("huge.toml"), huge);
  CHECK(octocap_calibration_load(dir.file("huge.toml").c_str(), &out) == OCTOCAP_ERROR_PARSE);
}

TEST_CASE("hardening: motion files with out-of-range numbers and rates are parse errors", "[hardening]") {
  testing::TempDir dir;
  auto trc = [&](const std::string& rate, const std::string& x) {
    return "PathFileType\t4\t(X/Y/Z)\tx.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n" + rate +
           "\t30\t1\t2\tm\nFrame#\tTime\tRHip\t\t\tLHip\t\t\n\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n1\t0\t" + x +
           "\t1\t0\t0.2\t1\t0\n";
  };
  for (const std::string& x : {std::string("1e308"), std::string("1e39"), std::string("-2e6"), std::string("1.5abc")}) {
    INFO(x);
    write(dir.file("big.trc"), trc("30", x));
    CHECK(open_motion(dir.file("big.trc")) == OCTOCAP_ERROR_PARSE);
  }
  for (const std::string& rate : {std::string("abc"), std::string("-30"), std::string("nan"), std::string("1e-300")}) {
    INFO(rate);
    write(dir.file("rate.trc"), trc(rate, "0"));
    CHECK(open_motion(dir.file("rate.trc")) == OCTOCAP_ERROR_PARSE);
    CHECK_THAT(octocap_last_error(), ContainsSubstring("DataRate"));
  }
  write(dir.file("ok.trc"), trc("30", "-0.2"));
  CHECK(open_motion(dir.file("ok.trc")) != OCTOCAP_ERROR_INTERNAL);
}

TEST_CASE("hardening: camera names with quotes and backslashes survive a save and a load", "[hardening]") {
  octocap_calibration_t* calib = nullptr;
  REQUIRE(octocap_calibration_load((kSample + "/calibration.toml").c_str(), &calib) == OCTOCAP_OK);
  testing::Calib guard(calib);
  octocap_camera_t cams[2];
  REQUIRE(octocap_calibration_get_camera(calib, 0, &cams[0]) == OCTOCAP_OK);
  REQUIRE(octocap_calibration_get_camera(calib, 1, &cams[1]) == OCTOCAP_OK);
  std::snprintf(cams[0].name, sizeof cams[0].name, "%s", "a \"quoted\" \\ name");
  std::snprintf(cams[1].name, sizeof cams[1].name, "%s", "tab\there");
  octocap_calibration_t* named = nullptr;
  REQUIRE(octocap_calibration_create(cams, 2, &named) == OCTOCAP_OK);
  testing::Calib guard2(named);
  testing::TempDir dir;
  REQUIRE(octocap_calibration_save(named, dir.file("named.toml").c_str()) == OCTOCAP_OK);
  octocap_calibration_t* back = nullptr;
  REQUIRE(octocap_calibration_load(dir.file("named.toml").c_str(), &back) == OCTOCAP_OK);
  testing::Calib guard3(back);
  octocap_camera_t c;
  REQUIRE(octocap_calibration_get_camera(back, 0, &c) == OCTOCAP_OK);
  CHECK(std::string(c.name) == "a \"quoted\" \\ name");
  REQUIRE(octocap_calibration_get_camera(back, 1, &c) == OCTOCAP_OK);
  CHECK(std::string(c.name) == "tab\there");
}

TEST_CASE("hardening: extreme frame numbers and timestamps are refused or handled, never overflowed", "[hardening]") {
  octocap_calibration_t* calib = nullptr;
  REQUIRE(octocap_calibration_load((kSample + "/calibration.toml").c_str(), &calib) == OCTOCAP_OK);
  testing::Calib guard(calib);
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  octocap_session_t* s = nullptr;
  for (int64_t first : {INT64_MIN, int64_t{-1}, INT64_MAX}) {
    cfg.first_frame_index = first;
    CHECK(octocap_session_create(&cfg, calib, &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  }
  cfg.first_frame_index = 0;
  cfg.delta_m = 1e-6f;  // with many candidates: seconds a frame; refused
  CHECK(octocap_session_create(&cfg, calib, &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  cfg.delta_m = 0.01f;
  cfg.max_candidates = 100000;
  CHECK(octocap_session_create(&cfg, calib, &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  octocap_session_config_init(&cfg);
  testing::Session session = testing::make_session(calib, cfg);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open((kSample + "/keypoints").c_str(), OCTOCAP_LAYOUT_AUTO, &rec) == OCTOCAP_OK);
  std::vector<octocap_keypoint2d_t> kps(4096);
  uint32_t people[8], n = 0;
  REQUIRE(octocap_recording_read_frame(rec, 0, kps.data(), 4096, &n, people, 5) == OCTOCAP_OK);
  octocap_recording_destroy(rec);
  // The filter's time step between the two extremes overflows int64; it must be computed without UB (UBSan pass).
  CHECK(octocap_session_solve_keypoints(session.get(), kps.data(), people, 5, INT64_MIN) == OCTOCAP_OK);
  CHECK(octocap_session_solve_keypoints(session.get(), kps.data(), people, 5, INT64_MAX) == OCTOCAP_OK);
  octocap_joint_t j[25];
  REQUIRE(octocap_session_get_keypoints3d(session.get(), j, 25, &n) == OCTOCAP_OK);
  for (const auto& p : j)
    if (p.valid) CHECK((std::isfinite(p.position[0]) && std::isfinite(p.position[1]) && std::isfinite(p.position[2])));
}

TEST_CASE("hardening: two people in 18 views is solved, the right person picked, in bounded work", "[hardening]") {
  using namespace octocap::internal;
  synth::RigOptions rig;
  rig.cameras = 18;
  rig.distortion = false;
  const Calibration cams = synth::make_camera_ring(rig);
  testing::Calib calib = testing::make_calibration(cams);
  const synth::Motion actor = synth::load_cmu_motion(synth::default_bvh_path(), 0, 3, 10);
  std::mt19937 rng(3);
  synth::NoiseOptions noise;
  noise.missing = noise.outlier = noise.swap = 0;
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  testing::Session s = testing::make_session(calib.get(), cfg);
  for (size_t f = 0; f < actor.frames.size(); ++f) {
    // A bystander 2 m to the side, at the edge of the volume: seen by 6 of the 18 cameras, listed first there.
    std::vector<Eigen::Vector3d> other = actor.frames[(f + 1) % actor.frames.size()];
    for (auto& p : other) p += Eigen::Vector3d(2.0, 0, 0.5);
    auto views = synth::observe(cams, actor.frames[f], LayoutId::body25, noise, rng);
    const auto bystander = synth::observe(cams, other, LayoutId::body25, noise, rng);
    for (size_t v = 0; v < views.size(); ++v)
      if (v % 3 == 0)
        for (const auto& p : bystander[v]) views[v].insert(views[v].begin(), p);
    const synth::FlatFrame flat = synth::flatten(views);
    REQUIRE(octocap_session_solve_keypoints(s.get(), reinterpret_cast<const octocap_keypoint2d_t*>(flat.xyc.data()),
                                            flat.people_per_view.data(), 18, static_cast<int64_t>(f) * 33333) == OCTOCAP_OK);
    octocap_joint_t j[25];
    uint32_t n = 0;
    REQUIRE(octocap_session_get_keypoints3d(s.get(), j, 25, &n) == OCTOCAP_OK);
    double err = 0;
    int solved = 0;
    for (int k = 0; k < 25; ++k) {
      if (!j[k].valid) continue;
      err += (Eigen::Vector3d(j[k].position[0], j[k].position[1], j[k].position[2]) - actor.frames[f][k]).norm();
      ++solved;
    }
    REQUIRE(solved >= 20);
    CHECK(err / solved < 0.03);  // the actor, not the bystander 2 m away
  }
}

TEST_CASE("hardening: a JSON number out of double's range is a parse error", "[hardening]") {
  testing::TempDir dir;
  for (const char* cam : {"cam1", "cam2"}) {
    fs::create_directories(dir.file(cam));
    write(dir.file(cam) + "/0.json", "{\"people\": [{\"pose_keypoints_2d\": [1e999, 2, 0.9]}]}");
  }
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open(dir.path().string().c_str(), OCTOCAP_LAYOUT_COCO_17, &rec) == OCTOCAP_OK);
  uint32_t n = 0, people[2];
  CHECK(octocap_recording_read_frame(rec, 0, nullptr, 0, &n, people, 2) == OCTOCAP_ERROR_PARSE);
  CHECK_THAT(octocap_last_error(), ContainsSubstring("0.json"));
  octocap_recording_destroy(rec);
}

TEST_CASE("hardening: octocap solve leaves no partial file behind and refuses impossible ranges", "[hardening]") {
  testing::TempDir dir;
  // A copy of the sample whose frame 45 is malformed in one camera.
  fs::copy(kSample + "/keypoints", dir.file("kp"), fs::copy_options::recursive);
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir.file("kp/cam_2"))) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  write(files.at(45).string(), "{\"people\": [");
  const std::string base = std::string(OCTOCAP_CLI_PATH) + " solve --calibration " + kSample + "/calibration.toml --keypoints ";
  testing::Run r = testing::run_command(base + dir.file("kp") + " --output " + dir.file("take.trc") + " --csv " +
                                        dir.file("take.csv"));
  INFO(r.output);
  CHECK(exit_status(r) == 1);
  CHECK_THAT(r.output, ContainsSubstring("malformed JSON"));
  CHECK_FALSE(fs::exists(dir.file("take.trc")));
  CHECK_FALSE(fs::exists(dir.file("take.csv")));
  r = testing::run_command(base + kSample + "/keypoints --output " + dir.file("a.trc") + " --start-frame 90");
  CHECK(exit_status(r) == 1);
  CHECK_THAT(r.output, ContainsSubstring("past the last frame"));
  CHECK_FALSE(fs::exists(dir.file("a.trc")));
  r = testing::run_command(base + kSample + "/keypoints --output " + dir.file("b.trc") + " --rate 1e-300");
  CHECK(exit_status(r) == 1);
  CHECK_THAT(r.output, ContainsSubstring("--rate"));
  // --start-frame + --frames past 2^32 is the rest of the take, not a wrapped, empty one.
  r = testing::run_command(base + kSample + "/keypoints --output " + dir.file("c.trc") +
                           " --start-frame 80 --frames 4294967295");
  INFO(r.output);
  CHECK(exit_status(r) == 0);
  CHECK_THAT(r.output, ContainsSubstring("frames solved:        10 / 10"));
}
