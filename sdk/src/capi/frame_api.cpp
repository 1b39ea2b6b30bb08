// Frame handles: the one family of per-frame queries, whatever the source.
#include "capi/boundary.h"
#include "capi/frame_queries.h"
#include "capi/handles.h"

using namespace octocap::internal;

namespace octocap::internal::capi {

octocap_frame_t* make_frame(std::shared_ptr<const FrameResult> frame) {
  return make_handle<octocap_frame_t>(std::move(frame));
}

}  // namespace octocap::internal::capi

namespace {

const FrameResult& frame_of(const octocap_frame_t* f) { return *capi::checked(f, "frame")->frame; }

const PersonResult& person_of(const octocap_frame_t* f, uint32_t person) {
  const FrameResult& r = frame_of(f);
  capi::check_person(r, person);
  return r.people[person];
}

}  // namespace

extern "C" {

octocap_result_t octocap_frame_get_summary(const octocap_frame_t* f, octocap_frame_summary_t* out) {
  return capi::guard([&] { capi::query_summary(frame_of(f), out); });
}

octocap_result_t octocap_frame_get_person(const octocap_frame_t* f, uint32_t person, octocap_person_t* out) {
  return capi::guard([&] { capi::query_person(frame_of(f), person, out); });
}

octocap_result_t octocap_frame_get_keypoints3d(const octocap_frame_t* f, uint32_t person, octocap_joint_t* out,
                                               uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_keypoints(person_of(f, person), out, capacity, count); });
}

octocap_result_t octocap_frame_get_joints(const octocap_frame_t* f, uint32_t person, octocap_joint_t* out,
                                          uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_joints(person_of(f, person), out, capacity, count); });
}

octocap_result_t octocap_frame_get_bones(const octocap_frame_t* f, uint32_t person, octocap_coord_frame_t coord_frame,
                                         octocap_bone_pose_t* out, uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_bones(person_of(f, person), coord_frame, out, capacity, count); });
}

octocap_result_t octocap_frame_get_person_views(const octocap_frame_t* f, uint32_t person, int32_t* out,
                                                uint32_t capacity, uint32_t* count) {
  return capi::guard([&] { capi::query_person_views(person_of(f, person), out, capacity, count); });
}

void octocap_frame_release(octocap_frame_t* f) { capi::destroy_handle(f); }

}  // extern "C"
