// Time offsets of unsynchronised cameras: recovered from a synthetic take with known sub-frame offsets (real CMU
// motion); the solve after sync is as accurate as the synchronised original's; Pose2Sim's real take with frames
// trimmed from two cameras, placed within three quarters of a frame (not yet exactly: see the README).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "octocap/octocap.h"
#include "support/capi_helpers.h"
#include "support/run_command.h"
#include "support/temp_dir.h"
#include "synth.h"

using Catch::Matchers::ContainsSubstring;
namespace fs = std::filesystem;
using namespace octocap::internal;

namespace {

void write_openpose(const std::string& path, const std::vector<Person2D>& people) {
  std::ofstream out(path);
  out << "{\"version\": 1.3, \"people\": [";
  for (size_t p = 0; p < people.size(); ++p) {
    out << (p ? ", " : "") << "{\"pose_keypoints_2d\": [";
    for (size_t k = 0; k < people[p].size(); ++k)
      out << (k ? ", " : "") << people[p][k].x << ", " << people[p][k].y << ", " << people[p][k].confidence;
    out << "]}";
  }
  out << "]}\n";
}

struct SyntheticTake {
  testing::TempDir dir;
  Calibration cams;
  testing::Calib calib;
  std::vector<std::vector<Eigen::Vector3d>> truth;  // on the first camera's clock, per frame
};

// Four cameras at 30 Hz whose frame j shows the motion at (j + offset[c]) / 30 s (CMU at 120 Hz: offsets in quarters).
void make_take(SyntheticTake& t, const std::vector<double>& offsets, size_t frames) {
  synth::RigOptions rig;
  rig.cameras = static_cast<int>(offsets.size());
  t.cams = synth::make_camera_ring(rig);
  t.calib = testing::make_calibration(t.cams);
  const size_t base = 40;  // 120 Hz samples before frame 0, for negative offsets
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, base * 2 + 4 * frames + 40, 1);
  std::mt19937 rng(11);
  synth::NoiseOptions noise;
  noise.outlier = noise.swap = 0;
  for (size_t c = 0; c < offsets.size(); ++c) fs::create_directories(t.dir.file("cam" + std::to_string(c)));
  for (size_t j = 0; j < frames; ++j) {
    t.truth.push_back(motion.frames[base + 4 * j]);
    for (size_t c = 0; c < offsets.size(); ++c) {
      const size_t index = static_cast<size_t>(std::llround(base + 4 * (static_cast<double>(j) + offsets[c])));
      const auto people = synth::observe(t.cams, motion.frames.at(index), LayoutId::body25, noise, rng);
      char name[32];
      std::snprintf(name, sizeof name, "/%06zu.json", j);
      write_openpose(t.dir.file("cam" + std::to_string(c)) + name, people[c]);
    }
  }
}

// Mean distance (mm) of the solved keypoints to the truth, every frame solved through the recording as it reads.
double solve_mpjpe(octocap_recording_t* rec, const octocap_calibration_t* calib,
                   const std::vector<std::vector<Eigen::Vector3d>>& truth) {
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.layout = OCTOCAP_LAYOUT_BODY_25;
  cfg.filter = OCTOCAP_FILTER_NONE;
  testing::Session s = testing::make_session(calib, cfg);
  uint32_t views = 0, frames = 0;
  octocap_recording_view_count(rec, &views);
  octocap_recording_frame_count(rec, &frames);
  std::vector<octocap_keypoint2d_t> kps(25 * 8 * views);
  std::vector<uint32_t> people(views);
  double sum = 0;
  size_t n = 0;
  for (uint32_t f = 10; f + 10 < frames && f < truth.size(); ++f) {  // the ends: some views are outside their take
    uint32_t needed = 0;
    REQUIRE(octocap_recording_read_frame(rec, f, kps.data(), static_cast<uint32_t>(kps.size()), &needed, people.data(),
                                         views) == OCTOCAP_OK);
    if (octocap_session_solve_keypoints(s.get(), kps.data(), people.data(), views, f * 33333) != OCTOCAP_OK) continue;
    octocap_joint_t j[25];
    uint32_t count = 0;
    REQUIRE(octocap_session_get_keypoints3d(s.get(), j, 25, &count) == OCTOCAP_OK);
    for (int k = 0; k < 25; ++k) {
      if (!j[k].valid || !truth[f][k].allFinite()) continue;
      sum += (Eigen::Vector3d(j[k].position[0], j[k].position[1], j[k].position[2]) - truth[f][k]).norm();
      ++n;
    }
  }
  return n ? 1000 * sum / static_cast<double>(n) : 1e9;
}

}  // namespace

