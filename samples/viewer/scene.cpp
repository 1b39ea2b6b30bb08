#include "scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "octocap/octocap.hpp"

namespace {

Eigen::Vector3f position(const octocap_joint_t& j) { return {j.position[0], j.position[1], j.position[2]}; }

}  // namespace

void Scene::load_model() {
  character_ = load_character(options_.model.empty() ? default_character_path() : options_.model);
  map_ = find_bone_map(character_);
  if (!options_.bone_map.empty()) apply_bone_map_file(character_, options_.bone_map, map_);
  retarget_ = std::make_unique<Retargeter>(character_, map_);
}

Scene::Scene(octocap::Subscriber* live, const SceneOptions& options) : live_(live), options_(options) { load_model(); }

bool Scene::take_live(int timeout_ms) {
  if (!live_) throw std::runtime_error("not a live scene");
  const std::optional<octocap::Frame> frame = live_->take(timeout_ms);
  if (!frame) return false;
  // One figure per person of the frame, kept by id; a person who left takes their figure along.
  std::vector<Figure> next;
  for (uint32_t i = 0; i < frame->person_count(); ++i) {
    const uint32_t id = frame->person(i).id;
    const std::vector<octocap_bone_pose_t> bones = frame->bones(i, OCTOCAP_FRAME_RIG);
    Figure figure;
    for (Figure& f : figures_)
      if (f.person_id == id) figure = std::move(f);
    figure.person_id = id;
    if (figure.scale <= 0 && bones[OCTOCAP_BONE_L_UPPER_LEG].valid && bones[OCTOCAP_BONE_L_LOWER_LEG].valid) {
      // A person's first frame with a leg sets their scale; the first person's sets the floor (below the lowest
      // joint, a knee: about half a metre).
      figure.scale = (bones[OCTOCAP_BONE_L_UPPER_LEG].length_m + bones[OCTOCAP_BONE_L_LOWER_LEG].length_m) /
                     retarget_->model_leg_length();
      if (!has_floor_) {
        float lowest = std::numeric_limits<float>::infinity();
        for (const auto& b : bones)
          if (b.valid) lowest = std::min(lowest, b.head_position[1]);
        floor_y_ = lowest - 0.5f;
        has_floor_ = true;
      }
    }
    if (figure.scale <= 0) continue;
    pose_bones(figure, bones.data());
    next.push_back(std::move(figure));
  }
  figures_ = std::move(next);
  posed_ = !figures_.empty();
  return posed_;
}

Scene::Scene(const std::string& motion_path, const SceneOptions& options) : options_(options) {
  motion_ = std::make_unique<octocap::Motion>(motion_path);
  frames_ = motion_->frame_count();
  rate_hz_ = motion_->rate_hz();
  load_model();

  // One scale for the whole take (the median leg), and the floor and centre the cameras look at.
  std::vector<float> legs;
  float lowest = std::numeric_limits<float>::infinity();
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  int roots = 0;
  const uint32_t step = std::max(1u, frames_ / 200);
  for (uint32_t f = 0; f < frames_; f += step) {
    const octocap::Frame frame = motion_->frame(f);
    if (frame.person_count() == 0) continue;
    const std::vector<octocap_bone_pose_t> bones = frame.bones(0, OCTOCAP_FRAME_RIG);
    const std::vector<octocap_joint_t> joints = frame.joints(0);
    if (bones[OCTOCAP_BONE_L_UPPER_LEG].valid && bones[OCTOCAP_BONE_L_LOWER_LEG].valid)
      legs.push_back(bones[OCTOCAP_BONE_L_UPPER_LEG].length_m + bones[OCTOCAP_BONE_L_LOWER_LEG].length_m);
    for (const auto& j : joints)
      if (j.valid) lowest = std::min(lowest, j.position[1]);
    if (joints[OCTOCAP_JOINT_ROOT].valid) sum += position(joints[OCTOCAP_JOINT_ROOT]), ++roots;
  }
  if (legs.empty()) throw std::runtime_error(motion_path + ": no frame has a left leg (hip, knee, ankle)");
  std::nth_element(legs.begin(), legs.begin() + legs.size() / 2, legs.end());
  figures_.resize(1);
  figures_[0].scale = legs[legs.size() / 2] / retarget_->model_leg_length();
  floor_y_ = std::isfinite(lowest) ? lowest - 0.08f : 0.0f;  // feet joints sit at the ankles
  centre_ = roots ? Eigen::Vector3f(sum / static_cast<float>(roots)) : Eigen::Vector3f::Zero();
}

