#include "character.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <algorithm>
#include <functional>
#include <stdexcept>

namespace {

Eigen::Affine3f to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4f e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return Eigen::Affine3f(e);
}

// Keeps the 4 largest weights and renormalises them (GPU-style skinning takes 4).
void add_weight(std::array<uint16_t, 4>& ids, std::array<float, 4>& w, uint16_t bone, float weight) {
  const auto smallest = std::min_element(w.begin(), w.end());
  if (weight <= *smallest) return;
  ids[static_cast<size_t>(smallest - w.begin())] = bone;
  *smallest = weight;
}

}  // namespace

int Character::find(const std::string& name) const {
  for (size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].name == name) return static_cast<int>(i);
  return -1;
}

std::vector<Eigen::Affine3f> Character::rest_locals() const {
  std::vector<Eigen::Affine3f> l;
  for (const auto& n : nodes) l.push_back(n.local);
  return l;
}

std::vector<Eigen::Affine3f> Character::globals(const std::vector<Eigen::Affine3f>& locals) const {
  std::vector<Eigen::Affine3f> g(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) g[i] = nodes[i].parent < 0 ? locals[i] : g[nodes[i].parent] * locals[i];
  return g;
}

size_t Character::vertex_count() const {
  size_t n = 0;
  for (const auto& m : meshes) n += m.positions.size();
  return n;
}

std::string default_character_path() { return "/usr/share/assimp/models/X/BCN_Epileptic.X"; }

Character load_character(const std::string& path) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_LBW_MAX_WEIGHTS, 4);
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                     aiProcess_LimitBoneWeights | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode) throw std::runtime_error("cannot load " + path + ": " + importer.GetErrorString());
  Character c;
  c.source = path;
  std::function<void(const aiNode*, int)> walk = [&](const aiNode* n, int parent) {
    const int me = static_cast<int>(c.nodes.size());
    c.nodes.push_back({n->mName.C_Str(), parent, to_eigen(n->mTransformation)});
    for (unsigned i = 0; i < n->mNumChildren; ++i) walk(n->mChildren[i], me);
  };
  walk(scene->mRootNode, -1);

  for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
    const aiMesh* am = scene->mMeshes[mi];
    if (!am->HasBones() || !am->HasPositions()) continue;
    SkinnedMesh m;
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      m.positions.emplace_back(am->mVertices[v].x, am->mVertices[v].y, am->mVertices[v].z);
      m.normals.push_back(am->HasNormals() ? Eigen::Vector3f(am->mNormals[v].x, am->mNormals[v].y, am->mNormals[v].z)
                                           : Eigen::Vector3f::UnitY());
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f)
      if (am->mFaces[f].mNumIndices == 3)
        for (unsigned k = 0; k < 3; ++k) m.indices.push_back(am->mFaces[f].mIndices[k]);
    m.bone_ids.assign(am->mNumVertices, {0, 0, 0, 0});
    m.weights.assign(am->mNumVertices, {0, 0, 0, 0});
    for (unsigned b = 0; b < am->mNumBones; ++b) {
      const aiBone* ab = am->mBones[b];
      const int node = c.find(ab->mName.C_Str());
      if (node < 0) continue;
      // Bones are shared across meshes by node.
      int index = -1;
      for (size_t i = 0; i < c.bones.size(); ++i)
        if (c.bones[i].node == node) index = static_cast<int>(i);
      if (index < 0) {
        index = static_cast<int>(c.bones.size());
        c.bones.push_back({node, to_eigen(ab->mOffsetMatrix)});
      }
      for (unsigned w = 0; w < ab->mNumWeights; ++w)
        if (ab->mWeights[w].mVertexId < am->mNumVertices)
          add_weight(m.bone_ids[ab->mWeights[w].mVertexId], m.weights[ab->mWeights[w].mVertexId],
                     static_cast<uint16_t>(index), ab->mWeights[w].mWeight);
    }
    for (auto& w : m.weights) {
      const float sum = w[0] + w[1] + w[2] + w[3];
      if (sum > 0)
        for (float& x : w) x /= sum;
    }
    c.meshes.push_back(std::move(m));
  }
  if (c.meshes.empty()) throw std::runtime_error(path + " has no skinned mesh (a rigged character is needed)");
  return c;
}
