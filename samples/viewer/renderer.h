// Draws a skinned character, a floor grid and a skeleton overlay with OpenGL 3.3 core (OSMesa or GLFW context).
// The world is octocap's rig frame (Y up, metres).
#pragma once
#include <Eigen/Geometry>
#include <utility>
#include <vector>

#include "gl_api.h"
#include "skinning.h"

struct ViewCamera {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();        // world (rig frame) -> GL eye
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  int width = 640, height = 480;
};

// A pinhole camera as OpenCV describes it (K, world->camera R, t; pixels y down), looking at the rig-frame world
// through `rig_to_world` (identity for a Y-up calibration). Distortion is not rendered.
ViewCamera calibrated_camera(const Eigen::Matrix3d& K, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                             const Eigen::Matrix3d& rig_to_world, int width, int height);
// Looking at `target` from `distance` metres, turned `yaw` about Y from the character's front (+Z), `pitch` down.
ViewCamera orbit_camera(const Eigen::Vector3f& target, float distance, float yaw, float pitch, float fov_deg,
                        int width, int height);

using Segment = std::pair<Eigen::Vector3f, Eigen::Vector3f>;

// One character to draw: its skinned meshes (model space, the renderer's topology) and where they stand.
struct Drawable {
  const std::vector<SkinnedVertices>* meshes = nullptr;
  Eigen::Affine3f model_to_world = Eigen::Affine3f::Identity();
};

class Renderer {
 public:
  // Needs a current OpenGL 3.3 core context; throws std::runtime_error with the shader log on failure.
  Renderer(const GlApi& gl, const std::vector<const SkinnedMesh*>& meshes);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // model_to_world places the skinned (model space) vertices; skeleton segments and the grid are in world space.
  void draw(const ViewCamera& camera, const std::vector<SkinnedVertices>& meshes, const Eigen::Affine3f& model_to_world,
            const std::vector<Segment>& skeleton, bool grid, float floor_y);
  // Several characters of the same model (one per person), each in a colour of its own.
  void draw(const ViewCamera& camera, const std::vector<Drawable>& characters, const std::vector<Segment>& skeleton,
            bool grid, float floor_y);

 private:
  void upload_lines(const std::vector<float>& vertices);
  const GlApi& gl_;
  unsigned mesh_program_ = 0, line_program_ = 0;
  std::vector<unsigned> vaos_, vbos_, ebos_;
  std::vector<size_t> index_counts_;
  unsigned line_vao_ = 0, line_vbo_ = 0;
};
