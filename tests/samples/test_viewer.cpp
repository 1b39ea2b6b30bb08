// The skinned character: skinning against geometry, retargeting onto a model whose rest pose differs from the
// template, the headless renderer, the viewer's command line (PNG frames, calibrated views, window under Xvfb).
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_exception.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <functional>
#include <map>

#include "character.h"
#include "gltf_export.h"
#include "offscreen.h"
#include "retarget.h"
#include "scene.h"
#include "skinning.h"
#include "support/loopback_dds.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

using Catch::Approx;
using Catch::Matchers::ContainsSubstring;

namespace {

const std::string kSample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";
const std::string kCmu = "/usr/share/assimp/models/BVH/01_01.bvh";

// A two-bone limb along +X: upper bone at the origin, lower bone at the elbow (1, 0, 0).
Character two_bone_limb(const std::vector<Eigen::Vector3f>& vertices, const std::vector<std::array<float, 2>>& weights) {
  Character c;
  c.nodes.push_back({"upper", -1, Eigen::Affine3f::Identity()});
  Eigen::Affine3f elbow = Eigen::Affine3f::Identity();
  elbow.translate(Eigen::Vector3f(1, 0, 0));
  c.nodes.push_back({"lower", 0, elbow});
  c.bones.push_back({0, Eigen::Affine3f::Identity()});
  c.bones.push_back({1, elbow.inverse()});
  SkinnedMesh m;
  for (size_t i = 0; i < vertices.size(); ++i) {
    m.positions.push_back(vertices[i]);
    m.normals.push_back(Eigen::Vector3f::UnitY());
    m.bone_ids.push_back({0, 1, 0, 0});
    m.weights.push_back({weights[i][0], weights[i][1], 0, 0});
  }
  c.meshes.push_back(m);
  return c;
}

SkinnedVertices skin(const Character& c, const Eigen::Quaternionf& elbow_rotation, SkinningMethod method) {
  std::vector<Eigen::Affine3f> locals = c.rest_locals();
  locals[1].rotate(elbow_rotation);
  SkinnedVertices out;
  skin_mesh(c.meshes[0], skin_matrices(c, c.globals(locals)), Eigen::Affine3f::Identity(), method, out);
  return out;
}

// The sample's first camera at half its size, and plain pinhole projection through it (independent of the GL matrices).
struct SampleCamera {
  Eigen::Matrix3d Ks, R;
  Eigen::Vector3d t;
  int w = 0, h = 0;
  Eigen::Vector2d project(const Eigen::Vector3f& p) const {
    const Eigen::Vector3d c = R * p.cast<double>() + t;
    return {Ks(0, 0) * c.x() / c.z() + Ks(0, 2), Ks(1, 1) * c.y() / c.z() + Ks(1, 2)};
  }
};

SampleCamera sample_camera() {
  octocap_calibration_t* calib = nullptr;
  REQUIRE(octocap_calibration_load((kSample + "/calibration.toml").c_str(), &calib) == OCTOCAP_OK);
  octocap_camera_t cam;
  REQUIRE(octocap_calibration_get_camera(calib, 0, &cam) == OCTOCAP_OK);
  octocap_calibration_destroy(calib);
  SampleCamera s;
  for (int k = 0; k < 9; ++k) s.Ks(k / 3, k % 3) = cam.matrix[k];
  s.Ks.topRows<2>() *= 0.5;
  const Eigen::Vector3d r(cam.rotation[0], cam.rotation[1], cam.rotation[2]);
  s.R = Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix();
  s.t = Eigen::Vector3d(cam.translation[0], cam.translation[1], cam.translation[2]);
  s.w = static_cast<int>(cam.width) / 2, s.h = static_cast<int>(cam.height) / 2;
  return s;
}

void check_near(const Eigen::Vector3f& got, const Eigen::Vector3f& want, float tolerance = 1e-5f) {
  INFO("got " << got.transpose() << ", want " << want.transpose());
  CHECK((got - want).norm() < tolerance);
}

}  // namespace

