#include "capi/frame_queries.h"

#include "capi/boundary.h"
#include "capi/struct_versions.h"
#include "rig/engine_frames.h"

namespace octocap::internal::capi {
namespace {

CoordFrame frame_of(octocap_coord_frame_t f) {
  if (f != OCTOCAP_FRAME_RIG && f != OCTOCAP_FRAME_UNITY && f != OCTOCAP_FRAME_GODOT)
    throw Error(Errc::invalid_argument, "unknown coordinate frame " + std::to_string(f));
  return static_cast<CoordFrame>(f);
}

octocap_quat_t quat_c(const Eigen::Quaterniond& q) {
  return {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()), static_cast<float>(q.w())};
}

// Joints and bones are only ever appended: a caller built with an older header's count (its capacity at least that
// count) gets as many as it has room for, and OK. Below the oldest count the two-call pattern's BUFFER_TOO_SMALL holds.
uint32_t appended_count(uint32_t now, uint32_t first_released, const void* out, uint32_t capacity) {
  return out && capacity >= first_released && capacity < now ? capacity : now;
}

}  // namespace

void check_person(const FrameResult& f, uint32_t person, bool allow_empty) {
  const size_t n = f.person_count();
  if (person < n || (allow_empty && person == 0)) return;
  throw Error(Errc::invalid_argument, "person " + std::to_string(person) + " out of range (the frame holds " +
                                          std::to_string(n) + (n == 1 ? " person)" : " people)"));
}

void to_c_joint(const PointResult& r, octocap_joint_t& out) {
  out = octocap_joint_t{};
  if (!r.valid) return;
  for (int k = 0; k < 3; ++k) out.position[k] = static_cast<float>(r.position[k]);
  out.confidence = static_cast<float>(r.confidence);
  out.reprojection_error_px = static_cast<float>(r.reprojection_error_px);
  out.views_used = r.views_used;
  out.valid = 1;
}

void query_summary(const FrameResult& f, octocap_frame_summary_t* out) {
  fill_sized(out, sizeof(octocap_frame_summary_t), "octocap_frame_summary_t", [&](octocap_frame_summary_t& s) {
    s.person_count = static_cast<uint32_t>(f.person_count());
    s.frame_index = f.info.frame_index;
    s.timestamp_us = f.info.timestamp_us;
    s.layout = static_cast<octocap_layout_t>(f.layout);
    s.keypoint_count = static_cast<uint32_t>(f.keypoint_count());
    s.definition_counter = f.definition_counter;
    s.source_id = f.source_id;
    s.view_count = f.view_count;
    s.joints_in_rig_frame = f.rig_frame_joints ? 1 : 0;
    s.solve_ms = static_cast<float>(f.info.solve_ms);
  });
}

void query_person(const FrameResult& f, uint32_t person, octocap_person_t* out) {
  check_person(f, person);
  const PersonResult& r = f.people[person];
  fill_sized(out, kPersonSize10, "octocap_person_t", [&](octocap_person_t& p) {
    p.id = r.id;
    p.keypoints_solved = r.keypoints_solved;
    p.keypoints_total = static_cast<uint32_t>(r.keypoints.size());
    for (const PointResult& j : r.joints) p.joints_solved += j.valid ? 1 : 0;
    p.views_with_person = r.views_with_person;
    p.mean_reprojection_error_px = static_cast<float>(r.mean_reprojection_error_px);
    double conf = 0;
    for (const PointResult& k : r.keypoints) conf += k.valid ? k.confidence : 0;
    p.confidence = p.keypoints_solved ? static_cast<float>(conf / p.keypoints_solved) : 0.f;
    p.foot_contacts = (r.foot_contact[0] ? OCTOCAP_FOOT_RIGHT : 0u) | (r.foot_contact[1] ? OCTOCAP_FOOT_LEFT : 0u);
  });
}

void query_frame_info(const FrameResult& f, octocap_frame_info_t* out) {
  require(out, "out");
  *out = octocap_frame_info_t{};
  out->frame_index = f.info.frame_index;
  out->timestamp_us = f.info.timestamp_us;
  out->keypoints_solved = f.info.keypoints_solved;
  out->keypoints_total = f.info.keypoints_total;
  out->mean_reprojection_error_px = static_cast<float>(f.info.mean_reprojection_error_px);
  out->views_with_person = f.info.views_with_person;
  out->solve_ms = static_cast<float>(f.info.solve_ms);
}

void query_keypoints(const PersonResult& f, octocap_joint_t* out, uint32_t capacity, uint32_t* count) {
  fill_array(static_cast<uint32_t>(f.keypoints.size()), out, capacity, count, [&] {
    for (size_t k = 0; k < f.keypoints.size(); ++k) to_c_joint(f.keypoints[k], out[k]);
  });
}

void query_joints(const PersonResult& f, octocap_joint_t* out, uint32_t capacity, uint32_t* count) {
  const uint32_t n = appended_count(kJointCount, kFirstJointCount, out, capacity);
  fill_array(n, out, capacity, count, [&] {
    for (uint32_t j = 0; j < n; ++j) to_c_joint(f.joints[j], out[j]);
  });
}

void query_bones(const PersonResult& f, octocap_coord_frame_t frame, octocap_bone_pose_t* out, uint32_t capacity,
                 uint32_t* count) {
  const CoordFrame cf = frame_of(frame);
  const uint32_t n = appended_count(kBoneCount, kFirstBoneCount, out, capacity);
  fill_array(n, out, capacity, count, [&] {
    for (uint32_t b = 0; b < n; ++b) {
      const BonePose& p = f.bones[b];
      octocap_bone_pose_t& o = out[b];
      o = octocap_bone_pose_t{};
      o.local_rotation = quat_c(convert_rotation(p.local, cf));
      o.global_rotation = quat_c(convert_rotation(p.global, cf));
      const Eigen::Vector3d h = convert_position(p.head, cf);
      for (int k = 0; k < 3; ++k) o.head_position[k] = static_cast<float>(h[k]);
      o.length_m = static_cast<float>(p.length);
      o.valid = p.valid ? 1 : 0;
    }
  });
}

void query_person_views(const PersonResult& f, int32_t* out, uint32_t capacity, uint32_t* count) {
  fill_array(static_cast<uint32_t>(f.selected.size()), out, capacity, count, [&] {
    for (size_t v = 0; v < f.selected.size(); ++v) out[v] = f.selected[v];
  });
}

}  // namespace octocap::internal::capi
