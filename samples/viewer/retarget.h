// Drives a character's bones with octocap's bone rotations. Each octocap bone is mapped to one node of the model
// (found by name: Mixamo, Unity Humanoid, MakeHuman / Rigify, Biped-style; or given in a JSON map), and rotations
// are applied relative to the model's own rest pose: a model resting in an A-pose, or facing another axis, still
// reproduces the measured bone directions.
//
// Two bones are not one node each, because a model's skin is not: the root's rotation goes to the joint the legs'
// and the spine's skin share (the lowest common ancestor of the thighs and the spine: Mixamo's Hips), never to a
// sibling branch, so that every joint between the root and the spine turns with the body; and the torso's rotation
// against the hips is spread over the spine's nodes up to the chest, node k of n taking k/n of it (the C#
// retargeter's rule for Spine, Chest, UpperChest), so that a twist turns along the back, not at one joint.
#pragma once
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "character.h"
#include "octocap/octocap.h"

using BoneMap = std::array<int, OCTOCAP_BONE_COUNT>;  // model node per octocap bone, -1 when unmapped

// Name heuristics. Every bone but the shoulders (clavicles) and feet must be found for a usable map.
BoneMap find_bone_map(const Character& c);
// Overrides from a JSON object {"l_upper_arm": "mixamorig:LeftArm", ...} (octocap bone names). Throws
// std::runtime_error naming the file, an unknown octocap bone or a node the model does not have.
void apply_bone_map_file(const Character& c, const std::string& path, BoneMap& map);
// Bones a pose needs that the map lacks, as "name, name" (empty when complete).
std::string missing_bones(const BoneMap& map);

class Retargeter {
 public:
  // Throws std::runtime_error when the map lacks a bone needed to find the model's orientation, or when the thighs
  // and the spine have no common ancestor (no node could carry the root's rotation to both).
  Retargeter(const Character& c, const BoneMap& map);

  // Node globals (model space, rest scale) for octocap bone poses in the rig frame (OCTOCAP_FRAME_RIG).
  // Invalid bones keep the rest orientation relative to their parent.
  std::vector<Eigen::Affine3f> pose(const octocap_bone_pose_t* bones) const;
  // Model space -> rig frame placement of posed globals: rotation to octocap's axes, scale to the subject's size
  // (`scale`, model -> metres; 0: from the pose's leg length), the model's hip centre (between its thighs) on the
  // measured root (between the hips). Pinning the posed hip centre, not a node's rest position, keeps the placement
  // the same whichever way the person faces.
  Eigen::Affine3f placement(const octocap_bone_pose_t* bones, const std::vector<Eigen::Affine3f>& globals,
                            float scale = 0) const;

  // The node the root's rotation drives, and the spine's nodes the torso's rotation is spread over (hips up; the
  // last one, the chest, takes all of it).
  int root_node() const { return root_node_; }
  const std::vector<int>& spine_nodes() const { return spine_; }
  // Every node pose() sets (the rest follow their parents at rest): what an animation must carry.
  std::vector<int> driven_nodes() const;

  // Rest direction of each mapped bone in the rig frame after alignment (tests compare posed directions).
  const Eigen::Matrix3f& model_to_rig() const { return to_rig_; }
  // Hip-knee-ankle length of the model's left leg in its rest pose (the size the subject's is compared with).
  float model_leg_length() const { return leg_length_; }
  // Global position of the head and tail of octocap bone b on posed model globals (model space).
  Eigen::Vector3f bone_head(const std::vector<Eigen::Affine3f>& globals, int b) const;
  Eigen::Vector3f bone_tail(const std::vector<Eigen::Affine3f>& globals, int b) const;

 private:
  const Character& c_;
  BoneMap map_;
  std::vector<Eigen::Affine3f> rest_locals_, rest_globals_;
  std::array<int, OCTOCAP_BONE_COUNT> tail_node_{};
  std::array<Eigen::Quaternionf, OCTOCAP_BONE_COUNT> correction_;  // model rest direction -> template direction
  Eigen::Matrix3f to_rig_ = Eigen::Matrix3f::Identity();           // model axes -> rig axes
  float leg_length_ = 1;
  int root_node_ = -1;
  std::vector<int> spine_;
};