TEST_CASE("skinning a two-bone limb bent 90 degrees puts vertices where geometry says") {
  const Character limb = two_bone_limb({{0.5f, 0, 0}, {1.5f, 0, 0}, {1.5f, 0.1f, 0}, {1, 0, 0}, {1, 0.2f, 0}},
                                       {{1, 0}, {0, 1}, {0, 1}, {0.5f, 0.5f}, {0.5f, 0.5f}});
  const Eigen::Quaternionf bend(Eigen::AngleAxisf(static_cast<float>(M_PI / 2), Eigen::Vector3f::UnitZ()));
  for (SkinningMethod method : {SkinningMethod::linear, SkinningMethod::dual_quaternion}) {
    const SkinnedVertices v = skin(limb, bend, method);
    check_near(v.positions[0], {0.5f, 0, 0});      // on the upper bone: does not move
    check_near(v.positions[1], {1, 0.5f, 0});      // on the lower bone: turned about the elbow
    check_near(v.positions[2], {0.9f, 0.5f, 0});   // off its axis: the offset turns too
    check_near(v.positions[3], {1, 0, 0});         // at the pivot, shared: stays
    check_near(v.normals[2], {-1, 0, 0});
  }
  // Shared off-axis vertex: linear blending averages the two positions (it cuts the corner, 0.141 from the
  // elbow instead of 0.2); dual quaternions turn it by half the angle and keep its distance.
  const SkinnedVertices lbs = skin(limb, bend, SkinningMethod::linear);
  check_near(lbs.positions[4], {0.9f, 0.1f, 0});
  const SkinnedVertices dqs = skin(limb, bend, SkinningMethod::dual_quaternion);
  const float s = std::sqrt(0.5f);
  check_near(dqs.positions[4], {1 - 0.2f * s, 0.2f * s, 0});
  CHECK((dqs.positions[4] - Eigen::Vector3f(1, 0, 0)).norm() == Approx(0.2f).margin(1e-5));
}

TEST_CASE("a 180-degree twist collapses linear blending (candy wrapper) but not dual quaternions") {
  const Character limb = two_bone_limb({{1, 0.2f, 0}}, {{0.5f, 0.5f}});
  const Eigen::Quaternionf twist(Eigen::AngleAxisf(static_cast<float>(M_PI * 0.999), Eigen::Vector3f::UnitX()));
  const float lbs_radius = std::hypot(skin(limb, twist, SkinningMethod::linear).positions[0].y(),
                                      skin(limb, twist, SkinningMethod::linear).positions[0].z());
  const Eigen::Vector3f d = skin(limb, twist, SkinningMethod::dual_quaternion).positions[0];
  CHECK(lbs_radius < 0.01f);
  CHECK(std::hypot(d.y(), d.z()) == Approx(0.2f).margin(1e-4));
}

