// The per-frame entry points: any bytes as a stream of frames (view counts, people per view, raw float keypoints
// with NaN, infinities and huge values, raw int64 timestamps) into one session, and every frame query after each.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "octocap/octocap.h"

namespace {

// Four cameras around a 2 m volume, made once.
octocap_calibration_t* rig() {
  static octocap_calibration_t* calib = [] {
    octocap_camera_t cams[4] = {};
    for (int i = 0; i < 4; ++i) {
      octocap_camera_t& c = cams[i];
      std::snprintf(c.name, sizeof c.name, "cam%d", i);
      c.width = 640;
      c.height = 480;
      const double m[9] = {500, 0, 320, 0, 500, 240, 0, 0, 1};
      std::memcpy(c.matrix, m, sizeof m);
      const double yaw = i * M_PI / 2;  // looking at the origin from 4 m, Y up
      c.rotation[1] = yaw;
      c.translation[1] = 1.0;
      c.translation[2] = 4.0;
    }
    octocap_calibration_t* out = nullptr;
    if (octocap_calibration_create(cams, 4, &out) != OCTOCAP_OK) __builtin_trap();
    return out;
  }();
  return calib;
}

template <class T>
bool take(const uint8_t*& data, size_t& size, T& out) {
  if (size < sizeof(T)) return false;
  std::memcpy(&out, data, sizeof(T));
  data += sizeof(T);
  size -= sizeof(T);
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  uint8_t header = 0;
  if (!take(data, size, header)) return 0;
  // One session per (method, filter), made once: creating one per input would be most of the work. Each input
  // starts from a reset session, so every input is replayable on its own.
  static octocap_session_t* sessions[4] = {};
  octocap_session_t*& s = sessions[header % 4];
  if (!s) {
    octocap_session_config_t cfg;
    octocap_session_config_init(&cfg);
    cfg.layout = OCTOCAP_LAYOUT_COCO_17;
    cfg.method = header & 1 ? OCTOCAP_METHOD_SUBDIVISION : OCTOCAP_METHOD_TRIANGULATION;
    cfg.filter = header & 2 ? OCTOCAP_FILTER_ONE_EURO : OCTOCAP_FILTER_NONE;
    cfg.worker_threads = 1;
    if (octocap_session_create(&cfg, rig(), &s) != OCTOCAP_OK) __builtin_trap();
  }
  if (octocap_session_reset(s) != OCTOCAP_OK) __builtin_trap();
  const uint32_t K = 17;
  for (int frame = 0; frame < 8; ++frame) {
    uint8_t views = 0;
    int64_t t = 0;
    if (!take(data, size, views) || !take(data, size, t)) break;
    views = static_cast<uint8_t>(views % 6);  // 4 is right; 0..5 tries the mismatches too
    std::vector<uint32_t> people(views);
    size_t total = 0;
    for (uint32_t& p : people) {
      uint8_t n = 0;
      take(data, size, n);
      p = n % 4;
      total += p * K;
    }
    std::vector<octocap_keypoint2d_t> kps(total);
    for (auto& k : kps) {
      float xyc[3] = {0, 0, 0};
      for (float& v : xyc) take(data, size, v);
      k = {xyc[0], xyc[1], xyc[2]};
    }
    const octocap_result_t r =
        octocap_session_solve_keypoints(s, kps.empty() ? nullptr : kps.data(), people.data(), views, t);
    if (r == OCTOCAP_ERROR_INTERNAL) __builtin_trap();
    octocap_frame_t* f = nullptr;
    if (octocap_session_get_frame(s, &f) != OCTOCAP_OK) continue;
    octocap_frame_summary_t summary{};
    summary.struct_size = sizeof summary;
    octocap_frame_get_summary(f, &summary);
    for (uint32_t p = 0; p <= summary.person_count; ++p) {
      octocap_joint_t joints[32];
      octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
      uint32_t n = 0;
      if (octocap_frame_get_keypoints3d(f, p, joints, 32, &n) == OCTOCAP_OK)
        for (uint32_t k = 0; k < n; ++k)
          if (joints[k].valid && !(std::isfinite(joints[k].position[0]) && std::isfinite(joints[k].reprojection_error_px)))
            __builtin_trap();  // never a valid NaN
      octocap_frame_get_bones(f, p, static_cast<octocap_coord_frame_t>(p % 3), bones, OCTOCAP_BONE_COUNT, &n);
    }
    octocap_frame_release(f);
  }
  return 0;
}
