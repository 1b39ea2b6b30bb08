#include "stream/wire_convert.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace octocap::internal {
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

namespace {

// One person's keypoints, joints and bones into `buf`'s sequences.
void fill_person(const PersonResult& person, PoseBuffers& buf) {
  buf.keypoints.resize(person.keypoints.size());
  for (size_t k = 0; k < person.keypoints.size(); ++k) to_wire(person.keypoints[k], buf.keypoints[k]);
  buf.joints.resize(kJointCount);
  for (int j = 0; j < kJointCount; ++j) to_wire(person.joints[j], buf.joints[j]);
  buf.bones.resize(kBoneCount);
  for (int b = 0; b < kBoneCount; ++b) {
    const BonePose& p = person.bones[b];
    octocap_wire_BoneSample& s = buf.bones[b];
    s = octocap_wire_BoneSample{};
    quat_to(p.local, s.local_rotation);
    quat_to(p.global, s.global_rotation);
    for (int k = 0; k < 3; ++k) s.head_position[k] = static_cast<float>(p.head[k]);
    s.length_m = static_cast<float>(p.length);
    s.valid = p.valid ? 1 : 0;
  }
}

bool read_person(const dds_sequence_octocap_wire_PointSample& keypoints,
                 const dds_sequence_octocap_wire_PointSample& joints, const dds_sequence_octocap_wire_BoneSample& bones,
                 size_t K, PersonResult& person, std::string& why) {
  // Joints and bones are only ever appended to the skeleton: a writer of another version sends more or fewer than
  // ours, from the 1.0 skeleton's 15 and 13 up. What both know is read; ours past the writer's stay invalid.
  if (keypoints._length != K || joints._length < static_cast<uint32_t>(kFirstJointCount) ||
      bones._length < static_cast<uint32_t>(kFirstBoneCount)) {
    why = "sizes " + std::to_string(keypoints._length) + "/" + std::to_string(joints._length) + "/" +
          std::to_string(bones._length) + " do not match the skeleton definition (" + std::to_string(K) + "/" +
          std::to_string(kJointCount) + "/" + std::to_string(kBoneCount) + ")";
    return false;
  }
  const int joint_count = std::min<int>(kJointCount, static_cast<int>(joints._length));
  const int bone_count = std::min<int>(kBoneCount, static_cast<int>(bones._length));
  person.keypoints.resize(K);
  person.keypoints_solved = 0;
  for (size_t k = 0; k < K; ++k) {
    if (!from_wire(keypoints._buffer[k], person.keypoints[k])) {
      why = "non-finite keypoint";
      return false;
    }
    person.keypoints_solved += person.keypoints[k].valid;
  }
  for (int j = 0; j < joint_count; ++j)
    if (!from_wire(joints._buffer[j], person.joints[j])) {
      why = "non-finite joint";
      return false;
    }
  for (int b = 0; b < bone_count; ++b) {
    const octocap_wire_BoneSample& s = bones._buffer[b];
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
  return true;
}

// The frame-wide fields Pose and PeopleFrame both carry (read_frame reads them back).
template <class Sample>
void fill_frame(const FrameResult& frame, uint32_t source_id, uint32_t definition_counter, Sample& w) {
  w.source_id = source_id;
  w.version = octocap_wire_VERSION;
  w.frame_number = static_cast<uint64_t>(frame.info.frame_index);
  w.timestamp_us = frame.info.timestamp_us;
  w.definition_counter = definition_counter;
  w.mean_reprojection_error_px = static_cast<float>(frame.info.mean_reprojection_error_px);
  w.views_with_person = frame.info.views_with_person;
}

bool version_ok(uint32_t version, std::string& why) {
  if (version == octocap_wire_VERSION) return true;
  why = "wire version " + std::to_string(version) + ", this reader understands " + std::to_string(octocap_wire_VERSION);
  return false;
}

// The frame-wide fields both samples carry; the people are set by the caller.
bool read_frame(uint64_t frame_number, int64_t timestamp_us, float reprojection, uint32_t views, size_t K,
                LayoutId layout_id, FrameResult& out, std::string& why) {
  if (frame_number > (uint64_t{1} << 62)) {
    why = "frame number " + std::to_string(frame_number) + " is out of range";
    return false;
  }
  if (!std::isfinite(reprojection)) {
    why = "non-finite reprojection error";
    return false;
  }
  out.layout = layout_id;
  out.info.frame_index = static_cast<int64_t>(frame_number);
  out.info.timestamp_us = timestamp_us;
  out.info.keypoints_total = static_cast<uint32_t>(K);
  out.info.mean_reprojection_error_px = reprojection;
  out.info.views_with_person = views;
  out.info.solve_ms = 0;
  out.blank = PersonResult{};
  out.blank.keypoints.assign(K, PointResult{});
  return true;
}

}  // namespace

void fill_pose(const FrameResult& frame, uint32_t source_id, uint32_t definition_counter, PoseBuffers& out) {
  // The wire's Pose carries one person: the first (lowest id) of the frame.
  fill_person(frame.person_or_blank(0), out);
  octocap_wire_Pose& w = out.sample;
  fill_frame(frame, source_id, definition_counter, w);
  point_seq(w.keypoints, out.keypoints);
  point_seq(w.joints, out.joints);
  point_seq(w.bones, out.bones);
  std::memcpy(w.root_position, out.bones[kBoneRoot].head_position, sizeof w.root_position);
  std::memcpy(w.root_rotation, out.bones[kBoneRoot].global_rotation, sizeof w.root_rotation);
}

void fill_people(const FrameResult& frame, uint32_t source_id, uint32_t definition_counter, PeopleBuffers& out) {
  const size_t n = std::min<size_t>(frame.people.size(), kWirePeople);
  if (out.people.size() < n) out.people.resize(n);
  out.samples.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const PersonResult& person = frame.people[i];
    fill_person(person, out.people[i]);
    octocap_wire_PersonPose& w = out.samples[i];
    w.person_id = person.id;
    w.mean_reprojection_error_px = static_cast<float>(person.mean_reprojection_error_px);
    w.views_with_person = person.views_with_person;
    point_seq(w.keypoints, out.people[i].keypoints);
    point_seq(w.joints, out.people[i].joints);
    point_seq(w.bones, out.people[i].bones);
  }
  octocap_wire_PeopleFrame& w = out.sample;
  fill_frame(frame, source_id, definition_counter, w);
  point_seq(w.people, out.samples);
}

