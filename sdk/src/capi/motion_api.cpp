// Motion files for playback: frames of joints and bone poses, from TRC / CSV / BVH.
#include "capi/boundary.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"
#include "rig/motion_take.h"

using namespace octocap::internal;

namespace {

FrameResult frame_at(const octocap_motion_t* m, uint32_t frame) { return capi::checked(m, "motion")->take.frame(frame); }

}  // namespace

extern "C" {

octocap_result_t octocap_motion_open(const char* path, octocap_motion_t** out) {
  return capi::guard([&] {
    capi::require(out, "out");
    *out = nullptr;
    capi::require(path, "path");
    *out = capi::make_handle<octocap_motion_t>(MotionTake(path));
  });
}

void octocap_motion_destroy(octocap_motion_t* m) { capi::destroy_handle(m); }

octocap_result_t octocap_motion_info(const octocap_motion_t* m, uint32_t* frame_count, double* rate_hz) {
  return capi::guard([&] {
    capi::checked(m, "motion");
    if (frame_count) *frame_count = m->take.frame_count();
    if (rate_hz) *rate_hz = m->take.rate_hz();
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
