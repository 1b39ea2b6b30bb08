// Bone rotations: rebuild the skeleton from quaternions, no spin, engine frames.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "rig/bone_solver.h"
#include "rig/engine_frames.h"
#include "support/skeleton_truth.h"
#include "synth.h"

using namespace octocap::internal;

namespace {

SkeletonJoints tpose() {
  SkeletonJoints j;
  j[kRoot] = {0, 1, 0};
  j[kLHip] = {0.1, 1, 0};
  j[kRHip] = {-0.1, 1, 0};
  j[kNeck] = {0, 1.5, 0};
  j[kHead] = {0, 1.7, 0};
  j[kLShoulder] = {0.2, 1.5, 0};
  j[kLElbow] = {0.5, 1.5, 0};
  j[kLHand] = {0.75, 1.5, 0};
  j[kRShoulder] = {-0.2, 1.5, 0};
  j[kRElbow] = {-0.5, 1.5, 0};
  j[kRHand] = {-0.75, 1.5, 0};
  j[kLKnee] = {0.1, 0.55, 0};
  j[kLFoot] = {0.1, 0.1, 0};
  j[kRKnee] = {-0.1, 0.55, 0};
  j[kRFoot] = {-0.1, 0.1, 0};
  // Feet standing flat: toes ahead and below the ankle along the template, heels below and behind.
  for (auto [ankle, toe, heel] : {std::tuple{kLFoot, kLToe, kLHeel}, std::tuple{kRFoot, kRToe, kRHeel}}) {
    j[toe] = j[ankle] + 0.17 * tpose_directions()[kBoneLFoot];
    j[heel] = j[ankle] + Eigen::Vector3d(0, -0.06, -0.05);
  }
  // Hands along the arms, knuckles 9 cm past the wrist.
  j[kLKnuckles] = j[kLHand] + 0.09 * tpose_directions()[kBoneLHand];
  j[kRKnuckles] = j[kRHand] + 0.09 * tpose_directions()[kBoneRHand];
  return j;
}

double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

// The head bone's local rotation of one frame solved with `cues`.
Eigen::Quaterniond solve_bones_with(const SkeletonJoints& j, const BodyCues& cues) {
  return BoneSolver{}.solve(j, cues)[kBoneHead].local;
}

}  // namespace

TEST_CASE("the T-pose gives identity rotations", "[rig]") {
  const SkeletonPose pose = solve_bones(tpose());
  for (int b = 0; b < kBoneCount; ++b) {
    INFO(bone_table()[b].name);
    REQUIRE(pose[b].valid);
    REQUIRE(angle_between(pose[b].local, Eigen::Quaterniond::Identity()) < 1e-9);
  }
}

TEST_CASE("joints rebuilt from the quaternions and bone lengths match real motion", "[rig]") {
  const auto motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 300, 8);
  double worst = 0;
  for (const auto& frame : motion.frames) {
    const SkeletonJoints truth = testing::skeleton_from_keypoints(frame, LayoutId::body25);
    const SkeletonPose pose = solve_bones(truth);
    // Every bone but the hands: BODY_25 has no hand points, so no knuckles.
    for (int b = 0; b < kBoneCount; ++b) REQUIRE(pose[b].valid == (b != kBoneRHand && b != kBoneLHand));
    const SkeletonJoints rebuilt = testing::rebuild_from_bones(pose, truth[kRoot]);
    for (int j = 0; j < kJointCount; ++j) worst = std::max(worst, (rebuilt[j] - truth[j]).norm());
    // Local rotations chain into the global ones.
    for (int b = 1; b < kBoneCount; ++b)
      if (pose[b].valid) REQUIRE(angle_between(pose[bone_table()[b].parent].global * pose[b].local, pose[b].global) < 1e-9);
  }
  REQUIRE(worst < 1e-9);
}

