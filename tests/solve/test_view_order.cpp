// Views given in another order than the calibration's cameras: found from the 2D people alone, on known cameras and
// motion, and on Pose2Sim's real take with two views swapped.
#include <catch2/catch_test_macros.hpp>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "solve/view_order.h"
#include "support/run_command.h"
#include "support/synth.h"
#include "support/temp_dir.h"

using namespace octocap::internal;

namespace {

// `frames` frames of CMU walking seen by the ring's cameras with the usual detector faults; people[view] as the
// cameras took them, then handed to the check in the order `given` (given[i]: the camera whose pictures come as
// view i).
ViewOrderCheck check_order(const Calibration& calib, const std::vector<int>& given, size_t frames = 60) {
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, frames, 4);
  std::mt19937 rng(11);
  ViewOrderCheck check(calib, 0.3, 15);
  for (size_t f = 0; f < frames; ++f) {
    const auto taken = synth::observe(calib, motion.frames[f], LayoutId::body25, synth::NoiseOptions{}, rng);
    std::vector<std::vector<Person2D>> people(calib.size());
    for (size_t v = 0; v < calib.size(); ++v) people[v] = taken[static_cast<size_t>(given[v])];
    const bool decides = check.add(people);
    CHECK(decides == (f + 1 == frames));
  }
  return check;
}

}  // namespace

TEST_CASE("views in the calibration's order are not reported; two swapped are named, so is a rotated order",
          "[solve][view_order]") {
  synth::RigOptions rig;
  rig.cameras = 5;
  const Calibration calib = synth::make_camera_ring(rig);

  const ViewOrderCheck right = check_order(calib, {0, 1, 2, 3, 4});
  REQUIRE(right.decided());
  CHECK(right.verdict().empty());
  CHECK(right.given_agreement() > 0.8);  // the detector's faults cost the rest
  CHECK(right.best() == std::vector<int>{0, 1, 2, 3, 4});

  const ViewOrderCheck swapped = check_order(calib, {0, 2, 1, 3, 4});
  INFO(swapped.verdict());
  CHECK(swapped.verdict().find("cameras cam_2 and cam_3 look swapped") == 0);
  CHECK(swapped.best() == std::vector<int>{0, 2, 1, 3, 4});
  CHECK(swapped.given_agreement() < 0.6);
  CHECK(swapped.best_agreement() > 0.8);

  // Pictures of cam_3 given as cam_2, of cam_4 as cam_3, of cam_2 as cam_4.
  const ViewOrderCheck rotated = check_order(calib, {0, 2, 3, 1, 4});
  INFO(rotated.verdict());
  CHECK(rotated.verdict().find("out of the calibration's order") != std::string::npos);
  CHECK(rotated.verdict().find("the pictures given as cam_2 fit cam_3") != std::string::npos);
  CHECK(rotated.best() == std::vector<int>{0, 2, 3, 1, 4});
}

TEST_CASE("the view order is judged only with three views or more that saw people, once", "[solve][view_order]") {
  synth::RigOptions rig;
  rig.cameras = 2;
  ViewOrderCheck two(synth::make_camera_ring(rig), 0.3, 15, 1);
  const std::vector<std::vector<Person2D>> someone(2, std::vector<Person2D>{Person2D(25, Keypoint2D{100, 100, 1})});
  CHECK_FALSE(two.add(someone));  // two views: a swap fails to solve visibly, nothing to outvote
  CHECK_FALSE(two.decided());

  rig.cameras = 4;
  ViewOrderCheck four(synth::make_camera_ring(rig), 0.3, 15, 1);
  std::vector<std::vector<Person2D>> two_of_four(4);
  two_of_four[0] = two_of_four[1] = someone[0];
  CHECK_FALSE(four.add(two_of_four));
  CHECK_FALSE(four.add({}));  // a frame of another view count is not counted
  CHECK_FALSE(four.decided());
}

TEST_CASE("Pose2Sim's real take with cam_02 and cam_03 swapped: solve says so, the right order says nothing",
          "[solve][view_order][real]") {
  const std::string demo = std::string(OCTOCAP_REAL_DATA_DIR) + "/Demo";
  REQUIRE(std::filesystem::exists(demo + "/pose/cam2_json"));
  testing::TempDir dir;
  // The views are read in their folders' order: cam3's keypoints come second, cam2's third.
  std::filesystem::create_directories(dir.file("pose"));
  const char* order[] = {"cam1_json", "cam3_json", "cam2_json", "cam4_json"};
  for (int i = 0; i < 4; ++i)
    std::filesystem::create_directory_symlink(demo + "/pose/" + order[i],
                                              dir.file("pose/view" + std::to_string(i + 1) + "_json"));
  const std::string calib = demo + "/calibration/Calib_qualisys.toml";
  const auto swapped = testing::run_command(std::string(OCTOCAP_CLI_PATH) + " solve --calibration " + calib +
                                            " --keypoints " + dir.file("pose") + " --output " +
                                            dir.file("swapped.trc"));
  INFO(swapped.output);
  REQUIRE(swapped.status == 0);  // a warning: the user may know better (a deliberately odd rig)
  CHECK(swapped.output.find("cameras cam_02 and cam_03 look swapped") != std::string::npos);

  const auto right = testing::run_command(std::string(OCTOCAP_CLI_PATH) + " solve --calibration " + calib +
                                          " --keypoints " + demo + "/pose --output " + dir.file("right.trc"));
  INFO(right.output);
  REQUIRE(right.status == 0);
  CHECK(right.output.find("look swapped") == std::string::npos);
  CHECK(right.output.find("out of the calibration's order") == std::string::npos);
}