TEST_CASE("sync: known sub-frame offsets of a synthetic take are recovered within 0.1 frame", "[sync]") {
  const std::vector<double> offsets = {0, 3.25, -1.5, 7.75};
  SyntheticTake take;
  make_take(take, offsets, 150);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open(take.dir.path().string().c_str(), OCTOCAP_LAYOUT_BODY_25, &rec) == OCTOCAP_OK);
  std::vector<double> found(4);
  std::vector<float> residual(4);
  REQUIRE(octocap_recording_estimate_sync(rec, take.calib.get(), 30, found.data(), residual.data(), 4) == OCTOCAP_OK);
  for (size_t c = 0; c < 4; ++c) {
    INFO("camera " << c << ": true " << offsets[c] << ", found " << found[c] << ", residual " << residual[c] << " px");
    CHECK(std::abs(found[c] - offsets[c]) <= 0.1);
  }
  // The solve of the unsynchronised take is ruined; after sync it is as good as a synchronised one.
  const double before = solve_mpjpe(rec, take.calib.get(), take.truth);
  REQUIRE(octocap_recording_set_sync(rec, found.data(), 4) == OCTOCAP_OK);
  const double after = solve_mpjpe(rec, take.calib.get(), take.truth);
  REQUIRE(octocap_recording_set_sync(rec, offsets.data(), 4) == OCTOCAP_OK);
  const double ideal = solve_mpjpe(rec, take.calib.get(), take.truth);
  INFO("MPJPE unsynchronised " << before << " mm, after sync " << after << " mm, with the true offsets " << ideal << " mm");
  CHECK(before > 2 * after);
  CHECK(after < ideal + 2.0);
  CHECK(after < 20.0);

  // The offsets survive a sync file, matched to the calibration's cameras by name.
  const std::string file = take.dir.file("sync.toml");
  REQUIRE(octocap_sync_save(file.c_str(), 30, take.calib.get(), found.data(), 4) == OCTOCAP_OK);
  std::vector<double> back(4);
  double rate = 0;
  REQUIRE(octocap_sync_load(file.c_str(), take.calib.get(), back.data(), 4, &rate) == OCTOCAP_OK);
  CHECK(rate == 30);
  for (size_t c = 0; c < 4; ++c) CHECK(std::abs(back[c] - found[c]) < 1e-9);
  std::ofstream(take.dir.file("bad.toml")) << "rate = 30.0\n[offsets_frames]\nnobody = 1.0\n";
  CHECK(octocap_sync_load(take.dir.file("bad.toml").c_str(), take.calib.get(), back.data(), 4, &rate) == OCTOCAP_ERROR_PARSE);
  CHECK(octocap_recording_set_sync(rec, found.data(), 3) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_recording_estimate_sync(rec, take.calib.get(), 30, found.data(), nullptr, 3) == OCTOCAP_ERROR_CAMERA_MISMATCH);
  octocap_recording_destroy(rec);
}

