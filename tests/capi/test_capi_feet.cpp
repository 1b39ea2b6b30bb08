// Foot contacts and foot_lock through the C ABI, against ground truth this test makes: real CMU motion seen by five
// distorted cameras with pixel noise, the truth's own contacts (ankle still and low) as the reference.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "octocap/octocap.h"
#include "support/capi_helpers.h"
#include "synth.h"

using namespace octocap::internal;

namespace {

constexpr int kRAnkle = 11, kLAnkle = 14;  // BODY_25

struct Run {
  std::vector<std::array<Eigen::Vector3d, OCTOCAP_JOINT_COUNT>> joints;
  std::vector<std::array<Eigen::Vector3d, 2>> ankle_keypoints;  // BODY_25 RAnkle, LAnkle: what TRC and CSV carry
  std::vector<uint32_t> contacts;
};

Run solve_take(const Calibration& cams, const octocap_calibration_t* calib, const synth::Motion& motion, uint32_t foot_lock) {
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.foot_lock = foot_lock;
  cfg.worker_threads = 2;
  testing::Session s = testing::make_session(calib, cfg);
  std::mt19937 rng(11);  // the same pictures for both runs
  Run run;
  for (size_t f = 0; f < motion.frames.size(); ++f) {
    const auto views = synth::observe(cams, motion.frames[f], LayoutId::body25, {2.0, 0, 0, 0}, rng);
    const synth::FlatFrame flat = synth::flatten(views);
    REQUIRE(octocap_session_solve_keypoints(s.get(), reinterpret_cast<const octocap_keypoint2d_t*>(flat.xyc.data()),
                                            flat.people_per_view.data(), static_cast<uint32_t>(flat.people_per_view.size()),
                                            static_cast<int64_t>(f * 1e6 / motion.rate_hz)) == OCTOCAP_OK);
    octocap_frame_t* frame = nullptr;
    REQUIRE(octocap_session_get_frame(s.get(), &frame) == OCTOCAP_OK);
    octocap_person_t person;
    person.struct_size = sizeof person;
    REQUIRE(octocap_frame_get_person(frame, 0, &person) == OCTOCAP_OK);
    run.contacts.push_back(person.foot_contacts);
    octocap_joint_t joints[OCTOCAP_JOINT_COUNT];
    uint32_t n = 0;
    REQUIRE(octocap_frame_get_joints(frame, 0, joints, OCTOCAP_JOINT_COUNT, &n) == OCTOCAP_OK);
    std::array<Eigen::Vector3d, OCTOCAP_JOINT_COUNT> j;
    for (uint32_t k = 0; k < OCTOCAP_JOINT_COUNT; ++k)
      j[k] = joints[k].valid ? Eigen::Vector3d(joints[k].position[0], joints[k].position[1], joints[k].position[2])
                             : Eigen::Vector3d::Constant(std::nan(""));
    run.joints.push_back(j);
    octocap_joint_t keypoints[25];
    REQUIRE(octocap_frame_get_keypoints3d(frame, 0, keypoints, 25, &n) == OCTOCAP_OK);
    std::array<Eigen::Vector3d, 2> ankles;
    for (int side = 0; side < 2; ++side) {
      const octocap_joint_t& k = keypoints[side == 0 ? kRAnkle : kLAnkle];
      ankles[side] = k.valid ? Eigen::Vector3d(k.position[0], k.position[1], k.position[2]) : Eigen::Vector3d::Constant(std::nan(""));
    }
    run.ankle_keypoints.push_back(ankles);
    octocap_frame_release(frame);
  }
  return run;
}

double horizontal(const Eigen::Vector3d& v) { return std::hypot(v.x(), v.z()); }

}  // namespace

