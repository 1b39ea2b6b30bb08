// Animated characters: a motion file (through the C ABI) driving a rigged model frame by frame, or a live DDS stream
// driving one copy of the model per person it carries (each with its own scale, from that person's legs).
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

// One posed character: a person of the frame on the model.
struct Figure {
  uint32_t person_id = 0;
  float scale = 0;  // model -> metres, from the person's legs
  std::vector<SkinnedVertices> skinned;
  Eigen::Affine3f placement = Eigen::Affine3f::Identity();  // model space -> rig frame
  std::vector<Eigen::Affine3f> globals;                    // posed nodes, model space
  std::vector<Segment> segments;                           // the measured skeleton (overlay)
  std::array<Eigen::Vector3f, OCTOCAP_JOINT_COUNT> joints{};
  Eigen::Vector3f root = Eigen::Vector3f::Zero();
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
  // The first figure in a pose given bone by bone (OCTOCAP_BONE_COUNT of them, rig frame): a motion's frame changed
  // by hand, a pose from elsewhere.
  void pose(const octocap_bone_pose_t* bones) { pose_bones(figures_.at(0), bones); }
  // Live: waits up to timeout_ms for the next pose and applies it; false when none came.
  bool take_live(int timeout_ms);
  bool live() const { return live_ != nullptr; }
  bool posed() const { return posed_; }

  // Every posed character, in person id order (a motion file: one). The accessors below read the first.
  const std::vector<Figure>& figures() const { return figures_; }
  // What the renderer draws: every figure's skinned meshes where it stands, and all their skeletons.
  std::vector<Drawable> drawables() const;
  std::vector<Segment> skeletons() const;

  const std::vector<SkinnedVertices>& vertices() const { return first().skinned; }
  const Eigen::Affine3f& placement() const { return first().placement; }  // model space -> rig frame
  const std::vector<Eigen::Affine3f>& globals() const { return first().globals; }  // posed nodes, model space
  const std::vector<Segment>& skeleton() const { return first().segments; }
  std::vector<const SkinnedMesh*> meshes() const;
  float floor_y() const { return floor_y_; }
  const Eigen::Vector3f& centre() const { return centre_; }
  // The current frame's root (the orbit camera follows it): the first figure's.
  const Eigen::Vector3f& root() const { return first().root; }
  const Character& character() const { return character_; }
  const BoneMap& bone_map() const { return map_; }
  const Retargeter& retargeter() const { return *retarget_; }
  // The character's own joints at the current pose, rig frame (where its limbs really are: the ground truth
  // for rendered views). NaN where the map has no bone.
  const std::array<Eigen::Vector3f, OCTOCAP_JOINT_COUNT>& character_joints() const { return first().joints; }

 private:
  void load_model();
  void pose_bones(Figure& figure, const octocap_bone_pose_t* bones);
  const Figure& first() const { return figures_.empty() ? empty_ : figures_.front(); }

  std::unique_ptr<octocap::Motion> motion_;
  octocap::Subscriber* live_ = nullptr;
  bool posed_ = false;
  uint32_t frames_ = 0;
  double rate_hz_ = 30;
  SceneOptions options_;
  Character character_;
  BoneMap map_{};
  std::unique_ptr<Retargeter> retarget_;
  float floor_y_ = 0;
  bool has_floor_ = false;
  Eigen::Vector3f centre_ = Eigen::Vector3f::Zero();
  std::vector<Figure> figures_;
  Figure empty_;
};