TEST_CASE("retargeting onto a model in an A-pose, turned and with odd rest frames, reproduces joint directions") {
  // A humanoid with Mixamo names, arms 45 degrees down (A-pose), facing -X instead of +Z, every node with a
  // random rest orientation: none of it may change the bone directions the motion asks for.
  const std::vector<std::pair<const char*, const char*>> hierarchy = {
      {"mixamorig:Hips", ""}, {"mixamorig:Spine", "mixamorig:Hips"}, {"mixamorig:Neck", "mixamorig:Spine"},
      {"mixamorig:Head", "mixamorig:Neck"}, {"mixamorig:LeftShoulder", "mixamorig:Neck"},
      {"mixamorig:LeftArm", "mixamorig:LeftShoulder"}, {"mixamorig:LeftForeArm", "mixamorig:LeftArm"},
      {"mixamorig:LeftHand", "mixamorig:LeftForeArm"}, {"mixamorig:RightShoulder", "mixamorig:Neck"},
      {"mixamorig:RightArm", "mixamorig:RightShoulder"}, {"mixamorig:RightForeArm", "mixamorig:RightArm"},
      {"mixamorig:RightHand", "mixamorig:RightForeArm"}, {"mixamorig:LeftUpLeg", "mixamorig:Hips"},
      {"mixamorig:LeftLeg", "mixamorig:LeftUpLeg"}, {"mixamorig:LeftFoot", "mixamorig:LeftLeg"},
      {"mixamorig:RightUpLeg", "mixamorig:Hips"}, {"mixamorig:RightLeg", "mixamorig:RightUpLeg"},
      {"mixamorig:RightFoot", "mixamorig:RightLeg"}, {"mixamorig:LeftToeBase", "mixamorig:LeftFoot"},
      {"mixamorig:RightToeBase", "mixamorig:RightFoot"}, {"mixamorig:LeftHandMiddle1", "mixamorig:LeftHand"},
      {"mixamorig:RightHandMiddle1", "mixamorig:RightHand"}};
  const float a = std::sqrt(0.5f);
  // Rest positions in the rig's axes (left +X, up +Y), then turned to face -X.
  const std::vector<Eigen::Vector3f> rest = {
      {0, 1, 0}, {0, 1.1f, 0}, {0, 1.5f, 0}, {0, 1.7f, 0}, {0.05f, 1.48f, 0}, {0.18f, 1.45f, 0},
      {0.18f + 0.28f * a, 1.45f - 0.28f * a, 0}, {0.18f + 0.53f * a, 1.45f - 0.53f * a, 0},
      {-0.05f, 1.48f, 0}, {-0.18f, 1.45f, 0}, {-0.18f - 0.28f * a, 1.45f - 0.28f * a, 0},
      {-0.18f - 0.53f * a, 1.45f - 0.53f * a, 0}, {0.1f, 0.95f, 0}, {0.1f, 0.5f, 0.02f}, {0.1f, 0.08f, 0},
      {-0.1f, 0.95f, 0}, {-0.1f, 0.5f, 0.02f}, {-0.1f, 0.08f, 0}, {0.1f, 0.02f, 0.14f}, {-0.1f, 0.02f, 0.14f},
      {0.18f + 0.62f * a, 1.45f - 0.62f * a, 0}, {-0.18f - 0.62f * a, 1.45f - 0.62f * a, 0}};  // the hands' knuckles
  const Eigen::Matrix3f facing = Eigen::AngleAxisf(static_cast<float>(-M_PI / 2), Eigen::Vector3f::UnitY()).toRotationMatrix();
  std::mt19937 rng(3);
  std::vector<Eigen::Affine3f> globals;
  Character c;
  c.source = "synthetic";
  for (size_t i = 0; i < hierarchy.size(); ++i) {
    Eigen::Affine3f g = Eigen::Affine3f::Identity();
    g.linear() = Eigen::Quaternionf::UnitRandom().toRotationMatrix();  // odd rest frames
    (void)rng;
    g.translation() = facing * rest[i];
    globals.push_back(g);
    const int parent = *hierarchy[i].second ? c.find(hierarchy[i].second) : -1;
    c.nodes.push_back({hierarchy[i].first, parent, parent < 0 ? g : Eigen::Affine3f(globals[parent].inverse() * g)});
  }
  const BoneMap map = find_bone_map(c);
  REQUIRE(missing_bones(map).empty());
  CHECK(c.nodes[map[OCTOCAP_BONE_L_LOWER_LEG]].name == "mixamorig:LeftLeg");
  CHECK(c.nodes[map[OCTOCAP_BONE_L_UPPER_LEG]].name == "mixamorig:LeftUpLeg");
  CHECK(c.nodes[map[OCTOCAP_BONE_R_SHOULDER]].name == "mixamorig:RightShoulder");
  const Retargeter retarget(c, map);

  octocap_motion_t* motion = nullptr;
  REQUIRE(octocap_motion_open(kCmu.c_str(), &motion) == OCTOCAP_OK);
  double worst = 0;
  for (uint32_t f = 0; f < 2000; f += 97) {
    octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
    octocap_joint_t joints[OCTOCAP_JOINT_COUNT];
    uint32_t n = 0;
    REQUIRE(octocap_motion_bones(motion, f, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
    REQUIRE(octocap_motion_joints(motion, f, joints, OCTOCAP_JOINT_COUNT, &n) == OCTOCAP_OK);
    const auto posed = retarget.pose(bones);
    for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
      octocap_bone_info_t info;
      octocap_bone_info(static_cast<uint32_t>(b), &info);
      if (b == OCTOCAP_BONE_ROOT) continue;  // the model's hips sit between its thighs, not at the left one
      const auto& h = joints[info.head_joint].position;
      const auto& t = joints[info.tail_joint].position;
      const Eigen::Vector3f want = Eigen::Vector3f(t[0] - h[0], t[1] - h[1], t[2] - h[2]).normalized();
      const Eigen::Vector3f got = (retarget.model_to_rig() * (retarget.bone_tail(posed, b) - retarget.bone_head(posed, b))).normalized();
      const double angle = std::acos(std::clamp(static_cast<double>(want.dot(got)), -1.0, 1.0)) * 180 / M_PI;
      INFO("frame " << f << " bone " << info.name << ": " << angle << " degrees off");
      CHECK(angle < 0.5);
      worst = std::max(worst, angle);
    }
  }
  octocap_motion_destroy(motion);
  CHECK(worst < 0.5);
}

TEST_CASE("the headless renderer draws the character around its own joints, and a new pose changes the picture") {
  const SampleCamera cam = sample_camera();
  const int w = cam.w, h = cam.h;
  const Eigen::Matrix3d &Ks = cam.Ks, &R = cam.R;
  const Eigen::Vector3d& t = cam.t;

  Scene scene(kSample + "/ground_truth.csv", SceneOptions{});  // the sample world is Y up
  OffscreenContext context(w, h);
  Renderer renderer(context.gl(), scene.meshes());
  const ViewCamera view = calibrated_camera(Ks, R, t, Eigen::Matrix3d::Identity(), w, h);
  auto render = [&](int frame, std::array<Eigen::Vector3f, OCTOCAP_JOINT_COUNT>& joints) {
    scene.pose(frame);
    joints = scene.character_joints();
    renderer.draw(view, scene.vertices(), scene.placement(), {}, false, scene.floor_y());
    return context.read_rgb();
  };
  std::array<Eigen::Vector3f, OCTOCAP_JOINT_COUNT> joints0, joints1;
  const std::vector<uint8_t> first = render(0, joints0), later = render(45, joints1);

  // Silhouette: pixels that are not the background colour.
  int x0 = w, y0 = h, x1 = -1, y1 = -1, body = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = &first[(static_cast<size_t>(y) * w + x) * 3];
      if (std::abs(p[0] - 237) + std::abs(p[1] - 240) + std::abs(p[2] - 245) < 6) continue;
      ++body;
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  REQUIRE(body > 500);
  // The character's joints projected by plain pinhole arithmetic, independent of the GL matrices.
  for (int k = 0; k < OCTOCAP_JOINT_COUNT; ++k) {
    const Eigen::Vector3f& j = joints0[k];
    if (k == OCTOCAP_JOINT_R_HEEL || k == OCTOCAP_JOINT_L_HEEL) continue;  // no model bone ends at a heel
    REQUIRE(j.allFinite());
    const Eigen::Vector2d uv = cam.project(j);
    const double u = uv.x(), v = uv.y();
    INFO("joint at " << u << ", " << v << "; silhouette box " << x0 << ".." << x1 << " x " << y0 << ".." << y1);
    CHECK(u >= x0 - 2);
    CHECK(u <= x1 + 2);
    CHECK(v >= y0 - 2);
    CHECK(v <= y1 + 2);
  }
  size_t changed = 0;
  for (size_t i = 0; i < first.size(); i += 3) changed += first[i] != later[i] || first[i + 1] != later[i + 1];
  CHECK(changed > static_cast<size_t>(body) / 5);
  CHECK((joints0[OCTOCAP_JOINT_L_HAND] - joints1[OCTOCAP_JOINT_L_HAND]).norm() > 0.05f);
}

TEST_CASE("the default character with a turned head, then flexed feet, changes the picture there and only there") {
  const SampleCamera cam = sample_camera();
  Scene scene(kSample + "/ground_truth.csv", SceneOptions{});
  OffscreenContext context(cam.w, cam.h);
  Renderer renderer(context.gl(), scene.meshes());
  const ViewCamera view = calibrated_camera(cam.Ks, cam.R, cam.t, Eigen::Matrix3d::Identity(), cam.w, cam.h);
  octocap_motion_t* motion = nullptr;
  REQUIRE(octocap_motion_open((kSample + "/ground_truth.csv").c_str(), &motion) == OCTOCAP_OK);
  std::array<octocap_bone_pose_t, OCTOCAP_BONE_COUNT> bones{};
  uint32_t n = 0;
  REQUIRE(octocap_motion_bones(motion, 0, OCTOCAP_FRAME_RIG, bones.data(), OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
  octocap_motion_destroy(motion);
  REQUIRE(bones[OCTOCAP_BONE_HEAD].valid);
  REQUIRE(bones[OCTOCAP_BONE_R_FOOT].valid);
  REQUIRE(bones[OCTOCAP_BONE_L_FOOT].valid);
  auto render = [&](const std::array<octocap_bone_pose_t, OCTOCAP_BONE_COUNT>& pose) {
    scene.pose(pose.data());
    renderer.draw(view, scene.vertices(), scene.placement(), {}, false, scene.floor_y());
    return context.read_rgb();
  };
  // A bone turned by `q` in the world (rig frame), everything else as it was.
  auto turned = [&](std::initializer_list<int> which, const Eigen::Quaterniond& q) {
    std::array<octocap_bone_pose_t, OCTOCAP_BONE_COUNT> pose = bones;
    for (int b : which) {
      octocap_quat_t& g = pose[b].global_rotation;
      const Eigen::Quaterniond now = (q * Eigen::Quaterniond(g.w, g.x, g.y, g.z)).normalized();
      g = {static_cast<float>(now.x()), static_cast<float>(now.y()), static_cast<float>(now.z()), static_cast<float>(now.w())};
    }
    return pose;
  };
  const std::vector<uint8_t> base = render(bones);
  const auto joints = scene.character_joints();
  const double neck_v = cam.project(joints[OCTOCAP_JOINT_NECK]).y(), root_v = cam.project(joints[OCTOCAP_JOINT_ROOT]).y();
  const double knee_v = std::min(cam.project(joints[OCTOCAP_JOINT_R_KNEE]).y(), cam.project(joints[OCTOCAP_JOINT_L_KNEE]).y());
  REQUIRE(neck_v < root_v);  // image rows grow downward: the neck is above the hips
  // Rows of the pixels that changed against the base picture.
  auto changed_rows = [&](const std::vector<uint8_t>& picture) {
    std::vector<int> rows;
    for (size_t i = 0; i < picture.size(); i += 3)
      if (std::abs(picture[i] - base[i]) + std::abs(picture[i + 1] - base[i + 1]) + std::abs(picture[i + 2] - base[i + 2]) > 24)
        rows.push_back(static_cast<int>(i / 3) / cam.w);
    return rows;
  };
  // The head turned 70 degrees to the side: pixels change around the head, none below the chest.
  const std::vector<int> head = changed_rows(render(turned({OCTOCAP_BONE_HEAD}, Eigen::Quaterniond(Eigen::AngleAxisd(70 * M_PI / 180, Eigen::Vector3d::UnitY())))));
  const double chest_v = neck_v + 0.3 * (root_v - neck_v);
  INFO("head turned: " << head.size() << " pixels changed, lowest row " << (head.empty() ? -1 : *std::max_element(head.begin(), head.end()))
                       << "; neck at row " << neck_v << ", chest " << chest_v);
  CHECK(head.size() > 30);
  CHECK(std::count_if(head.begin(), head.end(), [&](int v) { return v <= chest_v; }) == static_cast<std::ptrdiff_t>(head.size()));
  // Both feet flexed 35 degrees (toes up, about the body's left-right axis): pixels change below the knees only.
  const Eigen::Quaterniond flex(Eigen::AngleAxisd(-35 * M_PI / 180, Eigen::Vector3d::UnitX()));
  const std::vector<int> feet = changed_rows(render(turned({OCTOCAP_BONE_R_FOOT, OCTOCAP_BONE_L_FOOT}, flex)));
  INFO("feet flexed: " << feet.size() << " pixels changed, highest row " << (feet.empty() ? -1 : *std::min_element(feet.begin(), feet.end()))
                       << "; knees at row " << knee_v);
  CHECK(feet.size() > 30);
  CHECK(std::count_if(feet.begin(), feet.end(), [&](int v) { return v >= knee_v; }) == static_cast<std::ptrdiff_t>(feet.size()));
}

TEST_CASE("octocap-viewer writes one PNG per frame, from calibrated cameras too, and opens a window under Xvfb") {
  testing::TempDir dir;
  const std::string viewer = OCTOCAP_VIEWER_PATH;
  testing::Run r = testing::run_command(viewer + " --motion " + kCmu + " --frames " + dir.file("orbit") +
                                        " --max-frames 3 --step 50 --size 320x240 --skeleton --skinning dqs");
  INFO(r.output);
  REQUIRE(r.status == 0);
  for (int f = 0; f < 3; ++f) {
    const cv::Mat im = cv::imread(dir.file("orbit/frame_00000" + std::to_string(f) + ".png"));
    REQUIRE(im.cols == 320);
    REQUIRE(im.rows == 240);
  }
  CHECK(!std::filesystem::exists(dir.file("orbit/frame_000003.png")));

  r = testing::run_command(viewer + " --motion " + kSample + "/ground_truth.csv --frames " + dir.file("views") +
                           " --calibration " + kSample + "/calibration.toml --all-cameras --size 480x360 --max-frames 2" +
                           " --ground-truth " + dir.file("views/truth.csv"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  size_t cameras = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path() / "views"))
    if (e.is_directory()) {
      ++cameras;
      CHECK(std::filesystem::exists(e.path() / "frame_000001.png"));
      CHECK(cv::imread((e.path() / "frame_000000.png").string()).cols == 480);
    }
  CHECK(cameras == 5);
  CHECK(std::filesystem::file_size(dir.file("views/truth.csv")) > 100);

  r = testing::run_command(viewer + " --motion " + kCmu + " --frames " + dir.file("x") + " --size 12");
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("WIDTHxHEIGHT"));
  r = testing::run_command(viewer + " --motion " + kCmu + " --frames " + dir.file("x") + " --calibration " + kSample +
                           "/calibration.toml --camera nope");
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("no camera named \"nope\""));
  r = testing::run_command(viewer + " --motion " + std::string(OCTOCAP_SOURCE_DIR) + "/README.md --frames " + dir.file("x"));
  CHECK(r.status != 0);
  CHECK_THAT(r.output, ContainsSubstring("unknown motion format"));

  // GLFW needs an X server: Xvfb stands in for one. Mesa's GLX driver is dlopen()ed and closed again, and what it
  // leaks has no module left to name for a suppression: leak checking is off for this child only (it has no effect
  // outside the sanitizer build; every other viewer run here is leak-checked).
  r = testing::run_command("ASAN_OPTIONS=detect_leaks=0 xvfb-run -a " + viewer + " --motion " + kCmu + " --window --max-frames 5 --size 320x240");
  INFO(r.output);
  CHECK(r.status == 0);
}

TEST_CASE("a character rendered from 5 calibrated cameras is solved back from its pixels near its true joints") {
  // The whole pipeline on known ground truth: CMU motion -> skinned character -> 5 rendered views -> ONNX detector
  // -> 3D, compared with where the rendered character's joints really are.
  testing::TempDir dir;
  testing::Run r = testing::run_command(std::string(OCTOCAP_VIEWER_PATH) + " --motion " + kSample +
                                        "/ground_truth.csv --frames " + dir.file("views") + " --calibration " + kSample +
                                        "/calibration.toml --all-cameras --no-grid --max-frames 6 --step 12 --size 960x540"
                                        " --ground-truth " + dir.file("truth.csv"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  r = testing::run_command(std::string(OCTOCAP_CLI_PATH) + " solve --images " + dir.file("views") + " --calibration " +
                           kSample + "/calibration.toml --output " + dir.file("out.trc") + " --ground-truth " +
                           dir.file("truth.csv") + " --filter none --detect-threads 1 --quiet --debug-images " +
                           dir.file("debug"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  const size_t at = r.output.find("MPJPE ");
  REQUIRE(at != std::string::npos);
  const double mpjpe = std::stod(r.output.substr(at + 6));
  CHECK(mpjpe < 60.0);
  const size_t solved = r.output.find("keypoints solved:");
  REQUIRE(solved != std::string::npos);
  CHECK(std::stod(r.output.substr(r.output.find('(', solved) + 1)) > 90.0);
  // What the detector saw, drawn: one picture per camera and frame, at the camera's size.
  const cv::Mat debug = cv::imread(dir.file("debug/cam_1_frame_000005.png"));
  CHECK(debug.cols == 960);
  CHECK(debug.rows == 540);
}

TEST_CASE("the glTF export carries the skinned character and the motion: re-imported, its joints are the viewer's") {
  testing::TempDir dir;
  const std::string glb = dir.file("walk.glb");
  Scene scene(kCmu, SceneOptions{});
  const int frames = 8, step = 25;
  export_gltf(scene, default_character_path(), glb, 0, frames, step);

  // Khronos' glTF-Validator finds neither an error nor a warning (assimp alone wrote 12 errors, joint weights summing
  // to 1.00000095, and 6 warnings, skinned meshes under transformed parents), nor an archived extension.
  const std::string validator = std::string(OCTOCAP_SOURCE_DIR) + "/.cache/gltf-validator/node_modules";
  REQUIRE(std::filesystem::exists(validator + "/gltf-validator"));  // scripts/fetch-gltf-validator.sh
  const testing::Run check = testing::run_command("NODE_PATH=" + validator + " node " + OCTOCAP_SOURCE_DIR +
                                                  "/tests/support/validate_gltf.js " + glb);
  INFO(check.output);
  CHECK(check.status == 0);
  CHECK_THAT(check.output, ContainsSubstring("errors 0 warnings 0"));
  CHECK_THAT(check.output, !ContainsSubstring("SpecularGlossiness") && !ContainsSubstring("FB_ngon_encoding"));

  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(glb, 0);
  REQUIRE(s != nullptr);
  REQUIRE(s->mNumAnimations == 1);
  CHECK(s->mNumMeshes >= 1);
  CHECK(s->mMeshes[0]->HasBones());
  const aiAnimation* anim = s->mAnimations[0];
  CHECK(anim->mNumChannels == 1 + scene.retargeter().driven_nodes().size());  // the scene root + every turned node
  // Node transforms at key k: channel keys where animated, the file's own matrix elsewhere.
  for (int k : {0, 3, 7}) {
    std::function<void(const aiNode*, const aiMatrix4x4&, std::map<std::string, aiVector3D>&)> walk =
        [&](const aiNode* n, const aiMatrix4x4& parent, std::map<std::string, aiVector3D>& out) {
          aiMatrix4x4 local = n->mTransformation;
          for (unsigned c = 0; c < anim->mNumChannels; ++c) {
            const aiNodeAnim* ch = anim->mChannels[c];
            if (ch->mNodeName != n->mName) continue;
            REQUIRE(ch->mNumRotationKeys == static_cast<unsigned>(frames));
            local = aiMatrix4x4(ch->mScalingKeys[k].mValue, ch->mRotationKeys[k].mValue, ch->mPositionKeys[k].mValue);
          }
          const aiMatrix4x4 global = parent * local;
          out[n->mName.C_Str()] = aiVector3D(global.a4, global.b4, global.c4);
          for (unsigned i = 0; i < n->mNumChildren; ++i) walk(n->mChildren[i], global, out);
        };
    std::map<std::string, aiVector3D> positions;
    walk(s->mRootNode, aiMatrix4x4(), positions);
    scene.pose(k * step);
    for (int b = 0; b < OCTOCAP_BONE_COUNT; ++b) {
      const std::string name = scene.character().nodes[scene.bone_map()[b]].name;
      REQUIRE(positions.count(name) == 1);
      const Eigen::Vector3f want = scene.placement() * scene.globals()[scene.bone_map()[b]].translation();
      const aiVector3D& got = positions[name];
      INFO("key " << k << ", node " << name);
      CHECK((Eigen::Vector3f(got.x, got.y, got.z) - want).norm() < 1e-3f);  // within 1 mm
    }
  }
}

TEST_CASE("octocap-viewer renders a live DDS stream from another process") {
  const uint32_t domain = testing::loopback_dds_domain() + 7;
  testing::TempDir dir;
  // Publisher in the background (it waits for the viewer to subscribe), the viewer renders 5 received poses.
  const std::string publisher = std::string(OCTOCAP_CLI_PATH) + " solve --calibration " + kSample +
                                "/calibration.toml --keypoints " + kSample + "/keypoints --output " + dir.file("pub.trc") +
                                " --publish --publish-qos record --wait-subscribers 1 --quiet --domain " +
                                std::to_string(domain);
  const testing::Run r = testing::run_command("(" + publisher + " > /dev/null 2>&1 &); " + OCTOCAP_VIEWER_PATH +
                                              " --subscribe --qos record --domain " + std::to_string(domain) +
                                              " --frames " + dir.file("live") + " --max-frames 5 --size 320x240");
  INFO(r.output);
  REQUIRE(r.status == 0);
  for (int f = 0; f < 5; ++f) CHECK(std::filesystem::exists(dir.file("live/frame_00000" + std::to_string(f) + ".png")));
}

TEST_CASE("a bone map file overrides the name heuristics, and a bad one is refused by name") {
  const Character c = load_character(default_character_path());
  BoneMap map = find_bone_map(c);
  testing::TempDir dir;
  apply_bone_map_file(c, dir.write("ok.json", R"({"head": "Head", "l_upper_arm": "B_UpperArm_Left"})"), map);
  CHECK(c.nodes[map[OCTOCAP_BONE_HEAD]].name == "Head");
  CHECK_THROWS_WITH(apply_bone_map_file(c, dir.write("a.json", R"({"elbow": "Head"})"), map),
                    ContainsSubstring("\"elbow\" is not an octocap bone"));
  CHECK_THROWS_WITH(apply_bone_map_file(c, dir.write("b.json", R"({"head": "Nope"})"), map),
                    ContainsSubstring("no node \"Nope\""));
  CHECK_THROWS_WITH(apply_bone_map_file(c, dir.write("c.json", "[1, 2"), map), ContainsSubstring("not JSON"));
  Character headless = c;
  headless.nodes[find_bone_map(c)[OCTOCAP_BONE_L_UPPER_LEG]].name = "thing";
  CHECK_THROWS_WITH(Retargeter(headless, find_bone_map(headless)), ContainsSubstring("l_upper_leg"));
}
