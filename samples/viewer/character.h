// A rigged, skinned character: node hierarchy with its rest (bind) pose, meshes with up to 4 bone weights per
// vertex. Loaded with assimp from any format it reads (glTF/GLB, FBX, COLLADA, X, ...), or built by hand (tests).
#pragma once
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

struct CharacterNode {
  std::string name;
  int parent = -1;                                     // parents come before children
  Eigen::Affine3f local = Eigen::Affine3f::Identity();  // rest pose, relative to the parent
};

struct SkinBone {
  int node = -1;
  Eigen::Affine3f offset = Eigen::Affine3f::Identity();  // mesh space -> bone space in the rest pose
};

struct SkinnedMesh {
  std::vector<Eigen::Vector3f> positions, normals;  // rest pose, mesh space
  std::vector<uint32_t> indices;                    // triangles
  std::vector<std::array<uint16_t, 4>> bone_ids;    // into Character::bones
  std::vector<std::array<float, 4>> weights;        // sum to 1 (0 weights for unused slots)
};

struct Character {
  std::string source;
  std::vector<CharacterNode> nodes;
  std::vector<SkinBone> bones;
  std::vector<SkinnedMesh> meshes;

  int find(const std::string& name) const;  // -1 when absent
  // Global transforms of every node from local ones (parents first).
  std::vector<Eigen::Affine3f> globals(const std::vector<Eigen::Affine3f>& locals) const;
  std::vector<Eigen::Affine3f> rest_locals() const;
  size_t vertex_count() const;
};

// Throws std::runtime_error with assimp's message, or when the file has no skinned mesh.
Character load_character(const std::string& path);
// The character used when none is given: Debian assimp-testmodels' rigged human (BSD-3-Clause).
std::string default_character_path();