TEST_CASE("a forearm circling near its rest axis does not spin (anti-spin), the naive frame does", "[rig]") {
  SkeletonJoints j = tpose();
  const Eigen::Vector3d rest = tpose_directions()[kBoneLLowerArm];
  double naive_roll_min = 10, naive_roll_max = -10, prev_naive = 0, naive_jump = 0, worst_twist = 0,
         worst_step_excess = 0;
  Eigen::Quaterniond prev_global;
  Eigen::Vector3d prev_dir;
  for (int i = 0; i <= 360; ++i) {
    const double t = i * M_PI / 180, cone = 8 * M_PI / 180;
    const Eigen::Vector3d d(std::cos(cone), std::sin(cone) * std::cos(t), std::sin(cone) * std::sin(t));
    j[kLHand] = j[kLElbow] + 0.25 * d;
    const SkeletonPose pose = solve_bones(j);
    const BonePose& arm = pose[kBoneLLowerArm];
    worst_twist = std::max(worst_twist, std::abs(twist_angle(arm.local, rest)));
    if (i > 0) {
      // The bone's frame turns no more than its direction does: no roll is added.
      const double step = angle_between(prev_global, arm.global);
      const double dir_step = std::acos(std::clamp(prev_dir.dot(d), -1.0, 1.0));
      worst_step_excess = std::max(worst_step_excess, step - dir_step);
    }
    prev_global = arm.global;
    prev_dir = d;
    // The paper's uncorrected frame, measured as a roll about the bone against the swing frame.
    const Eigen::Matrix3d naive = naive_bone_frame(d, rest);
    const Eigen::Matrix3d swing = Eigen::Quaterniond::FromTwoVectors(rest, d).toRotationMatrix();
    const Eigen::Matrix3d rel = swing.transpose() * naive;  // a rotation about +X
    const double roll = std::atan2(rel(2, 1), rel(1, 1));
    if (i > 0) naive_jump = std::max(naive_jump, std::abs(std::remainder(roll - prev_naive, 2 * M_PI)));
    prev_naive = roll;
    naive_roll_min = std::min(naive_roll_min, roll);
    naive_roll_max = std::max(naive_roll_max, roll);
  }
  REQUIRE(worst_twist < 1e-9);
  REQUIRE(worst_step_excess < 1e-4);  // radians; acos() near 0 is not more precise than this
  // Without the correction the same motion rolls the bone all the way round.
  REQUIRE(naive_roll_max - naive_roll_min > 1.5 * M_PI);
}