bool read_pose(const octocap_wire_Pose& in, LayoutId layout_id, FrameResult& out, std::string& why) {
  if (!version_ok(in.version, why)) return false;
  const size_t K = layout(layout_id).keypoints.size();
  PersonResult person;
  if (!read_person(in.keypoints, in.joints, in.bones, K, person, why)) return false;
  if (!read_frame(in.frame_number, in.timestamp_us, in.mean_reprojection_error_px, in.views_with_person, K, layout_id,
                  out, why))
    return false;
  out.info.keypoints_solved = person.keypoints_solved;
  person.views_with_person = in.views_with_person;
  person.mean_reprojection_error_px = in.mean_reprojection_error_px;
  out.people.clear();
  if (person.has_pose()) out.people.push_back(std::move(person));
  return true;
}

bool read_people(const octocap_wire_PeopleFrame& in, LayoutId layout_id, FrameResult& out, std::string& why) {
  if (!version_ok(in.version, why)) return false;
  const size_t K = layout(layout_id).keypoints.size();
  std::vector<PersonResult> people(in.people._length);
  uint32_t solved = 0;
  for (uint32_t i = 0; i < in.people._length; ++i) {
    const octocap_wire_PersonPose& w = in.people._buffer[i];
    if (w.person_id == 0 || (i > 0 && w.person_id <= people[i - 1].id)) {
      why = "person ids must be non-zero and increasing (" + std::to_string(w.person_id) + ")";
      return false;
    }
    if (!std::isfinite(w.mean_reprojection_error_px)) {
      why = "non-finite reprojection error";
      return false;
    }
    PersonResult& p = people[i];
    if (!read_person(w.keypoints, w.joints, w.bones, K, p, why)) return false;
    p.id = w.person_id;
    p.views_with_person = w.views_with_person;
    p.mean_reprojection_error_px = w.mean_reprojection_error_px;
    solved += p.keypoints_solved;
  }
  if (!read_frame(in.frame_number, in.timestamp_us, in.mean_reprojection_error_px, in.views_with_person, K, layout_id,
                  out, why))
    return false;
  out.info.keypoints_solved = solved;
  out.people = std::move(people);
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

}  // namespace octocap::internal
