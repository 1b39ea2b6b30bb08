// BVH export of a solved animation, read back with the BVH reader and forward kinematics.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>

#include "io/bvh.h"
#include "rig/bvh_export.h"
#include "support/skeleton_truth.h"
#include "support/temp_dir.h"
#include "synth.h"

using namespace octocap::internal;

TEST_CASE("BVH round trip: export, parse back, the same joint positions within 1 mm", "[bvh]") {
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 200, 6);
  std::vector<SkeletonPose> poses;
  std::vector<SkeletonJoints> truth;
  for (const auto& f : motion.frames) {
    truth.push_back(testing::skeleton_from_keypoints(f, LayoutId::body25));
    poses.push_back(solve_bones(truth.back()));
  }
  testing::TempDir dir;
  write_bvh(dir.file("take.bvh"), poses, motion.rate_hz);
  const BvhMotion bvh = read_bvh(dir.file("take.bvh"));
  REQUIRE(bvh.frames.size() == poses.size());
  REQUIRE(std::abs(bvh.frame_time - 1.0 / motion.rate_hz) < 1e-9);

  // What the file should hold: the same rotations on bones of the take's median lengths.
  std::vector<double> median_len(kBoneCount);
  for (int b = 0; b < kBoneCount; ++b) {
    std::vector<double> l;
    for (const auto& p : poses) l.push_back(p[b].length);
    std::nth_element(l.begin(), l.begin() + l.size() / 2, l.end());
    median_len[b] = l[l.size() / 2];
  }
  const std::pair<const char*, int> joints[] = {
      {"Neck", kNeck},        {"Neck_end", kHead},       {"RightArm", kRShoulder}, {"RightForeArm", kRElbow},
      {"RightHand", kRHand}, {"LeftArm", kLShoulder}, {"LeftForeArm", kLElbow}, {"LeftHand", kLHand},
      {"RightUpLeg", kRHip},  {"RightLeg", kRKnee},      {"RightFoot", kRFoot},    {"RightFoot_end", kRToe},
      {"LeftUpLeg", kLHip},   {"LeftLeg", kLKnee},       {"LeftFoot", kLFoot},     {"LeftFoot_end", kLToe}};
  double worst_file = 0, worst_truth = 0;
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Matrix3d> R;
  for (size_t f = 0; f < poses.size(); ++f) {
    SkeletonPose fixed = poses[f];
    for (int b = 0; b < kBoneCount; ++b) fixed[b].length = median_len[b];
    const SkeletonJoints expected = testing::rebuild_from_bones(fixed, truth[f][kRoot]);
    bvh.pose(f, P, R);
    for (const auto& [name, joint] : joints) {
      const int i = bvh.find(name);
      REQUIRE(i >= 0);
      const Eigen::Vector3d got = P[i] / 100.0;  // centimetres in the file
      worst_file = std::max(worst_file, (got - expected[joint]).norm());
      worst_truth = std::max(worst_truth, (got - truth[f][joint]).norm());
    }
  }
  INFO("worst vs the exported skeleton " << worst_file * 1000 << " mm, vs the captured joints " << worst_truth * 1000 << " mm");
  CHECK(worst_file < 0.001);
  CHECK(worst_truth < 0.03);  // only the take's bone-length variation (a BVH skeleton is rigid)
}
