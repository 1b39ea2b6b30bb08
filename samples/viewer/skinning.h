// CPU skinning of a character's meshes for a pose. Linear blend skinning blends the bones' matrices (fast; thin
// "candy-wrapper" collapse where a joint twists); dual-quaternion skinning blends rigid transforms instead and
// keeps the volume (no scale in the bones, which is the case for retargeted poses).
#pragma once
#include <Eigen/Geometry>
#include <vector>

#include "character.h"

enum class SkinningMethod { linear, dual_quaternion };

// bone matrix = node global (posed) * bone offset, per Character::bones. Vertices with no weight follow `unskinned`.
std::vector<Eigen::Affine3f> skin_matrices(const Character& c, const std::vector<Eigen::Affine3f>& posed_globals);

struct SkinnedVertices {
  std::vector<Eigen::Vector3f> positions, normals;
};

void skin_mesh(const SkinnedMesh& mesh, const std::vector<Eigen::Affine3f>& bone_matrices,
               const Eigen::Affine3f& unskinned, SkinningMethod method, SkinnedVertices& out);
