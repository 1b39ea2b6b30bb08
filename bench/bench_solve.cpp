// 3D solve benchmark: ms per frame by method, view count, keypoint count, delta and threads, on real CMU
// motion seen by synthetic cameras (1 px noise, 3% missed, 2% wrong, 2% swapped), through the public C ABI.
// Also the paper's literal projected-hull test against the ray test it is replaced by.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "octocap/octocap.h"
#include "pipeline/session.h"
#include "rig/bone_solver.h"
#include "solve/subdivision.h"
#include "skeleton_truth.h"
#include "synth.h"
#include "take_score.h"

using namespace octocap::internal;
using Clock = std::chrono::steady_clock;

namespace {

struct Frames {
  std::vector<synth::FlatFrame> flat;
  std::vector<std::vector<Eigen::Vector3d>> truth;
};

octocap_calibration_t* make_calib(const Calibration& cams) {
  std::vector<octocap_camera_t> cc;
  for (const Camera& c : cams) {
    octocap_camera_t o{};
    std::strncpy(o.name, c.name.c_str(), sizeof o.name - 1);
    o.width = c.width;
    o.height = c.height;
    for (int i = 0; i < 9; ++i) o.matrix[i] = c.K(i / 3, i % 3);
    for (int i = 0; i < 5; ++i) o.distortion[i] = c.dist[i];
    const Eigen::Vector3d r = matrix_to_rodrigues(c.R);
    for (int i = 0; i < 3; ++i) o.rotation[i] = r[i], o.translation[i] = c.t[i];
    cc.push_back(o);
  }
  octocap_calibration_t* calib = nullptr;
  octocap_calibration_create(cc.data(), static_cast<uint32_t>(cc.size()), &calib);
  return calib;
}

Frames make_frames(const Calibration& cams, const synth::Motion& motion, LayoutId layout_id) {
  Frames f;
  std::mt19937 rng(1);
  for (const auto& frame : motion.frames) {
    const auto truth = synth::to_layout(frame, layout_id);
    f.flat.push_back(synth::flatten(synth::observe(cams, truth, layout_id, {}, rng)));
    f.truth.push_back(truth);
  }
  return f;
}

struct Result {
  double ms_per_frame = 0, mpjpe_mm = 0, solved = 0;
};

Result run(octocap_calibration_t* calib, const Frames& frames, octocap_layout_t layout, octocap_method_t method,
           float delta, uint32_t threads) {
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.layout = layout;
  cfg.method = method;
  cfg.delta_m = delta;
  cfg.filter = OCTOCAP_FILTER_NONE;
  cfg.worker_threads = threads;
  if (const char* mc = std::getenv("OCTOCAP_BENCH_MAX_CANDIDATES")) cfg.max_candidates = static_cast<uint32_t>(std::atoi(mc));
  octocap_session_t* s = nullptr;
  if (octocap_session_create(&cfg, calib, &s) != OCTOCAP_OK) {
    std::fprintf(stderr, "session: %s\n", octocap_last_error());
    return {};
  }
  Result r;
  double err = 0;
  size_t n = 0, total = 0;
  std::vector<octocap_joint_t> j(32);
  double ms = 0;
  for (int pass = 0; pass < 2; ++pass) {  // the first pass warms caches and the worker pool
    ms = 0;
    for (size_t f = 0; f < frames.flat.size(); ++f) {
      const auto& ff = frames.flat[f];
      const auto t0 = Clock::now();
      octocap_session_solve_keypoints(s, reinterpret_cast<const octocap_keypoint2d_t*>(ff.xyc.data()),
                                      ff.people_per_view.data(), static_cast<uint32_t>(ff.people_per_view.size()),
                                      static_cast<int64_t>(f) * 33333);
      ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
      if (pass == 0) continue;
      uint32_t c = 0;
      octocap_session_get_keypoints3d(s, j.data(), 32, &c);
      for (uint32_t k = 0; k < c; ++k) {
        ++total;
        if (!j[k].valid) continue;
        err += (Eigen::Vector3d(j[k].position[0], j[k].position[1], j[k].position[2]) - frames.truth[f][k]).norm();
        ++n;
      }
    }
  }
  octocap_session_destroy(s);
  r.ms_per_frame = ms / frames.flat.size();
  r.mpjpe_mm = n ? 1000 * err / n : 0;
  r.solved = total ? 100.0 * n / total : 0;
  return r;
}

void hull_vs_ray() {
  const Calibration calib = synth::make_camera_ring({});
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::AlignedBox3d> cubes;
  std::vector<ViewRay> rays;
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3d lo(u(rng), 1 + u(rng), u(rng));
    cubes.emplace_back(lo, lo + Eigen::Vector3d::Constant(0.05 + 0.2 * (u(rng) + 1)));
    const Camera& cam = calib[i % calib.size()];
    rays.push_back(make_view_ray(cam, i % static_cast<int>(calib.size()),
                                 cam.project(cubes.back().center()) + Eigen::Vector2d(u(rng), u(rng)) * 100, 1));
  }
  int hits = 0;
  auto t0 = Clock::now();
  for (size_t i = 0; i < cubes.size(); ++i) hits += hull_contains_detection(calib[i % calib.size()], cubes[i], rays[i].normalized);
  const double hull_ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / cubes.size();
  t0 = Clock::now();
  for (size_t i = 0; i < cubes.size(); ++i)
    hits -= ray_meets_box(rays[i].origin, rays[i].direction.cwiseInverse(), cubes[i].min(), cubes[i].max(), 0);
  const double ray_ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / cubes.size();
  std::printf("\ncube support test, one cube x one view: projected 8-corner hull %.0f ns, ray/slab %.0f ns "
              "(%.1fx), disagreements %d\n", hull_ns, ray_ns, hull_ns / ray_ns, hits);
}