TEST_CASE("octocap sync writes the offsets; octocap solve --sync solves the take as if it were synchronised", "[sync][cli]") {
  const std::vector<double> offsets = {0, -2.5, 4.25};
  SyntheticTake take;
  make_take(take, offsets, 120);
  const std::string calib = take.dir.file("calib.toml");
  REQUIRE(octocap_calibration_save(take.calib.get(), calib.c_str()) == OCTOCAP_OK);
  const std::string cli = OCTOCAP_CLI_PATH;
  testing::Run r = testing::run_command(cli + " sync --calibration " + calib + " --keypoints " + take.dir.path().string() +
                                        " --output " + take.dir.file("sync.toml"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, ContainsSubstring("offset"));
  std::vector<double> found(3);
  REQUIRE(octocap_sync_load(take.dir.file("sync.toml").c_str(), take.calib.get(), found.data(), 3, nullptr) == OCTOCAP_OK);
  for (size_t c = 0; c < 3; ++c) CHECK(std::abs(found[c] - offsets[c]) <= 0.1);
  // The median reprojection error the solve reports: the views agree only once the take is synchronised.
  auto median_px = [&](const std::string& extra) {
    const testing::Run s = testing::run_command(cli + " solve --calibration " + calib + " --keypoints " +
                                                take.dir.path().string() + " --output " + take.dir.file("out.trc") + extra);
    INFO(s.output);
    REQUIRE(s.status == 0);
    const size_t at = s.output.find("median ");
    REQUIRE(at != std::string::npos);
    return std::stod(s.output.substr(at + 7));
  };
  const double before = median_px(""), after = median_px(" --sync " + take.dir.file("sync.toml"));
  INFO("median reprojection: unsynchronised " << before << " px, after sync " << after << " px");
  CHECK(after < 0.5 * before);
  CHECK(after < 3.0);

  // Mistakes say what to fix, in the options' own words.
  const std::string base = cli + " sync --calibration " + calib + " --keypoints " + take.dir.path().string() +
                           " --output " + take.dir.file("bad.toml");
  r = testing::run_command(base + " --rate 1e-9");
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("--rate must be between"));
  r = testing::run_command(base + " --rate nan");
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("--rate") && !ContainsSubstring("max_offset_frames"));
  r = testing::run_command(base + " --max-offset-s 0.01");
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("less than one frame"));
  CHECK_FALSE(std::filesystem::exists(take.dir.file("bad.toml")));
  // A sync file whose offset for one camera is longer than the take: solved without that view, and said so.
  const std::string far = take.dir.file("far.toml");
  const double far_offsets[3] = {0, 500, 4.25};
  REQUIRE(octocap_sync_save(far.c_str(), 30, take.calib.get(), far_offsets, 3) == OCTOCAP_OK);
  r = testing::run_command(cli + " solve --calibration " + calib + " --keypoints " + take.dir.path().string() +
                           " --output " + take.dir.file("far.trc") + " --sync " + far);
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK_THAT(r.output, ContainsSubstring("offset of 500.0 frames leaves it in 0 of the take's 120 frames"));
  // And solve without a source says which to give.
  r = testing::run_command(cli + " solve --calibration " + calib + " --output " + take.dir.file("none.trc"));
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("give --keypoints or --images"));
}

TEST_CASE("sync: frames trimmed from real cameras of Pose2Sim's take are found within 0.75 frame", "[sync][real]") {
  const std::string demo = std::string(OCTOCAP_REAL_DATA_DIR) + "/Demo";
  testing::TempDir dir;
  // Cameras 2 and 3 started 3 and 5 frames late: their first files are gone, so their frame i is the original i + 3
  // (i + 5), captured at i + 3 (i + 5) on camera 1's clock.
  const int trimmed[4] = {0, 3, 5, 0};
  for (int c = 0; c < 4; ++c) {
    const std::string from = demo + "/pose/cam" + std::to_string(c + 1) + "_json";
    const std::string to = dir.file("cam" + std::to_string(c + 1) + "_json");
    fs::create_directories(to);
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(from)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (size_t i = static_cast<size_t>(trimmed[c]); i < files.size(); ++i)
      fs::copy_file(files[i], to + "/" + files[i].filename().string());
  }
  octocap_calibration_t* calib = nullptr;
  REQUIRE(octocap_calibration_load((demo + "/calibration/Calib_qualisys.toml").c_str(), &calib) == OCTOCAP_OK);
  testing::Calib guard(calib);
  octocap_recording_t* rec = nullptr;
  REQUIRE(octocap_recording_open(dir.path().string().c_str(), OCTOCAP_LAYOUT_BODY_25B, &rec) == OCTOCAP_OK);
  std::vector<double> found(4);
  std::vector<float> residual(4);
  REQUIRE(octocap_recording_estimate_sync(rec, calib, 9, found.data(), residual.data(), 4) == OCTOCAP_OK);
  for (int c = 0; c < 4; ++c) {
    INFO("camera " << c + 1 << ": trimmed " << trimmed[c] << ", found " << found[c] << ", residual " << residual[c] << " px");
    CHECK(std::abs(found[c] - trimmed[c]) <= 0.75);
  }
  octocap_recording_destroy(rec);
}