TEST_CASE("a session reports planted feet, and with foot_lock holds them: less sliding, nothing above the knees moves", "[capi]") {
  synth::RigOptions rig;
  const Calibration cams = synth::make_camera_ring(rig);
  const testing::Calib calib = testing::make_calibration(cams);
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 450, 4);  // 15 s at 30 frames/s
  const double dt = 1.0 / motion.rate_hz;
  const Run loose = solve_take(cams, calib.get(), motion, 0), locked = solve_take(cams, calib.get(), motion, 1);

  // The truth's contacts: an ankle moving under 0.15 m/s within 5 cm of its lowest.
  double floor = 1e9;
  for (const auto& f : motion.frames) floor = std::min({floor, f[kRAnkle].y(), f[kLAnkle].y()});
  int tp = 0, fp = 0, fn = 0, in_contact = 0;
  double truth_speed = 0, free_speed = 0, locked_speed = 0, free_err = 0, locked_err = 0, upper_change = 0;
  double keypoint_gap = 0;
  for (size_t f = 1; f + 1 < motion.frames.size(); ++f) {
    CHECK(loose.contacts[f] == locked.contacts[f]);  // contacts come from the solve, locked or not
    for (int side = 0; side < 2; ++side) {
      const int a = side == 0 ? kRAnkle : kLAnkle;
      const int joint = side == 0 ? OCTOCAP_JOINT_R_FOOT : OCTOCAP_JOINT_L_FOOT;
      const bool planted = horizontal(motion.frames[f + 1][a] - motion.frames[f - 1][a]) / (2 * dt) < 0.15 &&
                           motion.frames[f][a].y() < floor + 0.05;
      const bool said = (loose.contacts[f] & (side == 0 ? OCTOCAP_FOOT_RIGHT : OCTOCAP_FOOT_LEFT)) != 0;
      tp += said && planted, fp += said && !planted, fn += !said && planted;
      if (planted) {
        truth_speed += horizontal(motion.frames[f][a] - motion.frames[f - 1][a]) / dt;
        free_speed += horizontal(loose.joints[f][joint] - loose.joints[f - 1][joint]) / dt;
        locked_speed += horizontal(locked.joints[f][joint] - locked.joints[f - 1][joint]) / dt;
        ++in_contact;
      }
      // The locked ankle is what the keypoints say too (TRC and CSV are written from them).
      if (locked.ankle_keypoints[f][side].allFinite())
        keypoint_gap = std::max(keypoint_gap, (locked.ankle_keypoints[f][side] - locked.joints[f][joint]).norm());
      free_err += (loose.joints[f][joint] - motion.frames[f][a]).norm();
      locked_err += (locked.joints[f][joint] - motion.frames[f][a]).norm();
    }
    for (int j : {OCTOCAP_JOINT_ROOT, OCTOCAP_JOINT_NECK, OCTOCAP_JOINT_R_HIP, OCTOCAP_JOINT_L_HIP, OCTOCAP_JOINT_R_HAND})
      upper_change = std::max(upper_change, (loose.joints[f][j] - locked.joints[f][j]).norm());
  }
  const double f1 = 2.0 * tp / (2.0 * tp + fp + fn);
  INFO("contact F1 " << f1 << " (tp " << tp << ", fp " << fp << ", fn " << fn << "); planted ankle speed: truth "
                     << 1000 * truth_speed / in_contact << " mm/s, free " << 1000 * free_speed / in_contact << ", locked "
                     << 1000 * locked_speed / in_contact << "; ankle error " << 1000 * free_err / (2 * motion.frames.size())
                     << " -> " << 1000 * locked_err / (2 * motion.frames.size()) << " mm");
  REQUIRE(in_contact > 200);
  CHECK(f1 >= 0.85);
  CHECK(locked_speed < 0.7 * free_speed);
  CHECK(locked_speed <= 1.5 * truth_speed);
  // A held ankle while the true one rolls from heel to toe: a few millimetres (the foot's contact point is its heel
  // or toe, not the ankle), the price of not skating.
  CHECK(locked_err / (2 * motion.frames.size()) <= free_err / (2 * motion.frames.size()) + 0.004);
  CHECK(upper_change == 0);
  CHECK(keypoint_gap < 1e-5);
}

TEST_CASE("foot_lock is 0 or 1, and a 1.0 caller's person struct is filled up to its size", "[capi]") {
  synth::RigOptions rig;
  const Calibration cams = synth::make_camera_ring(rig);
  const testing::Calib calib = testing::make_calibration(cams);
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  CHECK(cfg.foot_lock == 1);  // the default since 1.13
  cfg.foot_lock = 2;
  octocap_session_t* s = nullptr;
  CHECK(octocap_session_create(&cfg, calib.get(), &s) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(s == nullptr);

  cfg.foot_lock = 1;
  testing::Session session = testing::make_session(calib.get(), cfg);
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 2, 4);
  std::mt19937 rng(3);
  const synth::FlatFrame flat = synth::flatten(synth::observe(cams, motion.frames[0], LayoutId::body25, {}, rng));
  REQUIRE(octocap_session_solve_keypoints(session.get(), reinterpret_cast<const octocap_keypoint2d_t*>(flat.xyc.data()),
                                          flat.people_per_view.data(), static_cast<uint32_t>(flat.people_per_view.size()),
                                          0) == OCTOCAP_OK);
  octocap_frame_t* frame = nullptr;
  REQUIRE(octocap_session_get_frame(session.get(), &frame) == OCTOCAP_OK);
  struct {
    octocap_person_t person;
    uint32_t guard;
  } old;
  std::memset(&old, 0xAB, sizeof old);
  old.person.struct_size = 32;  // 1.0 to 1.10: no foot_contacts
  CHECK(octocap_frame_get_person(frame, 0, &old.person) == OCTOCAP_OK);
  CHECK(old.person.id == 1);
  CHECK(old.person.foot_contacts == 0xABABABABu);  // not written past the caller's size
  old.person.struct_size = 28;
  CHECK(octocap_frame_get_person(frame, 0, &old.person) == OCTOCAP_ERROR_STRUCT_SIZE);
  octocap_frame_release(frame);
}
