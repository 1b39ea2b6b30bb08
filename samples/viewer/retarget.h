// Drives a character's bones with octocap's bone rotations. Each octocap bone is mapped to one node of the model
// (found by name: Mixamo, Unity Humanoid, MakeHuman / Rigify, Biped-style; or given in a JSON map), and rotations
// are applied relative to the model's own rest pose: a model resting in an A-pose, or facing another axis, still
// reproduces the measured bone directions.
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
  // Throws std::runtime_error when the map lacks a bone needed to find the model's orientation.
  Retargeter(const Character& c, const BoneMap& map);

  // Node globals (model space, rest scale) for octocap bone poses in the rig frame (OCTOCAP_FRAME_RIG).
  // Invalid bones keep the rest orientation relative to their parent.
  std::vector<Eigen::Affine3f> pose(const octocap_bone_pose_t* bones) const;
  // Model space -> rig frame placement: rotation to octocap's axes, scale to the subject's size (from the
  // pose's leg length), the model root on the measured root.
  Eigen::Affine3f placement(const octocap_bone_pose_t* bones) const;

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
};
