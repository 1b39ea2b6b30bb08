#include "gltf_export.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/cexport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "glb_tidy.h"
#include "scene.h"

namespace {

aiMatrix4x4 to_ai(const Eigen::Affine3f& m) {
  const Eigen::Matrix4f& e = m.matrix();
  return aiMatrix4x4(e(0, 0), e(0, 1), e(0, 2), e(0, 3), e(1, 0), e(1, 1), e(1, 2), e(1, 3), e(2, 0), e(2, 1), e(2, 2),
                     e(2, 3), e(3, 0), e(3, 1), e(3, 2), e(3, 3));
}

struct SceneDeleter {
  void operator()(aiScene* s) const { aiFreeScene(s); }
};

}  // namespace

void export_gltf(Scene& scene, const std::string& model_path, const std::string& out_path, int first_frame,
                 int frame_count, int step) {
  if (frame_count <= 0 || step <= 0) throw std::runtime_error("nothing to export");
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_LBW_MAX_WEIGHTS, 4);
  // The same import as load_character(), so that nodes come in the same order.
  const aiScene* original = importer.ReadFile(model_path, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                              aiProcess_LimitBoneWeights | aiProcess_JoinIdenticalVertices);
  if (!original) throw std::runtime_error("cannot load " + model_path + ": " + importer.GetErrorString());
  aiScene* raw = nullptr;
  aiCopyScene(original, &raw);
  std::unique_ptr<aiScene, SceneDeleter> copy(raw);

  std::vector<aiNode*> nodes;
  std::function<void(aiNode*)> walk = [&](aiNode* n) {
    nodes.push_back(n);
    for (unsigned i = 0; i < n->mNumChildren; ++i) walk(n->mChildren[i]);
  };
  walk(copy->mRootNode);
  const Character& c = scene.character();
  if (nodes.size() != c.nodes.size()) throw std::runtime_error("the model's hierarchy changed between two imports");

  // Animated: the scene root (placement) and every node the retargeter turns (the root's and the spine's joints
  // included, which may be nodes no octocap bone is named after).
  std::vector<int> animated = {0};
  for (int n : scene.retargeter().driven_nodes())
    if (n > 0) animated.push_back(n);

  auto* animation = new aiAnimation();
  animation->mName = aiString("octocap");
  animation->mTicksPerSecond = scene.rate_hz() / step;
  animation->mDuration = frame_count - 1;
  animation->mNumChannels = static_cast<unsigned>(animated.size());
  animation->mChannels = new aiNodeAnim*[animated.size()];
  for (size_t i = 0; i < animated.size(); ++i) {
    auto* ch = new aiNodeAnim();
    ch->mNodeName = nodes[animated[i]]->mName;
    ch->mNumPositionKeys = ch->mNumRotationKeys = ch->mNumScalingKeys = static_cast<unsigned>(frame_count);
    ch->mPositionKeys = new aiVectorKey[frame_count];
    ch->mRotationKeys = new aiQuatKey[frame_count];
    ch->mScalingKeys = new aiVectorKey[frame_count];
    animation->mChannels[i] = ch;
  }
  const auto rest = c.rest_locals();
  for (int k = 0; k < frame_count; ++k) {
    scene.pose(first_frame + k * step);
    const std::vector<Eigen::Affine3f>& g = scene.globals();
    for (size_t i = 0; i < animated.size(); ++i) {
      const int n = animated[i];
      const Eigen::Affine3f local = n == 0 ? Eigen::Affine3f(scene.placement() * rest[0])
                                           : Eigen::Affine3f(g[c.nodes[n].parent].inverse() * g[n]);
      aiVector3D scaling, position;
      aiQuaternion rotation;
      to_ai(local).Decompose(scaling, rotation, position);
      aiNodeAnim* ch = animation->mChannels[i];
      ch->mPositionKeys[k] = aiVectorKey(k, position);
      ch->mRotationKeys[k] = aiQuatKey(k, rotation);
      ch->mScalingKeys[k] = aiVectorKey(k, scaling);
    }
  }
  // The file's own animations are replaced: the export carries octocap's motion only.
  for (unsigned i = 0; i < copy->mNumAnimations; ++i) delete copy->mAnimations[i];
  delete[] copy->mAnimations;
  copy->mAnimations = new aiAnimation*[1]{animation};
  copy->mNumAnimations = 1;

  Assimp::Exporter exporter;
  if (exporter.Export(copy.get(), "glb2", out_path) != aiReturn_SUCCESS)
    throw std::runtime_error("cannot export " + out_path + ": " + exporter.GetErrorString());
  tidy_glb(out_path);
}