// The whole `octocap solve` path on the built-in sample: JSON parsing, person selection, solve, filter, rig,
// TRC writing, all through the public C ABI.
void end_to_end(const std::string& sample) {
  octocap_calibration_t* calib = nullptr;
  octocap_recording_t* rec = nullptr;
  if (octocap_calibration_load((sample + "/calibration.toml").c_str(), &calib) != OCTOCAP_OK ||
      octocap_recording_open((sample + "/keypoints").c_str(), OCTOCAP_LAYOUT_AUTO, &rec) != OCTOCAP_OK) {
    std::fprintf(stderr, "end to end: %s\n", octocap_last_error());
    return;
  }
  uint32_t frames = 0, views = 0;
  octocap_layout_t layout;
  octocap_recording_frame_count(rec, &frames);
  octocap_recording_view_count(rec, &views);
  octocap_recording_layout(rec, &layout);
  std::printf("\nend to end on data/sample (%u frames x %u views, JSON in, TRC out), 1 worker thread:\n", frames, views);
  for (octocap_method_t m : {OCTOCAP_METHOD_SUBDIVISION, OCTOCAP_METHOD_TRIANGULATION}) {
    octocap_session_config_t cfg;
    octocap_session_config_init(&cfg);
    cfg.layout = layout;
    cfg.method = m;
    cfg.worker_threads = 1;
    octocap_session_t* s = nullptr;
    octocap_session_create(&cfg, calib, &s);
    octocap_motion_writer_t* w = nullptr;
    octocap_motion_writer_create("/tmp/octocap_bench.trc", OCTOCAP_MOTION_TRC, layout, OCTOCAP_UP_Y, 30, &w);
    std::vector<octocap_keypoint2d_t> buf(4096);
    std::vector<uint32_t> people(views);
    const auto t0 = Clock::now();
    for (uint32_t f = 0; f < frames; ++f) {
      uint32_t needed = 0;
      octocap_recording_read_frame(rec, f, buf.data(), static_cast<uint32_t>(buf.size()), &needed, people.data(), views);
      if (octocap_session_solve_keypoints(s, buf.data(), people.data(), views, f * 33333) == OCTOCAP_OK)
        octocap_motion_writer_add_frame(w, s);
      else
        octocap_motion_writer_add_empty_frame(w);
    }
    octocap_motion_writer_close(w);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    std::printf("  %-13s %.2f ms/frame, %.0f frames/s\n", m == OCTOCAP_METHOD_SUBDIVISION ? "subdivision" : "triangulation",
                ms / frames, 1000.0 * frames / ms);
    octocap_session_destroy(s);
  }
  octocap_recording_destroy(rec);
  octocap_calibration_destroy(calib);
}

}  // namespace

