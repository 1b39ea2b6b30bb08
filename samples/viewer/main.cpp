// octocap-viewer: a rigged character driven by a motion (TRC / CSV / BVH), rendered headless to PNG through
// OSMesa, or in a GLFW window. Rendered from a default orbit camera, one calibrated camera, or every calibrated
// camera (per-camera image folders + the character's true joints: input for an end-to-end detector check).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "gltf_export.h"
#include "offscreen.h"
#include "scene.h"
#include "window.h"

namespace fs = std::filesystem;

namespace {

struct Options {
  std::string motion, frames_dir, model, bone_map, calibration, camera, size = "640x480", skinning = "lbs", up = "auto";
  std::string ground_truth, gltf;
  bool all_cameras = false, skeleton = false, no_grid = false, window = false;
  bool subscribe = false;  // live poses over DDS instead of --motion
  unsigned domain = 0, source_id = 0;
  std::string topic = "octocap", qos = "live", dds_security;
  int max_frames = 0, step = 1;
};


struct NamedCamera {
  std::string name;
  ViewCamera view;
};

// rig frame -> calibration world: identity for Y up; Z-up worlds were turned (x,y,z) -> (y,z,x) into the rig.
Eigen::Matrix3d rig_to_world(bool z_up) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  if (z_up) m << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  return m;
}

std::vector<NamedCamera> calibrated_cameras(const Options& o, int width, bool& z_up) {
  const octocap::Calibration calib = octocap::Calibration::load(o.calibration);
  if (o.up == "auto") {
    // The same up-axis decision a session makes from the cameras.
    octocap_session_config_t cfg;
    octocap_session_config_init(&cfg);
    z_up = octocap::Session(cfg, calib).up_axis() == OCTOCAP_UP_Z;
  } else {
    z_up = o.up == "z";
  }
  const uint32_t count = calib.camera_count();
  std::vector<NamedCamera> out;
  for (uint32_t i = 0; i < count; ++i) {
    const octocap_camera_t c = calib.camera(i);
    if (!o.all_cameras && o.camera != c.name) continue;
    Eigen::Matrix3d K;
    for (int k = 0; k < 9; ++k) K(k / 3, k % 3) = c.matrix[k];
    const Eigen::Vector3d r(c.rotation[0], c.rotation[1], c.rotation[2]);
    const Eigen::Matrix3d R = r.norm() > 0 ? Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix()
                                           : Eigen::Matrix3d::Identity();
    // Rendered at the calibration's size, or scaled to the requested width (same aspect, K scaled alike).
    const double s = width > 0 ? static_cast<double>(width) / c.width : 1.0;
    Eigen::Matrix3d Ks = K;
    Ks.topRows<2>() *= s;
    const int w = static_cast<int>(std::lround(c.width * s)), h = static_cast<int>(std::lround(c.height * s));
    out.push_back({c.name, calibrated_camera(Ks, R, Eigen::Vector3d(c.translation[0], c.translation[1], c.translation[2]),
                                             rig_to_world(z_up), w, h)});
  }
  if (out.empty()) throw std::runtime_error(o.calibration + " has no camera named \"" + o.camera + "\"");
  return out;
}

// The character's joints as keypoint columns octocap solve --ground-truth reads (COCO names), world frame.
struct TruthWriter {
  std::ofstream out;
  const Eigen::Matrix3d world;
  static constexpr std::pair<const char*, int> kColumns[] = {
      {"LShoulder", OCTOCAP_JOINT_L_SHOULDER}, {"RShoulder", OCTOCAP_JOINT_R_SHOULDER}, {"LElbow", OCTOCAP_JOINT_L_ELBOW},
      {"RElbow", OCTOCAP_JOINT_R_ELBOW}, {"LWrist", OCTOCAP_JOINT_L_HAND}, {"RWrist", OCTOCAP_JOINT_R_HAND},
      {"LHip", OCTOCAP_JOINT_L_HIP}, {"RHip", OCTOCAP_JOINT_R_HIP}, {"LKnee", OCTOCAP_JOINT_L_KNEE},
      {"RKnee", OCTOCAP_JOINT_R_KNEE}, {"LAnkle", OCTOCAP_JOINT_L_FOOT}, {"RAnkle", OCTOCAP_JOINT_R_FOOT}};
  TruthWriter(const std::string& path, const Eigen::Matrix3d& rig_to_world) : out(path), world(rig_to_world) {
    if (!out) throw std::runtime_error("cannot write " + path);
    out << "frame";
    for (const auto& c : kColumns) out << ',' << c.first << "_x," << c.first << "_y," << c.first << "_z";
    out << '\n';
  }
  void add(int frame, const std::array<Eigen::Vector3f, OCTOCAP_JOINT_COUNT>& joints) {
    out << frame;
    for (const auto& c : kColumns) {
      const Eigen::Vector3d p = world * joints[c.second].cast<double>();
      if (p.allFinite()) out << ',' << p.x() << ',' << p.y() << ',' << p.z();
      else out << ",,,";
    }
    out << '\n';
  }
};

