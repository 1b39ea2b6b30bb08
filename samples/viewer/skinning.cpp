#include "skinning.h"

std::vector<Eigen::Affine3f> skin_matrices(const Character& c, const std::vector<Eigen::Affine3f>& posed_globals) {
  std::vector<Eigen::Affine3f> m(c.bones.size());
  for (size_t b = 0; b < c.bones.size(); ++b) m[b] = posed_globals[c.bones[b].node] * c.bones[b].offset;
  return m;
}

namespace {

// A rigid transform as a unit dual quaternion: real part the rotation, dual part 0.5 * t * real.
struct DualQuat {
  Eigen::Vector4f real, dual;  // (x, y, z, w)
};

DualQuat to_dual(const Eigen::Affine3f& m) {
  Eigen::Quaternionf q(m.linear());
  q.normalize();
  const Eigen::Vector3f t = m.translation();
  const Eigen::Quaternionf tq(0, t.x(), t.y(), t.z());
  const Eigen::Quaternionf d = tq * q;
  return {Eigen::Vector4f(q.x(), q.y(), q.z(), q.w()), 0.5f * Eigen::Vector4f(d.x(), d.y(), d.z(), d.w())};
}

void skin_linear(const SkinnedMesh& mesh, const std::vector<Eigen::Affine3f>& bones, const Eigen::Affine3f& unskinned,
                 SkinnedVertices& out) {
  const size_t n = mesh.positions.size();
  for (size_t v = 0; v < n; ++v) {
    const auto& w = mesh.weights[v];
    const auto& id = mesh.bone_ids[v];
    // Blend the 3x4 matrices, then transform once: 48 multiply-adds per vertex, vectorised by Eigen.
    Eigen::Matrix<float, 3, 4> m = Eigen::Matrix<float, 3, 4>::Zero();
    for (int k = 0; k < 4; ++k)
      if (w[k] > 0) m.noalias() += w[k] * bones[id[k]].matrix().topRows<3>();
    if (w[0] + w[1] + w[2] + w[3] <= 0) m = unskinned.matrix().topRows<3>();
    out.positions[v] = m.leftCols<3>() * mesh.positions[v] + m.col(3);
    out.normals[v] = (m.leftCols<3>() * mesh.normals[v]).normalized();
  }
}

void skin_dual(const SkinnedMesh& mesh, const std::vector<Eigen::Affine3f>& bones, const Eigen::Affine3f& unskinned,
               SkinnedVertices& out) {
  std::vector<DualQuat> dq(bones.size());
  for (size_t b = 0; b < bones.size(); ++b) dq[b] = to_dual(bones[b]);
  const DualQuat fallback = to_dual(unskinned);
  const size_t n = mesh.positions.size();
  for (size_t v = 0; v < n; ++v) {
    const auto& w = mesh.weights[v];
    const auto& id = mesh.bone_ids[v];
    Eigen::Vector4f real = Eigen::Vector4f::Zero(), dual = Eigen::Vector4f::Zero();
    const Eigen::Vector4f pivot = dq[id[0]].real;
    for (int k = 0; k < 4; ++k) {
      if (w[k] <= 0) continue;
      // Antipodal quaternions are the same rotation: blend them on the pivot's hemisphere.
      const float s = dq[id[k]].real.dot(pivot) < 0 ? -w[k] : w[k];
      real += s * dq[id[k]].real;
      dual += s * dq[id[k]].dual;
    }
    if (w[0] + w[1] + w[2] + w[3] <= 0) real = fallback.real, dual = fallback.dual;
    const float norm = real.norm();
    real /= norm;
    dual /= norm;
    const Eigen::Quaternionf q(real.w(), real.x(), real.y(), real.z());
    const Eigen::Quaternionf d(dual.w(), dual.x(), dual.y(), dual.z());
    const Eigen::Quaternionf t = d * q.conjugate();  // = 0.5 * translation
    out.positions[v] = q * mesh.positions[v] + 2.0f * t.vec();
    out.normals[v] = q * mesh.normals[v];
  }
}

}  // namespace

void skin_mesh(const SkinnedMesh& mesh, const std::vector<Eigen::Affine3f>& bone_matrices,
               const Eigen::Affine3f& unskinned, SkinningMethod method, SkinnedVertices& out) {
  out.positions.resize(mesh.positions.size());
  out.normals.resize(mesh.normals.size());
  if (method == SkinningMethod::linear) skin_linear(mesh, bone_matrices, unskinned, out);
  else skin_dual(mesh, bone_matrices, unskinned, out);
}
