// Skinning and rendering benchmark: ms per frame of CPU skinning (linear blend vs dual quaternion) for 10k, 50k
// and 200k vertices (the default character's mesh repeated, its real weights and bones, a real CMU pose), and of an
// offscreen OSMesa render + PNG write at 640x480.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "character.h"
#include "offscreen.h"
#include "scene.h"
#include "skinning.h"

using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

SkinnedMesh repeated(const Character& c, size_t vertices) {
  SkinnedMesh out;
  while (out.positions.size() < vertices)
    for (const SkinnedMesh& m : c.meshes)
      for (size_t v = 0; v < m.positions.size() && out.positions.size() < vertices; ++v) {
        out.positions.push_back(m.positions[v]);
        out.normals.push_back(m.normals[v]);
        out.bone_ids.push_back(m.bone_ids[v]);
        out.weights.push_back(m.weights[v]);
      }
  return out;
}

}  // namespace

int main() {
  const std::string motion = "/usr/share/assimp/models/BVH/01_01.bvh";
  Scene scene(motion, SceneOptions{});
  const Character& c = scene.character();
  octocap_motion_t* m = nullptr;
  octocap_motion_open(motion.c_str(), &m);
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  uint32_t n = 0;
  octocap_frame_t* frame = nullptr;
  if (octocap_motion_get_frame(m, 300, &frame) != OCTOCAP_OK ||
      octocap_frame_get_bones(frame, 0, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &n) != OCTOCAP_OK) {
    std::fprintf(stderr, "bench_viewer: %s: %s\n", motion.c_str(), octocap_last_error());
    return 1;
  }
  octocap_frame_release(frame);
  octocap_motion_destroy(m);
  const Retargeter retarget(c, scene.bone_map());
  const auto skin = skin_matrices(c, retarget.pose(bones));

  std::printf("# octocap-viewer benchmark (one core)\n\n## CPU skinning, ms per frame\n\n");
  std::printf("| vertices | linear blend | dual quaternion |\n|---|---|---|\n");
  for (size_t count : {10000u, 50000u, 200000u}) {
    const SkinnedMesh mesh = repeated(c, count);
    SkinnedVertices out;
    std::printf("| %zu |", count);
    for (SkinningMethod method : {SkinningMethod::linear, SkinningMethod::dual_quaternion}) {
      skin_mesh(mesh, skin, Eigen::Affine3f::Identity(), method, out);  // warm-up
      const int runs = count > 100000 ? 10 : 40;
      const auto t0 = Clock::now();
      for (int r = 0; r < runs; ++r) skin_mesh(mesh, skin, Eigen::Affine3f::Identity(), method, out);
      std::printf(" %.2f |", ms_since(t0) / runs);
    }
    std::printf("\n");
  }

  std::printf("\n## Offscreen render (OSMesa) of the default character, 640x480, ms per frame\n\n");
  OffscreenContext context(640, 480);
  Renderer renderer(context.gl(), scene.meshes());
  const auto dir = std::filesystem::temp_directory_path() / "octocap_bench_viewer";
  std::filesystem::create_directories(dir);
  double pose_ms = 0, draw_ms = 0, png_ms = 0;
  const int frames = 40;
  for (int f = 0; f < frames; ++f) {
    auto t0 = Clock::now();
    scene.pose(f * 10);
    pose_ms += ms_since(t0);
    t0 = Clock::now();
    const ViewCamera cam = orbit_camera(scene.root(), 3.5f, 0, 0.15f, 45, 640, 480);
    renderer.draw(cam, scene.vertices(), scene.placement(), scene.skeleton(), true, scene.floor_y());
    const auto rgb = context.read_rgb();
    draw_ms += ms_since(t0);
    t0 = Clock::now();
    write_png((dir / ("frame_" + std::to_string(f) + ".png")).string(), rgb, 640, 480);
    png_ms += ms_since(t0);
  }
  std::filesystem::remove_all(dir);
  std::printf("| retarget + skin (%zu vertices) | draw + read back (%s) | PNG write | total | frames/s |\n|---|---|---|---|---|\n",
              c.vertex_count(), context.renderer_name().c_str());
  std::printf("| %.2f | %.2f | %.2f | %.2f | %.0f |\n", pose_ms / frames, draw_ms / frames, png_ms / frames,
              (pose_ms + draw_ms + png_ms) / frames, 1000.0 * frames / (pose_ms + draw_ms + png_ms));
  return 0;
}