TEST_CASE("an elbow that straightens and bends again keeps its roll: no flip near straight", "[rig]") {
  // The arm bends in one plane (forearm toward the front), straightens, wobbles around straight (a degree of noise,
  // any direction: no plane to trust) and bends again.
  BoneSolver solver;
  SkeletonJoints j = tpose();
  std::mt19937 rng(5);
  std::normal_distribution<double> wobble(0, 1.0 * M_PI / 180);
  Eigen::Quaterniond prev;
  double worst_step = 0, bent_roll_start = 0, bent_roll_end = 0;
  const int frames = 240;
  for (int i = 0; i < frames; ++i) {
    const double bend = (60 * M_PI / 180) * std::clamp((std::abs(i - frames / 2) - 40) / 60.0, 0.0, 1.0);
    Eigen::Vector3d f(std::cos(bend), 0, std::sin(bend));  // left forearm: +X, bending toward +Z
    f = (Eigen::AngleAxisd(wobble(rng), Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(wobble(rng), Eigen::Vector3d::UnitZ())) * f;
    j[kLHand] = j[kLElbow] + 0.25 * f;
    const SkeletonPose pose = solver.solve(j);
    const BonePose& upper = pose[kBoneLUpperArm];
    REQUIRE(upper.valid);
    if (i > 0) worst_step = std::max(worst_step, angle_between(prev, upper.global));
    prev = upper.global;
    const double roll = twist_angle(upper.local, tpose_directions()[kBoneLUpperArm]);
    if (i == 0) bent_roll_start = roll;
    if (i == frames - 1) bent_roll_end = roll;
  }
  INFO("largest step of the upper arm between frames " << worst_step * 180 / M_PI << " deg, roll bent "
                                                      << bent_roll_start * 180 / M_PI << " then " << bent_roll_end * 180 / M_PI);
  // Never a flip (half a turn), also while straight and wobbling: what noise moves is the bent plane's roll, by
  // about the wobble over the bend's sine.
  CHECK(worst_step < 20 * M_PI / 180);
  CHECK(std::abs(bent_roll_start) < 5 * M_PI / 180);      // bent in the template's hinge plane: no roll needed
  CHECK(std::abs(bent_roll_end - bent_roll_start) < 5 * M_PI / 180);
  // Bent in another plane (forearm toward the ceiling): the upper arm rolls a quarter turn so the elbow stays a hinge.
  j[kLHand] = j[kLElbow] + 0.25 * Eigen::Vector3d(std::cos(1.0), std::sin(1.0), 0);
  const SkeletonPose up = solve_bones(j);
  CHECK(std::abs(std::abs(twist_angle(up[kBoneLUpperArm].local, tpose_directions()[kBoneLUpperArm])) - M_PI / 2) < 1e-6);
  // The forearm then turns about the hinge alone: no roll of its own.
  CHECK(std::abs(twist_angle(up[kBoneLLowerArm].local, tpose_directions()[kBoneLLowerArm])) < 1e-9);
}

TEST_CASE("the head turns with the face: ears, else eyes, else the nose; held when the face is gone", "[rig]") {
  const SkeletonJoints j = tpose();
  const Eigen::Vector3d up = tpose_directions()[kBoneHead];
  const Eigen::AngleAxisd turn(40 * M_PI / 180, up);  // a look to the left
  BodyCues ears;
  ears.head_across = turn * Eigen::Vector3d(0.15, 0, 0);
  BoneSolver solver;
  CHECK(std::abs(twist_angle(solver.solve(j, ears)[kBoneHead].local, up) - turn.angle()) < 1e-9);
  BodyCues nose;
  nose.head_forward = turn * Eigen::Vector3d(0, 0, 0.1);
  CHECK(std::abs(twist_angle(solve_bones_with(j, nose), up) - turn.angle()) < 1e-9);
  // The face not seen for a while: the turn is held, drifting back only slowly, never snapping.
  double held = 0;
  for (int i = 0; i < 10; ++i) held = twist_angle(solver.solve(j)[kBoneHead].local, up);
  CHECK(held > 0.7 * turn.angle());
  CHECK(held < turn.angle());
}

TEST_CASE("a foot flexes, points and rolls with its toes and heel; held while the heel is not seen", "[rig]") {
  BoneSolver solver;
  const SkeletonJoints rest = tpose();
  const Eigen::Vector3d foot_axis = tpose_directions()[kBoneRFoot];
  double worst = 0;
  for (double flex : {-30.0, -10.0, 0.0, 20.0, 45.0})      // pointing the toes down is positive about +X
    for (double roll : {-25.0, 0.0, 15.0}) {                // inversion / eversion about the foot's own axis
      const Eigen::Quaterniond truth(Eigen::AngleAxisd(flex * M_PI / 180, Eigen::Vector3d::UnitX()) *
                                     Eigen::AngleAxisd(roll * M_PI / 180, foot_axis));
      SkeletonJoints j = rest;
      for (int toe : {kRToe, kRHeel}) j[toe] = j[kRFoot] + truth * (rest[toe] - rest[kRFoot]);
      const SkeletonPose pose = BoneSolver{}.solve(j);
      REQUIRE(pose[kBoneRFoot].valid);
      worst = std::max(worst, angle_between(pose[kBoneRFoot].local, truth));
      for (int i = 0; i < 30; ++i) solver.solve(j);  // held a moment: the smoothed roll settles
    }
  INFO("worst foot error " << worst * 180 / M_PI << " deg");
  CHECK(worst < 1e-9);  // a first frame takes its roll whole: there is nothing yet to smooth it against
  // The last pose (45 deg pointed, rolled 15 deg) held with the heel gone: the roll stays, easing back slowly.
  SkeletonJoints no_heel = rest;
  const Eigen::Quaterniond last(Eigen::AngleAxisd(45 * M_PI / 180, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(15 * M_PI / 180, foot_axis));
  no_heel[kRToe] = no_heel[kRFoot] + last * (rest[kRToe] - rest[kRFoot]);
  no_heel[kRHeel] = Eigen::Vector3d::Constant(std::nan(""));
  std::vector<double> off;  // how far the held foot is from the last seen one, frame by frame
  for (int i = 0; i < 10; ++i) {
    const SkeletonPose pose = solver.solve(no_heel);
    REQUIRE(pose[kBoneRFoot].valid);  // the toes alone still aim the foot
    off.push_back(angle_between(pose[kBoneRFoot].local, last) * 180 / M_PI);
  }
  INFO("held foot off by " << off.front() << " deg, then " << off.back() << " deg after 10 frames");
  CHECK(off.front() < 1.0);             // no snap to the toes-only answer (15 deg of roll away)
  CHECK(off.back() < 0.3 * 15);         // eases back slowly
  CHECK(off.back() > off.front());
  // No toes (a layout without feet): no foot bone, everything else as before.
  SkeletonJoints no_toes = rest;
  no_toes[kRToe] = Eigen::Vector3d::Constant(std::nan(""));
  const SkeletonPose pose = solve_bones(no_toes);
  CHECK_FALSE(pose[kBoneRFoot].valid);
  CHECK(pose[kBoneLFoot].valid);
  CHECK(pose[kBoneRLowerLeg].valid);
}

TEST_CASE("a palm turns: the hand rolls with its knuckles' line, the forearm's twist; held while not seen", "[rig]") {
  const SkeletonJoints rest = tpose();
  for (auto [bone, side] : {std::pair{kBoneRHand, 0}, std::pair{kBoneLHand, 1}}) {
    const Eigen::Vector3d axis = tpose_directions()[bone];
    for (double turn : {-90.0, -45.0, 0.0, 30.0, 80.0}) {  // palm down (T-pose) through the thumb up to palm up
      const Eigen::AngleAxisd truth(turn * M_PI / 180, axis);
      BodyCues cues;
      // Index knuckle minus little finger knuckle: forward (+Z) with the palm down, on either hand.
      (side == 0 ? cues.r_palm_across : cues.l_palm_across) = truth * Eigen::Vector3d(0, 0, 0.08);
      const SkeletonPose pose = BoneSolver{}.solve(rest, cues);
      REQUIRE(pose[bone].valid);
      INFO(bone_table()[bone].name << ", turned " << turn << " deg");
      CHECK(angle_between(pose[bone].local, Eigen::Quaterniond(truth)) < 1e-9);
      // The arm itself does not roll: the forearm's twist is the hand's roll against it.
      CHECK(angle_between(pose[bone == kBoneRHand ? kBoneRLowerArm : kBoneLLowerArm].local,
                          Eigen::Quaterniond::Identity()) < 1e-9);
    }
  }
  // Seen turned 80 deg, then the hand points lost (a fist, a hand behind the back): the roll holds, easing back.
  BoneSolver solver;
  BodyCues seen;
  const Eigen::AngleAxisd turned(80 * M_PI / 180, tpose_directions()[kBoneRHand]);
  seen.r_palm_across = turned * Eigen::Vector3d(0, 0, 0.08);
  solver.solve(rest, seen);
  double first = 0, last = 0;
  for (int i = 0; i < 10; ++i) {
    const double off = angle_between(solver.solve(rest)[kBoneRHand].local, Eigen::Quaterniond(turned)) * 180 / M_PI;
    if (i == 0) first = off;
    last = off;
  }
  CHECK(first < 0.03 * 80);  // one frame's slow drift, no snap to the smallest rotation (80 deg away)
  CHECK(last < 0.3 * 80);
  CHECK(last > first);
  // Knuckles on top of each other (a hand seen edge-on) say nothing: the smallest rotation, no flip.
  BodyCues edge_on;
  edge_on.r_palm_across = Eigen::Vector3d(-0.002, 0, 0);  // along the hand
  CHECK(angle_between(BoneSolver{}.solve(rest, edge_on)[kBoneRHand].local, Eigen::Quaterniond::Identity()) < 1e-9);
  // No knuckles (a layout without hand points): no hand bone, the arm as before.
  SkeletonJoints no_hand = rest;
  no_hand[kRKnuckles] = Eigen::Vector3d::Constant(std::nan(""));
  const SkeletonPose pose = solve_bones(no_hand);
  CHECK_FALSE(pose[kBoneRHand].valid);
  CHECK(pose[kBoneRLowerArm].valid);
}

TEST_CASE("a chest twisting against still hips: the torso turns with the shoulder line, the hips do not", "[rig]") {
  const SkeletonJoints rest = tpose();
  const Eigen::Vector3d up = tpose_directions()[kBoneTorso];
  BoneSolver solver;
  for (double twist : {0.0, 15.0, 30.0, 45.0, 60.0, 30.0, -40.0}) {
    // Shoulders, arms and hands (and the hand points) turned about the spine through the neck; hips and legs still.
    const Eigen::AngleAxisd turn(twist * M_PI / 180, up);
    SkeletonJoints j = rest;
    for (int k : {kRShoulder, kRElbow, kRHand, kRKnuckles, kLShoulder, kLElbow, kLHand, kLKnuckles})
      j[k] = rest[kNeck] + turn * (rest[k] - rest[kNeck]);
    const SkeletonPose pose = solver.solve(j);
    INFO("chest twisted " << twist << " deg");
    CHECK(angle_between(pose[kBoneRoot].global, Eigen::Quaterniond::Identity()) < 1e-9);
    CHECK(std::abs(twist_angle(pose[kBoneTorso].local, up) * 180 / M_PI - twist) < 1e-6);
    // The arms turned with the chest: nothing of their own.
    for (int b : {kBoneRShoulder, kBoneRUpperArm, kBoneRLowerArm, kBoneLShoulder, kBoneLUpperArm, kBoneLLowerArm})
      CHECK(angle_between(pose[b].local, Eigen::Quaterniond::Identity()) < 1e-6);
  }
}

TEST_CASE("a missing joint invalidates its bone and the bones below it", "[rig]") {
  SkeletonJoints j = tpose();
  j[kLElbow] = Eigen::Vector3d::Constant(std::nan(""));
  const SkeletonPose pose = solve_bones(j);
  REQUIRE_FALSE(pose[kBoneLUpperArm].valid);
  REQUIRE_FALSE(pose[kBoneLLowerArm].valid);
  REQUIRE(pose[kBoneRLowerArm].valid);
  j[kRHip] = Eigen::Vector3d::Constant(std::nan(""));
  const SkeletonPose no_root = solve_bones(j);
  for (int b = 0; b < kBoneCount; ++b) REQUIRE_FALSE(no_root[b].valid);
}

TEST_CASE("engine frames: a known rotation maps to the expected engine rotation", "[rig]") {
  const Eigen::Quaterniond yaw90(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  // Unity mirrors X: a left turn becomes a right turn about the same up axis.
  const Eigen::Quaterniond u = convert_rotation(yaw90, CoordFrame::unity);
  REQUIRE(u.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitY()))) < 1e-12);
  // Godot turns the world half a turn about Y: a yaw stays the same yaw.
  REQUIRE(convert_rotation(yaw90, CoordFrame::godot).angularDistance(yaw90) < 1e-12);
  // Rotating then converting equals converting then rotating, for positions and rotations alike.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u1(-1, 1);
  for (CoordFrame f : {CoordFrame::unity, CoordFrame::godot}) {
    for (int n = 0; n < 100; ++n) {
      const Eigen::Quaterniond q = Eigen::Quaterniond(u1(rng), u1(rng), u1(rng), u1(rng)).normalized();
      const Eigen::Vector3d p(u1(rng), u1(rng), u1(rng));
      REQUIRE((convert_rotation(q, f) * convert_position(p, f) - convert_position(q * p, f)).norm() < 1e-12);
    }
  }
  REQUIRE(convert_position({1, 2, 3}, CoordFrame::unity) == Eigen::Vector3d(-1, 2, 3));
  REQUIRE(convert_position({1, 2, 3}, CoordFrame::godot) == Eigen::Vector3d(-1, 2, -3));
}
