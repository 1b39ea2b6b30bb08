// Solving through the public C ABI against ground truth this test makes: real CMU motion, 5 cameras with
// lens distortion, pixel noise, missed joints, confident wrong detections, left/right swaps, bystanders.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "octocap/octocap.h"
#include "support/capi_helpers.h"
#include "support/skeleton_truth.h"
#include "synth.h"

using namespace octocap::internal;

namespace {

struct Scene {
  Calibration cams;
  testing::Calib calib;
  synth::Motion motion;
};

Scene make_scene(int cameras, size_t frames) {
  synth::RigOptions rig;
  rig.cameras = cameras;
  Scene s{synth::make_camera_ring(rig), nullptr, synth::load_cmu_motion(synth::default_bvh_path(), 0, frames, 4)};
  s.calib = testing::make_calibration(s.cams);
  return s;
}

struct Errors {
  std::vector<double> all_mm;
  std::vector<double> per_kp_sum, per_kp_n;
  size_t solved = 0, total = 0;
  double mpjpe() const {
    double s = 0;
    for (double e : all_mm) s += e;
    return s / all_mm.size();
  }
  double percentile(double p) const {
    std::vector<double> v = all_mm;
    std::sort(v.begin(), v.end());
    return v[static_cast<size_t>(p * (v.size() - 1))];
  }
  double worst_keypoint_mean() const {
    double w = 0;
    for (size_t k = 0; k < per_kp_sum.size(); ++k)
      if (per_kp_n[k] > 0) w = std::max(w, per_kp_sum[k] / per_kp_n[k]);
    return w;
  }
};

void accumulate(Errors& e, const std::vector<octocap_joint_t>& got, const std::vector<Eigen::Vector3d>& truth) {
  e.per_kp_sum.resize(truth.size());
  e.per_kp_n.resize(truth.size());
  for (size_t k = 0; k < truth.size(); ++k) {
    ++e.total;
    if (!got[k].valid) continue;
    ++e.solved;
    const double d = (Eigen::Vector3d(got[k].position[0], got[k].position[1], got[k].position[2]) - truth[k]).norm();
    e.all_mm.push_back(d * 1000);
    e.per_kp_sum[k] += d * 1000;
    e.per_kp_n[k] += 1;
  }
}

octocap_session_config_t config(octocap_method_t method) {
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.method = method;
  cfg.filter = OCTOCAP_FILTER_NONE;
  cfg.worker_threads = 2;
  return cfg;
}

std::vector<octocap_joint_t> keypoints3d(const octocap_session_t* s) {
  std::vector<octocap_joint_t> out(64);
  uint32_t n = 0;
  REQUIRE(octocap_session_get_keypoints3d(s, out.data(), 64, &n) == OCTOCAP_OK);
  out.resize(n);
  return out;
}

octocap_result_t solve(octocap_session_t* s, const std::vector<std::vector<Person2D>>& people, int64_t t) {
  const synth::FlatFrame flat = synth::flatten(people);
  return octocap_session_solve_keypoints(s, reinterpret_cast<const octocap_keypoint2d_t*>(flat.xyc.data()),
                                         flat.people_per_view.data(),
                                         static_cast<uint32_t>(flat.people_per_view.size()), t);
}

}  // namespace

TEST_CASE("both methods recover real motion from noisy, partly wrong detections", "[capi][accuracy]") {
  const Scene sc = make_scene(5, 300);
  synth::NoiseOptions noise;  // 1 px, 3% missed, 2% wrong, 2% swapped views
  for (octocap_method_t method : {OCTOCAP_METHOD_SUBDIVISION, OCTOCAP_METHOD_TRIANGULATION}) {
    INFO("method " << method);
    testing::Session s = testing::make_session(sc.calib.get(), config(method));
    std::mt19937 rng(42);
    Errors e;
    for (size_t f = 0; f < sc.motion.frames.size(); ++f) {
      const auto views = synth::observe(sc.cams, sc.motion.frames[f], LayoutId::body25, noise, rng);
      REQUIRE(solve(s.get(), views, static_cast<int64_t>(f * 33333)) == OCTOCAP_OK);
      accumulate(e, keypoints3d(s.get()), sc.motion.frames[f]);
    }
    INFO("MPJPE " << e.mpjpe() << " mm, p99 " << e.percentile(0.99) << " mm, worst keypoint mean "
                  << e.worst_keypoint_mean() << " mm, solved " << e.solved << "/" << e.total);
    CHECK(e.mpjpe() < 12.0);
    CHECK(e.worst_keypoint_mean() < 20.0);
    CHECK(e.percentile(0.99) < 40.0);
    CHECK(e.solved > 0.97 * e.total);
  }
}