int run(const Options& o) {
  int width = 640, height = 480;
  if (std::sscanf(o.size.c_str(), "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0)
    throw std::runtime_error("--size must be WIDTHxHEIGHT, e.g. 640x480");
  SceneOptions so;
  so.model = o.model;
  so.bone_map = o.bone_map;
  so.skinning = o.skinning == "dqs" ? SkinningMethod::dual_quaternion : SkinningMethod::linear;
  so.skeleton_overlay = o.skeleton;
  std::unique_ptr<octocap::Subscriber> subscriber;
  if (o.subscribe) {
    octocap_subscriber_config_t sc;
    octocap_subscriber_config_init(&sc);
    sc.domain_id = o.domain;
    sc.qos = o.qos == "record" ? OCTOCAP_QOS_RECORD : OCTOCAP_QOS_LIVE;
    sc.source_id = o.source_id;
    std::snprintf(sc.topic, sizeof sc.topic, "%s", o.topic.c_str());
    if (o.dds_security.size() >= sizeof sc.security) throw std::runtime_error("--dds-security: the path is too long");
    std::snprintf(sc.security, sizeof sc.security, "%s", o.dds_security.c_str());
    subscriber = std::make_unique<octocap::Subscriber>(sc);
  }
  Scene scene = o.subscribe ? Scene(subscriber.get(), so) : Scene(o.motion, so);
  std::string mapped;
  for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
    octocap_bone_info_t info;
    octocap_bone_info(static_cast<uint32_t>(b), &info);
    const int node = scene.bone_map()[b];
    mapped += std::string(b ? ", " : "") + info.name + "=" + (node >= 0 ? scene.character().nodes[node].name : "-");
  }
  std::fprintf(stderr, "  bone map: %s\n", mapped.c_str());
  const int frames = scene.live() ? std::max(o.max_frames, 0)
                     : o.max_frames > 0 ? std::min(o.max_frames * o.step, scene.frame_count()) : scene.frame_count();
  std::fprintf(stderr, "octocap-viewer: %s, %zu vertices, %d frames at %.1f Hz\n", scene.character().source.c_str(),
               scene.character().vertex_count(), scene.frame_count(), scene.rate_hz());

  if (o.window) {
    std::unique_ptr<Renderer> renderer;
    run_window("octocap-viewer", width, height, frames, scene.rate_hz() / o.step, o.max_frames,
               [&](const GlApi& gl) { renderer = std::make_unique<Renderer>(gl, scene.meshes()); },
               [&] { renderer.reset(); },
               [&](const WindowView& v, int w, int h) {
                 if (scene.live()) scene.take_live(0);
                 else scene.pose(v.frame * o.step);
                 const ViewCamera cam = orbit_camera(scene.root(), v.distance, v.yaw, v.pitch, 45, w, h);
                 renderer->draw(cam, scene.drawables(), scene.skeletons(), !o.no_grid, scene.floor_y());
               });
    return 0;
  }

  if (!o.gltf.empty()) {
    export_gltf(scene, o.model.empty() ? default_character_path() : o.model, o.gltf, 0, (frames + o.step - 1) / o.step, o.step);
    std::printf("octocap-viewer: wrote %s (%d animation frames)\n", o.gltf.c_str(), (frames + o.step - 1) / o.step);
    if (o.frames_dir.empty()) return 0;
  }
  if (o.frames_dir.empty()) throw std::runtime_error("give --frames DIR (PNG output), --export-gltf FILE or --window");
  bool z_up = false;
  std::vector<NamedCamera> cameras;
  if (!o.calibration.empty()) {
    cameras = calibrated_cameras(o, o.size == "640x480" && o.all_cameras ? 0 : width, z_up);
  } else {
    cameras.push_back({"orbit", ViewCamera{}});  // follows the character, set per frame below
  }
  const bool per_camera_folders = cameras.size() > 1 || o.all_cameras;
  std::unique_ptr<TruthWriter> truth;
  if (!o.ground_truth.empty()) {
    if (fs::path(o.ground_truth).has_parent_path()) fs::create_directories(fs::path(o.ground_truth).parent_path());
    truth = std::make_unique<TruthWriter>(o.ground_truth, rig_to_world(z_up));
  }
  for (const auto& c : cameras) fs::create_directories(per_camera_folders ? fs::path(o.frames_dir) / c.name : fs::path(o.frames_dir));

  std::unique_ptr<OffscreenContext> context;
  std::unique_ptr<Renderer> renderer;
  int written = 0;
  if (scene.live() && frames <= 0) throw std::runtime_error("with --subscribe and --frames, give --max-frames N");
  for (int f = 0, out_index = 0; f < frames; f += scene.live() ? 1 : o.step, ++out_index) {
    if (!scene.live()) scene.pose(f);
    else if (!scene.take_live(10000)) throw std::runtime_error("no pose arrived within 10 s (is a publisher running?)");
    if (truth) truth->add(out_index, scene.character_joints());
    if (o.calibration.empty()) {
      const Eigen::Vector3f target(scene.root().x(), scene.floor_y() + 1.0f, scene.root().z());
      cameras[0].view = orbit_camera(target, 3.5f, 0.0f, 0.15f, 45, width, height);
    }
    for (const auto& c : cameras) {
      if (!context || context->width() != c.view.width || context->height() != c.view.height) {
        renderer.reset();
        context = std::make_unique<OffscreenContext>(c.view.width, c.view.height);
        renderer = std::make_unique<Renderer>(context->gl(), scene.meshes());
        if (written == 0) std::fprintf(stderr, "  rendering with %s\n", context->renderer_name().c_str());
      }
      renderer->draw(c.view, scene.drawables(), scene.skeletons(), !o.no_grid, scene.floor_y());
      char name[64];
      std::snprintf(name, sizeof name, "frame_%06d.png", out_index);
      const fs::path dir = per_camera_folders ? fs::path(o.frames_dir) / c.name : fs::path(o.frames_dir);
      write_png((dir / name).string(), context->read_rgb(), c.view.width, c.view.height);
      ++written;
    }
  }
  std::printf("octocap-viewer: wrote %d PNG files to %s\n", written, o.frames_dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"octocap-viewer: a skinned character driven by octocap motion, rendered to PNG or a window"};
  Options o;
  auto* motion = app.add_option("--motion", o.motion, "Motion: TRC or CSV from octocap solve, or a BVH")->check(CLI::ExistingFile);
  auto* live = app.add_flag("--subscribe", o.subscribe, "Live poses over DDS from octocap (a session or octocap solve --publish); one character per person");
  motion->excludes(live);
  app.add_option("--domain", o.domain, "With --subscribe: DDS domain id")->capture_default_str();
  app.add_option("--topic", o.topic, "With --subscribe: topic base name")->capture_default_str();
  app.add_option("--qos", o.qos, "With --subscribe: live or record (as the publisher)")->check(CLI::IsMember({"live", "record"}))->capture_default_str();
  app.add_option("--source-id", o.source_id, "With --subscribe: only this rig (0: any)")->capture_default_str();
  app.add_option("--dds-security", o.dds_security, "With --subscribe: DDS Security identity folder, KEYSTORE/NAME (octocap security add ... --role viewer)");
  app.add_option("--frames", o.frames_dir, "Write one PNG per motion frame here (frame_000000.png, ...)");
  app.add_option("--model", o.model, "Rigged character (glTF/GLB, FBX, COLLADA, X, ...); default: assimp's rigged human")->check(CLI::ExistingFile);
  app.add_option("--bone-map", o.bone_map, "JSON {\"octocap bone\": \"model node\"} overriding the name heuristics")->check(CLI::ExistingFile);
  app.add_option("--calibration", o.calibration, "Render from calibrated cameras (anipose / Pose2Sim TOML)")->check(CLI::ExistingFile);
  app.add_option("--camera", o.camera, "With --calibration: the camera to render from");
  app.add_flag("--all-cameras", o.all_cameras, "With --calibration: every camera, into DIR/<camera>/");
  app.add_option("--export-gltf", o.gltf, "Write the character with the motion as glTF 2.0 binary (.glb)");
  app.add_option("--ground-truth", o.ground_truth, "Also write the character's true joints per frame (CSV, world frame)");
  app.add_option("--size", o.size, "Image size WxH (calibrated cameras: the width scales the calibration's size)")->capture_default_str();
  app.add_option("--skinning", o.skinning, "lbs (linear blend) or dqs (dual quaternion)")->check(CLI::IsMember({"lbs", "dqs"}))->capture_default_str();
  app.add_option("--up", o.up, "Calibration world up axis")->check(CLI::IsMember({"auto", "y", "z"}))->capture_default_str();
  app.add_flag("--skeleton", o.skeleton, "Draw the motion's skeleton over the mesh");
  app.add_flag("--no-grid", o.no_grid, "No floor grid");
  app.add_flag("--window", o.window, "Open a window (GLFW) instead of writing PNG files");
  app.add_option("--max-frames", o.max_frames, "Render at most this many frames (0: all)")->capture_default_str();
  app.add_option("--step", o.step, "Render every N-th motion frame")->check(CLI::PositiveNumber)->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (o.motion.empty() && !o.subscribe) {
    std::fprintf(stderr, "octocap-viewer: give --motion FILE or --subscribe\n");
    return 2;
  }
  if (!o.calibration.empty() && o.camera.empty() && !o.all_cameras) {
    std::fprintf(stderr, "octocap-viewer: with --calibration give --camera NAME or --all-cameras\n");
    return 2;
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "octocap-viewer: error: %s\n", e.what());
    return 1;
  }
}
