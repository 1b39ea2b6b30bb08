#include "stream/wire_convert.h"

#include <cmath>
#include <cstring>

namespace octocap {
namespace {

void to_wire(const PointResult& r, octocap_wire_PointSample& s) {
  s = octocap_wire_PointSample{};
  if (!r.valid) return;
  for (int k = 0; k < 3; ++k) s.position[k] = static_cast<float>(r.position[k]);
  s.confidence = static_cast<float>(r.confidence);
  s.reprojection_error_px = static_cast<float>(r.reprojection_error_px);
  s.views_used = r.views_used;
  s.valid = 1;
}

bool finite(const float* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

bool from_wire(const octocap_wire_PointSample& s, PointResult& r) {
  r = PointResult{};
  if (!s.valid) return true;
  if (!finite(s.position, 3) || !std::isfinite(s.confidence) || !std::isfinite(s.reprojection_error_px)) return false;
  r.position = Eigen::Vector3d(s.position[0], s.position[1], s.position[2]);
  r.confidence = s.confidence;
  r.reprojection_error_px = s.reprojection_error_px;
  r.views_used = s.views_used;
  r.valid = true;
  return true;
}

void quat_to(const Eigen::Quaterniond& q, float* out) {
  out[0] = static_cast<float>(q.x());
  out[1] = static_cast<float>(q.y());
  out[2] = static_cast<float>(q.z());
  out[3] = static_cast<float>(q.w());
}

Eigen::Quaterniond quat_from(const float* q) { return Eigen::Quaterniond(q[3], q[0], q[1], q[2]); }

template <class Seq, class T>
void point_seq(Seq& seq, std::vector<T>& buf) {
  seq._maximum = seq._length = static_cast<uint32_t>(buf.size());
  seq._buffer = buf.data();
  seq._release = false;
}

void copy_name(char (&dst)[32], const char* src) {
  std::strncpy(dst, src, 31);
  dst[31] = '\0';
}

}  // namespace

void fill_pose(const FrameResult& frame, uint32_t source_id, uint32_t definition_counter, PoseBuffers& out) {
  // The wire's Pose carries one person: the first (lowest id) of the frame.
  const PersonResult& person = frame.person_or_blank(0);
  out.keypoints.resize(person.keypoints.size());
  for (size_t k = 0; k < person.keypoints.size(); ++k) to_wire(person.keypoints[k], out.keypoints[k]);
  out.joints.resize(kJointCount);
  for (int j = 0; j < kJointCount; ++j) to_wire(person.joints[j], out.joints[j]);
  out.bones.resize(kBoneCount);
  for (int b = 0; b < kBoneCount; ++b) {
    const BonePose& p = person.bones[b];
    octocap_wire_BoneSample& s = out.bones[b];
    s = octocap_wire_BoneSample{};
    quat_to(p.local, s.local_rotation);
    quat_to(p.global, s.global_rotation);
    for (int k = 0; k < 3; ++k) s.head_position[k] = static_cast<float>(p.head[k]);
    s.length_m = static_cast<float>(p.length);
    s.valid = p.valid ? 1 : 0;
  }
  octocap_wire_Pose& w = out.sample;
  w.source_id = source_id;
  w.version = octocap_wire_VERSION;
  w.frame_number = static_cast<uint64_t>(frame.info.frame_index);
  w.timestamp_us = frame.info.timestamp_us;
  w.definition_counter = definition_counter;
  w.mean_reprojection_error_px = static_cast<float>(frame.info.mean_reprojection_error_px);
  w.views_with_person = frame.info.views_with_person;
  point_seq(w.keypoints, out.keypoints);
  point_seq(w.joints, out.joints);
  point_seq(w.bones, out.bones);
  std::memcpy(w.root_position, out.bones[kBoneRoot].head_position, sizeof w.root_position);
  std::memcpy(w.root_rotation, out.bones[kBoneRoot].global_rotation, sizeof w.root_rotation);
}

bool read_pose(const octocap_wire_Pose& in, LayoutId layout_id, FrameResult& out, std::string& why) {
  if (in.version != octocap_wire_VERSION) {
    why = "wire version " + std::to_string(in.version) + ", this reader understands " +
          std::to_string(octocap_wire_VERSION);
    return false;
  }
  const size_t K = layout(layout_id).keypoints.size();
  if (in.keypoints._length != K || in.joints._length != kJointCount || in.bones._length != kBoneCount) {
    why = "sizes " + std::to_string(in.keypoints._length) + "/" + std::to_string(in.joints._length) + "/" +
          std::to_string(in.bones._length) + " do not match the skeleton definition (" + std::to_string(K) + "/" +
          std::to_string(kJointCount) + "/" + std::to_string(kBoneCount) + ")";
    return false;
  }
  out.layout = layout_id;
  PersonResult person;
  person.keypoints.resize(K);
  uint32_t solved = 0;
  for (size_t k = 0; k < K; ++k) {
    if (!from_wire(in.keypoints._buffer[k], person.keypoints[k])) {
      why = "non-finite keypoint";
      return false;
    }
    solved += person.keypoints[k].valid;
  }
  for (int j = 0; j < kJointCount; ++j)
    if (!from_wire(in.joints._buffer[j], person.joints[j])) {
      why = "non-finite joint";
      return false;
    }
  for (int b = 0; b < kBoneCount; ++b) {
    const octocap_wire_BoneSample& s = in.bones._buffer[b];
    if (!finite(s.local_rotation, 4) || !finite(s.global_rotation, 4) || !finite(s.head_position, 3) ||
        !std::isfinite(s.length_m)) {
      why = "non-finite bone";
      return false;
    }
    BonePose& p = person.bones[b];
    p.local = quat_from(s.local_rotation);
    p.global = quat_from(s.global_rotation);
    p.head = Eigen::Vector3d(s.head_position[0], s.head_position[1], s.head_position[2]);
    p.length = s.length_m;
    p.valid = s.valid != 0;
  }
  if (in.frame_number > (uint64_t{1} << 62)) {
    why = "frame number " + std::to_string(in.frame_number) + " is out of range";
    return false;
  }
  out.info.frame_index = static_cast<int64_t>(in.frame_number);
  out.info.timestamp_us = in.timestamp_us;
  out.info.keypoints_solved = solved;
  out.info.keypoints_total = static_cast<uint32_t>(K);
  out.info.mean_reprojection_error_px = in.mean_reprojection_error_px;
  out.info.views_with_person = in.views_with_person;
  out.info.solve_ms = 0;
  person.keypoints_solved = solved;
  person.views_with_person = in.views_with_person;
  person.mean_reprojection_error_px = in.mean_reprojection_error_px;
  out.people.clear();
  out.blank = PersonResult{};
  out.blank.keypoints.assign(K, PointResult{});
  if (person.has_pose()) out.people.push_back(std::move(person));
  return true;
}

void fill_definition(LayoutId layout_id, uint32_t source_id, uint32_t change_counter, DefinitionBuffers& out) {
  const KeypointLayout& l = layout(layout_id);
  out.keypoint_names.assign(l.keypoints.size(), Name32{});
  for (size_t k = 0; k < l.keypoints.size(); ++k) copy_name(out.keypoint_names[k].s, l.keypoints[k]);
  out.joint_names.assign(kJointCount, Name32{});
  for (int j = 0; j < kJointCount; ++j) copy_name(out.joint_names[j].s, joint_names()[j]);
  out.bones.resize(kBoneCount);
  for (int b = 0; b < kBoneCount; ++b) {
    const BoneDef& d = bone_table()[b];
    octocap_wire_BoneDef& w = out.bones[b];
    copy_name(w.name, d.name);
    w.parent_bone = d.parent;
    w.head_joint = d.head;
    w.tail_joint = d.tail;
    for (int k = 0; k < 3; ++k) w.rest_direction[k] = static_cast<float>(tpose_directions()[b][k]);
  }
  octocap_wire_SkeletonDefinition& s = out.sample;
  s.source_id = source_id;
  s.version = octocap_wire_VERSION;
  s.change_counter = change_counter;
  s.layout = static_cast<int32_t>(layout_id);
  s.keypoint_names._maximum = s.keypoint_names._length = static_cast<uint32_t>(out.keypoint_names.size());
  s.keypoint_names._buffer = reinterpret_cast<char(*)[32]>(out.keypoint_names.data());
  s.keypoint_names._release = false;
  s.joint_names._maximum = s.joint_names._length = static_cast<uint32_t>(out.joint_names.size());
  s.joint_names._buffer = reinterpret_cast<char(*)[32]>(out.joint_names.data());
  s.joint_names._release = false;
  s.bones._maximum = s.bones._length = static_cast<uint32_t>(out.bones.size());
  s.bones._buffer = out.bones.data();
  s.bones._release = false;
}

}  // namespace octocap
