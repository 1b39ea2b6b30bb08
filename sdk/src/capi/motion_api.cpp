// Motion files for playback: frames of joints and bone poses, from TRC / CSV / BVH.
#include <cmath>

#include "capi/boundary.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"
#include "rig/bone_solver.h"

using namespace octocap::internal;

namespace {

FrameResult frame_at(const octocap_motion_t* m, uint32_t frame) {
  capi::checked(m, "motion");
  if (frame >= m->motion.frames.size())
    throw Error(Errc::invalid_argument, "frame " + std::to_string(frame) + " out of range (" +
                                            std::to_string(m->motion.frames.size()) + " frames)");
  FrameResult f;
  f.info.frame_index = frame;
  f.info.timestamp_us = std::llround(static_cast<double>(frame) * 1e6 / m->motion.rate_hz);
  f.rig_frame_joints = true;
  f.definition_counter = m->definition_counter;
  // Joints and bones only; a per-person CSV holds several people (its ids), every other file one (id 1).
  for (size_t i = 0; i < m->motion.ids.size(); ++i) {
    const SkeletonJoints& j = m->motion.frames[frame][i];
    PersonResult p;
    p.id = m->motion.ids[i];
    for (int k = 0; k < kJointCount; ++k) {
      p.joints[k].valid = j[k].allFinite();
      if (p.joints[k].valid) p.joints[k].position = j[k];
    }
    p.bones = m->bones[i][frame];
    if (p.has_pose()) f.people.push_back(p);
    else if (i == 0) f.blank = p;
  }
  return f;
}

}  // namespace

extern "C" {

octocap_result_t octocap_motion_open(const char* path, octocap_motion_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(path, "path");
    auto motion = load_skeleton_motion(path);
    std::vector<std::vector<SkeletonPose>> bones(motion.ids.size());
    for (size_t p = 0; p < bones.size(); ++p) {
      BoneSolver solver;  // each person's rolls held across the take's frames
      bones[p].reserve(motion.frames.size());
      for (const auto& people : motion.frames) bones[p].push_back(solver.solve(people[p]));
    }
    *out = capi::make_handle<octocap_motion_t>(std::move(motion), std::move(bones), next_definition_counter());
  });
}

void octocap_motion_destroy(octocap_motion_t* m) { capi::destroy_handle(m); }

octocap_result_t octocap_motion_info(const octocap_motion_t* m, uint32_t* frame_count, double* rate_hz) {
  return capi::guard([&] {
    capi::checked(m, "motion");
    if (frame_count) *frame_count = static_cast<uint32_t>(m->motion.frames.size());
    if (rate_hz) *rate_hz = m->motion.rate_hz;
  });
}

octocap_result_t octocap_motion_get_frame(const octocap_motion_t* m, uint32_t index, octocap_frame_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    *out = capi::make_frame(std::make_shared<const FrameResult>(frame_at(m, index)));
  });
}

// Deprecated 0.x queries.

octocap_result_t octocap_motion_joints(const octocap_motion_t* m, uint32_t frame, octocap_joint_t* out,
                                       uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_joints(frame_at(m, frame).person_or_blank(0), out, capacity, count); });
}

octocap_result_t octocap_motion_bones(const octocap_motion_t* m, uint32_t frame, octocap_coord_frame_t coord_frame,
                                      octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_bones(frame_at(m, frame).person_or_blank(0), coord_frame, out, capacity, count); });
}

}  // extern "C"