TEST_CASE("with bystanders in some views, the person who agrees across views is picked", "[capi][people]") {
  const Scene sc = make_scene(4, 150);
  const synth::Motion other = synth::load_cmu_motion(synth::default_bvh_path(), 1400, 150, 4);
  testing::Session s = testing::make_session(sc.calib.get(), config(OCTOCAP_METHOD_TRIANGULATION));
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coin(0, 1);
  size_t right = 0, decisions = 0;
  Errors e;
  for (size_t f = 0; f < sc.motion.frames.size(); ++f) {
    auto views = synth::observe(sc.cams, sc.motion.frames[f], LayoutId::body25, {1.0, 0.02, 0.01, 0}, rng);
    std::vector<Eigen::Vector3d> by = other.frames[f];
    for (auto& p : by) p += Eigen::Vector3d(1.5, 0, 1.2);
    const auto seen = synth::observe(sc.cams, by, LayoutId::body25, {1.0, 0.02, 0.01, 0}, rng);
    std::vector<int> truth(views.size(), 0);
    for (size_t v = 0; v < views.size(); ++v) {
      if (seen[v].empty() || views[v].empty() || !coin(rng)) continue;
      views[v].insert(views[v].begin(), seen[v].front());  // the bystander comes first in this view
      truth[v] = 1;
    }
    REQUIRE(solve(s.get(), views, static_cast<int64_t>(f * 33333)) == OCTOCAP_OK);
    int32_t sel[8];
    uint32_t n = 0;
    REQUIRE(octocap_session_get_selected_people(s.get(), sel, 8, &n) == OCTOCAP_OK);
    REQUIRE(n == views.size());
    for (size_t v = 0; v < n; ++v) {
      ++decisions;
      right += sel[v] == truth[v];
    }
    accumulate(e, keypoints3d(s.get()), sc.motion.frames[f]);
  }
  INFO("right " << right << "/" << decisions << ", MPJPE " << e.mpjpe());
  CHECK(right >= 0.98 * decisions);
  CHECK(e.mpjpe() < 15.0);
}

TEST_CASE("bone quaternions from the C ABI rebuild the true skeleton", "[capi][rig]") {
  const Scene sc = make_scene(5, 120);
  testing::Session s = testing::make_session(sc.calib.get(), config(OCTOCAP_METHOD_TRIANGULATION));
  octocap_up_axis_t up = OCTOCAP_UP_Z;
  REQUIRE(octocap_session_up_axis(s.get(), &up) == OCTOCAP_OK);
  REQUIRE(up == OCTOCAP_UP_Y);  // the ring's cameras are upright in a Y-up world
  std::mt19937 rng(6);
  double sum = 0;
  size_t n = 0;
  for (size_t f = 0; f < sc.motion.frames.size(); ++f) {
    const auto views = synth::observe(sc.cams, sc.motion.frames[f], LayoutId::body25, {1.0, 0, 0, 0}, rng);
    REQUIRE(solve(s.get(), views, static_cast<int64_t>(f * 33333)) == OCTOCAP_OK);
    octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT], unity[OCTOCAP_BONE_COUNT];
    uint32_t count = 0;
    REQUIRE(octocap_session_get_bones(s.get(), OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &count) == OCTOCAP_OK);
    REQUIRE(octocap_session_get_bones(s.get(), OCTOCAP_FRAME_UNITY, unity, OCTOCAP_BONE_COUNT, &count) == OCTOCAP_OK);
    SkeletonPose pose;
    for (int b = 0; b < kBoneCount; ++b) {
      // BODY_25 has no hand points: the hands are the bones it cannot give.
      REQUIRE(bones[b].valid == (b == kBoneRHand || b == kBoneLHand ? 0u : 1u));
      const auto& q = bones[b].global_rotation;
      pose[b].global = Eigen::Quaterniond(q.w, q.x, q.y, q.z);
      pose[b].length = bones[b].length_m;
      REQUIRE(std::abs(pose[b].global.norm() - 1.0) < 1e-5);
      // Unity's frame is the mirror image: same w and x, negated y and z, mirrored positions.
      REQUIRE(unity[b].global_rotation.w == q.w);
      REQUIRE(unity[b].global_rotation.y == -q.y);
      REQUIRE(unity[b].head_position[0] == -bones[b].head_position[0]);
    }
    const Eigen::Vector3d root(bones[0].head_position[0], bones[0].head_position[1], bones[0].head_position[2]);
    const SkeletonJoints rebuilt = testing::rebuild_from_bones(pose, root);
    const SkeletonJoints truth = testing::skeleton_from_keypoints(sc.motion.frames[f], LayoutId::body25);
    for (int j = 0; j < kJointCount; ++j) {
      if (j == kRHeel || j == kLHeel) continue;  // no bone ends at a heel: it only rolls the foot
      if (j == kRKnuckles || j == kLKnuckles) continue;  // BODY_25 has no hand points
      sum += (rebuilt[j] - truth[j]).norm();
      ++n;
    }
  }
  INFO("mean joint error rebuilt from quaternions: " << 1000 * sum / n << " mm");
  CHECK(sum / n < 0.015);
}

