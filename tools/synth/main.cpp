// Writes a synthetic multi-camera recording with ground truth, in the formats octocap reads:
//   OUT/calibration.toml, OUT/keypoints/cam_N/frame_NNNNNN.json (OpenPose), OUT/ground_truth.csv.
// The motion is real (CMU mocap subject 1, Debian's assimp-testmodels); cameras, noise, gaps, wrong
// detections, left/right swaps and a bystander are made here, from a fixed seed, so the output is repeatable.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "io/calibration_toml.h"
#include "io/motion_files.h"
#include "synth.h"

namespace fs = std::filesystem;
using namespace octocap::internal;

int main(int argc, char** argv) {
  CLI::App app{"octocap-synth: make a synthetic multi-camera keypoint recording with ground truth"};
  std::string out = "data/sample", bvh = synth::default_bvh_path();
  int cameras = 5, frames = 90, first = 600, step = 4;
  bool bystander = true;
  app.add_option("--output", out, "Output folder")->capture_default_str();
  app.add_option("--bvh", bvh, "CMU BVH motion")->capture_default_str();
  app.add_option("--cameras", cameras, "Camera count")->capture_default_str();
  app.add_option("--frames", frames, "Frame count")->capture_default_str();
  app.add_option("--first", first, "First BVH frame")->capture_default_str();
  app.add_option("--step", step, "BVH frames per output frame (120 Hz / 4 = 30 Hz)")->capture_default_str();
  app.add_option("--bystander", bystander, "Add a second person in some views")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  synth::RigOptions rig;
  rig.cameras = cameras;
  const Calibration calib = synth::make_camera_ring(rig);
  const synth::Motion motion = synth::load_cmu_motion(bvh, first, frames, step);
  fs::create_directories(out);
  write_calibration_toml(calib, out + "/calibration.toml");

  std::mt19937 rng(2024);
  synth::NoiseOptions noise;
  noise.pixel_sigma = 1.5;
  MotionTrack truth;
  truth.rate_hz = motion.rate_hz;
  for (const char* n : layout(LayoutId::body25).keypoints) truth.markers.emplace_back(n);
  for (size_t f = 0; f < motion.frames.size(); ++f) {
    auto people = synth::observe(calib, motion.frames[f], LayoutId::body25, noise, rng);
    if (bystander && f % 3 != 0) {
      // Someone standing at the edge of the volume, seen by the cameras on that side.
      std::vector<Eigen::Vector3d> other = motion.frames[0];
      for (auto& p : other) p += Eigen::Vector3d(1.8, 0, -1.2);
      auto seen = synth::observe(calib, other, LayoutId::body25, noise, rng);
      for (size_t v = 0; v < seen.size(); ++v)
        if (!seen[v].empty() && v % 2 == 0) people[v].insert(people[v].begin(), seen[v].front());
    }
    for (size_t v = 0; v < calib.size(); ++v) {
      const std::string dir = out + "/keypoints/" + calib[v].name;
      fs::create_directories(dir);
      nlohmann::json doc = {{"version", 1.3}, {"people", nlohmann::json::array()}};
      for (const auto& person : people[v]) {
        nlohmann::json kps = nlohmann::json::array();
        for (const auto& k : person) {
          kps.push_back(std::round(k.x * 100) / 100);
          kps.push_back(std::round(k.y * 100) / 100);
          kps.push_back(std::round(k.confidence * 1000) / 1000);
        }
        doc["people"].push_back({{"person_id", {-1}}, {"pose_keypoints_2d", kps}});
      }
      std::ostringstream name;
      name << dir << "/frame_" << std::setw(6) << std::setfill('0') << f << ".json";
      std::ofstream(name.str()) << doc.dump();
    }
    truth.frames.push_back(motion.frames[f]);
  }
  write_csv(out + "/ground_truth.csv", truth);
  std::printf("wrote %zu frames x %d cameras to %s (calibration.toml, keypoints/, ground_truth.csv)\n",
              motion.frames.size(), cameras, out.c_str());
  return 0;
}
