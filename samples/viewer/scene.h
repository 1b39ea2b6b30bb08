// One animated character: a motion file (through the C ABI) driving a rigged model, posed frame by frame.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "character.h"
#include "octocap/octocap.hpp"
#include "renderer.h"
#include "retarget.h"
#include "skinning.h"

struct SceneOptions {
  std::string model;     // empty: default_character_path()
  std::string bone_map;  // optional JSON overrides
  SkinningMethod skinning = SkinningMethod::linear;
  bool skeleton_overlay = false;
};

class Scene {
 public:
  // Throws std::runtime_error with the library's or assimp's message.
  Scene(const std::string& motion_path, const SceneOptions& options);
  // A live scene: poses arrive over DDS from `live` (not owned), through take_live().
  Scene(octocap::Subscriber* live, const SceneOptions& options);
  ~Scene();

  int frame_count() const { return static_cast<int>(frames_); }
  double rate_hz() const { return rate_hz_; }
  void pose(int frame);
  // Live: waits up to timeout_ms for the next pose and applies it; false when none came.
  bool take_live(int timeout_ms);
  bool live() const { return live_ != nullptr; }
  bool posed() const { return posed_; }

  const std::vector<SkinnedVertices>& vertices() const { return skinned_; }
  const Eigen::Affine3f& placement() const { return placement_; }  // model space -> rig frame
  const std::vector<Eigen::Affine3f>& globals() const { return globals_; }  // posed nodes, model space
  const std::vector<Segment>& skeleton() const { return segments_; }
  std::vector<const SkinnedMesh*> meshes() const;
  float floor_y() const { return floor_y_; }
  const Eigen::Vector3f& centre() const { return centre_; }
  // The current frame's root (the orbit camera follows it).
  const Eigen::Vector3f& root() const { return root_; }
  const Character& character() const { return character_; }
  const BoneMap& bone_map() const { return map_; }
  // The character's own 15 joints at the current pose, rig frame (where its limbs really are: the ground truth
  // for rendered views). NaN where the map has no bone.
  const std::array<Eigen::Vector3f, OCTOCAP_JOINT_COUNT>& character_joints() const { return joints_; }

 private:
  void load_model();
  void pose_bones(const octocap_bone_pose_t* bones);

  std::unique_ptr<octocap::Motion> motion_;
  octocap::Subscriber* live_ = nullptr;
  bool posed_ = false;
  uint32_t frames_ = 0;
  double rate_hz_ = 30;
  SceneOptions options_;
  Character character_;
  BoneMap map_{};
  std::unique_ptr<Retargeter> retarget_;
  float scale_ = 0;  // set from the motion's (or the first live frame's) leg length
  float floor_y_ = 0;
  Eigen::Vector3f centre_ = Eigen::Vector3f::Zero();
  Eigen::Vector3f root_ = Eigen::Vector3f::Zero();
  std::vector<SkinnedVertices> skinned_;
  Eigen::Affine3f placement_ = Eigen::Affine3f::Identity();
  std::vector<Eigen::Affine3f> globals_;
  std::vector<Segment> segments_;
  std::array<Eigen::Vector3f, OCTOCAP_JOINT_COUNT> joints_{};
};