// What reading a frame costs, per frame: the 1.0 frame handle (snapshot, summary, keypoints, bones, release) against
// the 0.x per-session queries that read the session in place.
void frame_queries(octocap_calibration_t* calib, const Frames& frames) {
  octocap_session_config_t cfg;
  octocap_session_config_init(&cfg);
  cfg.layout = OCTOCAP_LAYOUT_BODY_25;
  cfg.worker_threads = 1;
  octocap_session_t* s = nullptr;
  if (octocap_session_create(&cfg, calib, &s) != OCTOCAP_OK) return;
  const auto& f0 = frames.flat.front();
  octocap_session_solve_keypoints(s, reinterpret_cast<const octocap_keypoint2d_t*>(f0.xyc.data()),
                                  f0.people_per_view.data(), static_cast<uint32_t>(f0.people_per_view.size()), 0);
  octocap_joint_t joints[25];
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  uint32_t n = 0;
  constexpr int kReps = 20000;
  auto time_us = [&](auto&& body) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < kReps; ++i) body();
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / kReps;
  };
  const double framed = time_us([&] {
    octocap_frame_t* f = nullptr;
    octocap_session_get_frame(s, &f);
    octocap_frame_summary_t summary{};
    summary.struct_size = sizeof summary;
    octocap_frame_get_summary(f, &summary);
    octocap_frame_get_keypoints3d(f, 0, joints, 25, &n);
    octocap_frame_get_bones(f, 0, OCTOCAP_FRAME_UNITY, bones, OCTOCAP_BONE_COUNT, &n);
    octocap_frame_release(f);
  });
  const double in_place = time_us([&] {
    octocap_frame_info_t info;
    octocap_session_get_frame_info(s, &info);
    octocap_session_get_keypoints3d(s, joints, 25, &n);
    octocap_session_get_bones(s, OCTOCAP_FRAME_UNITY, bones, OCTOCAP_BONE_COUNT, &n);
  });
  std::printf("\nReading one solved frame (BODY_25, every bone in Unity's frame), us per frame:\n"
              "  frame handle (get, summary, keypoints, bones, release): %.2f us\n"
              "  0.x queries on the session (info, keypoints, bones):    %.2f us\n",
              framed, in_place);
  octocap_session_destroy(s);
}

// The rig stage alone (stage 4: joints -> bone rotations with their rolls), per person and frame: with feet (BODY_25's
// toes and heels: 15 bones) and without (COCO_17: 13 bones, the feet invalid), to set beside the 3D stage's ms.
void rig_stage(const synth::Motion& motion) {
  std::printf("\nRig stage (joints -> %d bone rotations, hinge/torso/face/foot/palm rolls), us per person-frame:\n", kBoneCount);
  for (LayoutId lid : {LayoutId::blazepose33, LayoutId::body25, LayoutId::coco17}) {
    const KeypointLayout& l = layout(lid);
    auto index = [&](const char* name) {
      for (size_t k = 0; k < l.keypoints.size(); ++k)
        if (std::string(l.keypoints[k]) == name) return static_cast<int>(k);
      return -1;
    };
    std::vector<SkeletonJoints> joints;
    std::vector<BodyCues> cues;  // the face's and the palms' across lines, as the session gives them
    for (size_t n = 0; n < motion.frames.size(); ++n) {
      const std::vector<Eigen::Vector3d> kp = synth::to_layout(motion, n, lid);
      joints.push_back(testing::skeleton_from_keypoints(kp, lid));
      auto at = [&](const char* name) { return index(name) < 0 ? Eigen::Vector3d::Constant(NAN) : kp[index(name)]; };
      BodyCues c;
      c.head_across = at("LEar") - at("REar");
      c.r_palm_across = at("RIndex") - at("RPinky");
      c.l_palm_across = at("LIndex") - at("LPinky");
      cues.push_back(c);
    }
    BoneSolver solver;
    double sink = 0;
    const int rounds = 50;
    const auto t0 = Clock::now();
    for (int r = 0; r < rounds; ++r)
      for (size_t i = 0; i < joints.size(); ++i) sink += solver.solve(joints[i], cues[i])[kBoneRoot].length;
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / (rounds * joints.size());
    const char* what = lid == LayoutId::coco17 ? "no feet, no hands" : lid == LayoutId::body25 ? "feet" : "feet and hands";
    std::printf("  %-12s (%s): %.2f us%s\n", l.name, what, us, sink > 0 ? "" : " ");
  }
}