TEST_CASE("the One Euro filter smooths jitter through the session", "[capi][filter]") {
  const Scene sc = make_scene(5, 1);
  octocap_session_config_t cfg = config(OCTOCAP_METHOD_TRIANGULATION);
  cfg.filter = OCTOCAP_FILTER_ONE_EURO;
  testing::Session filtered = testing::make_session(sc.calib.get(), cfg);
  testing::Session raw = testing::make_session(sc.calib.get(), config(OCTOCAP_METHOD_TRIANGULATION));
  std::mt19937 rng(8);
  double e_raw = 0, e_filt = 0;
  for (int f = 0; f < 200; ++f) {
    // A person standing still, seen with 3 px of noise: all motion in the output is jitter.
    const auto views = synth::observe(sc.cams, sc.motion.frames[0], LayoutId::body25, {3.0, 0, 0, 0}, rng);
    REQUIRE(solve(raw.get(), views, f * 16667) == OCTOCAP_OK);
    REQUIRE(solve(filtered.get(), views, f * 16667) == OCTOCAP_OK);
    if (f < 30) continue;
    const auto a = keypoints3d(raw.get()), b = keypoints3d(filtered.get());
    for (size_t k = 0; k < a.size(); ++k) {
      const Eigen::Vector3d t = sc.motion.frames[0][k];
      e_raw += (Eigen::Vector3d(a[k].position[0], a[k].position[1], a[k].position[2]) - t).squaredNorm();
      e_filt += (Eigen::Vector3d(b[k].position[0], b[k].position[1], b[k].position[2]) - t).squaredNorm();
    }
  }
  CHECK(e_filt < 0.5 * e_raw);
}

TEST_CASE("solving is deterministic, whatever the thread count", "[capi]") {
  const Scene sc = make_scene(6, 20);
  octocap_session_config_t one = config(OCTOCAP_METHOD_SUBDIVISION), two = one;
  one.worker_threads = 1;
  two.worker_threads = 2;
  testing::Session a = testing::make_session(sc.calib.get(), one), b = testing::make_session(sc.calib.get(), two);
  std::mt19937 rng(10);
  for (size_t f = 0; f < sc.motion.frames.size(); ++f) {
    const auto views = synth::observe(sc.cams, sc.motion.frames[f], LayoutId::body25, {}, rng);
    REQUIRE(solve(a.get(), views, f) == OCTOCAP_OK);
    REQUIRE(solve(b.get(), views, f) == OCTOCAP_OK);
    const auto ka = keypoints3d(a.get()), kb = keypoints3d(b.get());
    REQUIRE(std::memcmp(ka.data(), kb.data(), ka.size() * sizeof(octocap_joint_t)) == 0);
  }
}

extern "C" int octocap_c_consumer_check(const char* calibration_path);

TEST_CASE("the header works from strict C99", "[capi]") {
  REQUIRE(octocap_c_consumer_check(OCTOCAP_SOURCE_DIR "/data/sample/calibration.toml") == 1);
}

TEST_CASE("skeleton definition queries", "[capi]") {
  octocap_bone_info_t info;
  REQUIRE(octocap_bone_info(OCTOCAP_BONE_L_LOWER_ARM, &info) == OCTOCAP_OK);
  REQUIRE(std::string(info.name) == "l_lower_arm");
  REQUIRE(info.parent_bone == OCTOCAP_BONE_L_UPPER_ARM);
  REQUIRE(info.head_joint == OCTOCAP_JOINT_L_ELBOW);
  REQUIRE(info.tail_joint == OCTOCAP_JOINT_L_HAND);
  REQUIRE(info.rest_direction[0] == 1.0f);
  REQUIRE(std::string(octocap_joint_name(OCTOCAP_JOINT_ROOT)) == "root");
  const Scene sc = make_scene(3, 1);
  testing::Session s = testing::make_session(sc.calib.get(), config(OCTOCAP_METHOD_AUTO));
  uint32_t counter = 0;
  REQUIRE(octocap_session_definition_counter(s.get(), &counter) == OCTOCAP_OK);
  REQUIRE(counter >= 1);
  octocap_method_t method = OCTOCAP_METHOD_AUTO;
  REQUIRE(octocap_session_method(s.get(), &method) == OCTOCAP_OK);
  REQUIRE(method == OCTOCAP_METHOD_TRIANGULATION);  // auto picks triangulation below 5 cameras
  for (uint32_t b = 1; b < OCTOCAP_BONE_COUNT; ++b) {
    REQUIRE(octocap_bone_info(b, &info) == OCTOCAP_OK);
    REQUIRE(info.parent_bone >= 0);
    REQUIRE(static_cast<uint32_t>(info.parent_bone) < b);  // parents come first
  }
}