Scene::~Scene() = default;

std::vector<Drawable> Scene::drawables() const {
  std::vector<Drawable> out;
  if (!posed_) return out;
  for (const Figure& f : figures_) out.push_back(Drawable{&f.skinned, f.placement});
  return out;
}

std::vector<Segment> Scene::skeletons() const {
  std::vector<Segment> out;
  for (const Figure& f : figures_) out.insert(out.end(), f.segments.begin(), f.segments.end());
  return out;
}

std::vector<const SkinnedMesh*> Scene::meshes() const {
  std::vector<const SkinnedMesh*> out;
  for (const auto& m : character_.meshes) out.push_back(&m);
  return out;
}

void Scene::pose(int frame) {
  if (!motion_) throw std::runtime_error("a live scene is posed by take_live()");
  const uint32_t f = static_cast<uint32_t>(std::clamp(frame, 0, static_cast<int>(frames_) - 1));
  const octocap::Frame posed = motion_->frame(f);
  if (posed.person_count() == 0) return;  // a frame of the file with no joints: keep the last pose
  pose_bones(figures_[0], posed.bones(0, OCTOCAP_FRAME_RIG).data());
}

void Scene::pose_bones(Figure& figure, const octocap_bone_pose_t* bones) {
  posed_ = true;
  figure.globals = retarget_->pose(bones);
  const std::vector<Eigen::Affine3f>& globals = figure.globals;
  const auto skin = skin_matrices(character_, globals);
  figure.skinned.resize(character_.meshes.size());
  for (size_t m = 0; m < character_.meshes.size(); ++m)
    skin_mesh(character_.meshes[m], skin, Eigen::Affine3f::Identity(), options_.skinning, figure.skinned[m]);

  // Placement with the figure's fixed scale (the take's median leg, a live person's first), else this pose's legs.
  figure.placement = retarget_->placement(bones, globals, figure.scale);
  if (bones[OCTOCAP_BONE_ROOT].valid)
    figure.root = {bones[OCTOCAP_BONE_ROOT].head_position[0], bones[OCTOCAP_BONE_ROOT].head_position[1],
             bones[OCTOCAP_BONE_ROOT].head_position[2]};
  // The overlay is the measured skeleton: each bone from its head along its rotated rest direction.
  figure.segments.clear();
  if (options_.skeleton_overlay)
    for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
      if (!bones[b].valid) continue;
      octocap_bone_info_t info;
      octocap_bone_info(static_cast<uint32_t>(b), &info);
      const octocap_quat_t& q = bones[b].global_rotation;
      const Eigen::Vector3f head(bones[b].head_position[0], bones[b].head_position[1], bones[b].head_position[2]);
      const Eigen::Vector3f dir(info.rest_direction[0], info.rest_direction[1], info.rest_direction[2]);
      figure.segments.emplace_back(head, head + Eigen::Quaternionf(q.w, q.x, q.y, q.z) * dir * bones[b].length_m);
    }

  figure.joints.fill(Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()));
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
    if (map_[b] < 0) continue;
    octocap_bone_info_t info;
    octocap_bone_info(static_cast<uint32_t>(b), &info);
    if (!figure.joints[info.head_joint].allFinite()) figure.joints[info.head_joint] = figure.placement * retarget_->bone_head(globals, b);
  }
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
    if (map_[b] < 0) continue;
    octocap_bone_info_t info;
    octocap_bone_info(static_cast<uint32_t>(b), &info);
    if (!figure.joints[info.tail_joint].allFinite()) figure.joints[info.tail_joint] = figure.placement * retarget_->bone_tail(globals, b);
  }
}