// The temporal filter against the truth: CMU motion, 4 cameras 1920x1080, pixel noise; MPJPE and jitter (the mean
// length of the 3D acceleration error per frame: what a viewer sees shake) without filter and with each filter.
void filter_table() {
  std::printf("\nTemporal filter (CMU 01_01, 4 cameras 1920x1080, Gaussian pixel noise): MPJPE / jitter, mm\n");
  std::printf("| noise | none | One Euro, fixed (1.5 Hz, beta 20) | One Euro, adaptive | median reprojection |\n"
              "|---|---|---|---|---|\n");
  const Calibration cams = testing::filter_cameras();
  for (auto [sigma, step] : {std::pair{1.0, 4}, std::pair{2.0, 4}, std::pair{3.0, 4}, std::pair{6.0, 4}, std::pair{3.0, 2}}) {
    const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, 300, static_cast<size_t>(step));
    std::printf("| %.0f px, %.0f fps |", sigma, motion.rate_hz);
    for (int mode = 0; mode < 3; ++mode) {
      SessionConfig cfg;
      cfg.up = UpAxis::y;
      cfg.filter = mode > 0;
      cfg.filter_adaptive = mode == 2;
      const testing::TakeScore r = testing::score_take(cams, motion, cfg, sigma);
      std::printf(" %.1f / %.1f |", r.mpjpe_mm, r.jitter_mm);
      if (mode == 2) std::printf(" %.2f px |", r.median_reprojection_px);
    }
    std::printf("\n");
  }
}

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--filter") {  // that table alone
    filter_table();
    return 0;
  }
  const size_t n_frames = argc > 1 ? std::stoul(argv[1]) : 200;
  const synth::Motion motion = synth::load_cmu_motion(synth::default_bvh_path(), 0, n_frames, 4);
  std::printf("octocap 3D solve benchmark: %zu frames of CMU 01_01 at 30 Hz, ms per frame (C ABI call, person\n"
              "selection + solve + skeleton + bones), MPJPE against the generator's truth, 1 worker thread unless said\n\n",
              motion.frames.size());
  std::printf("%-13s %5s %4s %6s %7s | %8s %9s %8s %7s\n", "method", "views", "kps", "delta", "threads", "ms/frame",
              "frames/s", "MPJPE mm", "solved%");
  for (int views : {2, 4, 5, 8, 16}) {
    synth::RigOptions rig;
    rig.cameras = views;
    const Calibration cams = synth::make_camera_ring(rig);
    octocap_calibration_t* calib = make_calib(cams);
    for (auto [lid, clid] : {std::pair{LayoutId::coco17, OCTOCAP_LAYOUT_COCO_17}, std::pair{LayoutId::body25, OCTOCAP_LAYOUT_BODY_25}}) {
      const Frames frames = make_frames(cams, motion, lid);
      const int kps = static_cast<int>(layout(lid).keypoints.size());
      auto row = [&](octocap_method_t m, float delta, uint32_t threads) {
        const Result r = run(calib, frames, clid, m, delta, threads);
        std::printf("%-13s %5d %4d %4.0fmm %7u | %8.3f %9.0f %8.1f %7.1f\n",
                    m == OCTOCAP_METHOD_SUBDIVISION ? "subdivision" : "triangulation", views, kps, delta * 1000,
                    threads, r.ms_per_frame, 1000.0 / r.ms_per_frame, r.mpjpe_mm, r.solved);
      };
      const bool full = (views == 5);
      for (float d : full ? std::vector<float>{0.005f, 0.01f, 0.02f, 0.03f} : std::vector<float>{0.01f})
        row(OCTOCAP_METHOD_SUBDIVISION, d, 1);
      if (full) row(OCTOCAP_METHOD_SUBDIVISION, 0.01f, 2);
      row(OCTOCAP_METHOD_TRIANGULATION, 0.01f, 1);
    }
    octocap_calibration_destroy(calib);
  }
  {
    synth::RigOptions rig;
    const Calibration cams = synth::make_camera_ring(rig);
    octocap_calibration_t* calib = make_calib(cams);
    frame_queries(calib, make_frames(cams, synth::Motion{{motion.frames.front()}, motion.rate_hz, {}}, LayoutId::body25));
    octocap_calibration_destroy(calib);
  }
  hull_vs_ray();
  rig_stage(motion);
  filter_table();
  end_to_end(OCTOCAP_SOURCE_DIR "/data/sample");
  return 0;
}
