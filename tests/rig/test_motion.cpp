// Motion playback through the C ABI (octocap_motion_*): TRC / CSV / BVH to the paper's joints and bones.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "octocap/octocap.h"
#include "support/temp_dir.h"

using Catch::Approx;

namespace {

const std::string kSample = std::string(OCTOCAP_SOURCE_DIR) + "/data/sample";

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

// Column of NAME_x in the sample's ground truth (BODY_25 names, Y up).
double value(const std::vector<std::vector<std::string>>& rows, size_t frame, const std::string& name, int axis) {
  for (size_t c = 0; c < rows[0].size(); ++c)
    if (rows[0][c] == name + "_x") return std::stod(rows[frame + 1][c + axis]);
  FAIL("no column " << name);
  return 0;
}

struct Motion {
  octocap_motion_t* m = nullptr;
  ~Motion() { octocap_motion_destroy(m); }
};

}  // namespace

TEST_CASE("a keypoint CSV plays back as skeleton joints from the layout's sources, Z-up files turned upright") {
  const auto rows = read_csv(kSample + "/ground_truth.csv");
  Motion y_up;
  REQUIRE(octocap_motion_open((kSample + "/ground_truth.csv").c_str(), &y_up.m) == OCTOCAP_OK);
  uint32_t frames = 0;
  double rate = 0;
  REQUIRE(octocap_motion_info(y_up.m, &frames, &rate) == OCTOCAP_OK);
  CHECK(frames == rows.size() - 1);
  octocap_joint_t j[OCTOCAP_JOINT_COUNT];
  uint32_t n = 0;
  REQUIRE(octocap_motion_joints(y_up.m, 10, j, OCTOCAP_JOINT_COUNT, &n) == OCTOCAP_OK);
  REQUIRE(n == OCTOCAP_JOINT_COUNT);
  for (int axis = 0; axis < 3; ++axis) {
    // BODY_25: the root is between the hips, the head between the ears, the left elbow is LElbow.
    CHECK(j[OCTOCAP_JOINT_ROOT].position[axis] ==
          Approx(0.5 * (value(rows, 10, "RHip", axis) + value(rows, 10, "LHip", axis))).margin(1e-5));
    CHECK(j[OCTOCAP_JOINT_HEAD].position[axis] ==
          Approx(0.5 * (value(rows, 10, "REar", axis) + value(rows, 10, "LEar", axis))).margin(1e-5));
    CHECK(j[OCTOCAP_JOINT_L_ELBOW].position[axis] == Approx(value(rows, 10, "LElbow", axis)).margin(1e-5));
  }

  // The same take in a Z-up world, (x, y, z)_yup = (y, z, x)_zup: read back upright, equal.
  testing::TempDir dir;
  std::ofstream out(dir.file("zup.csv"));
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < rows[r].size(); ++c) {
      std::string cell = rows[r][c];
      if (r > 0 && c > 0 && !cell.empty()) {
        const size_t base = 1 + 3 * ((c - 1) / 3), axis = (c - 1) % 3;
        // z-up (p0, p1, p2) = (q2, q0, q1)
        cell = rows[r][base + (axis == 0 ? 2 : axis == 1 ? 0 : 1)];
      }
      out << (c ? "," : "") << cell;
    }
    out << '\n';
  }
  out.close();
  Motion z_up;
  REQUIRE(octocap_motion_open(dir.file("zup.csv").c_str(), &z_up.m) == OCTOCAP_OK);
  octocap_joint_t k[OCTOCAP_JOINT_COUNT];
  REQUIRE(octocap_motion_joints(z_up.m, 10, k, OCTOCAP_JOINT_COUNT, &n) == OCTOCAP_OK);
  for (int i = 0; i < OCTOCAP_JOINT_COUNT; ++i)
    for (int axis = 0; axis < 3; ++axis) CHECK(k[i].position[axis] == Approx(j[i].position[axis]).margin(1e-5));

  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  REQUIRE(octocap_motion_bones(y_up.m, 10, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
  for (int i = 0; i < OCTOCAP_BONE_COUNT; ++i) {
    // The CSV's layout has no hand points: every bone but the hands.
    const bool hand = i == OCTOCAP_BONE_R_HAND || i == OCTOCAP_BONE_L_HAND;
    CHECK(bones[i].valid == (hand ? 0u : 1u));
    if (!hand) CHECK(bones[i].length_m > 0.05f);
  }
}

TEST_CASE("a CMU BVH plays back in metres, and motion misuse gives clear errors") {
  Motion cmu;
  REQUIRE(octocap_motion_open("/usr/share/assimp/models/BVH/01_01.bvh", &cmu.m) == OCTOCAP_OK);
  uint32_t frames = 0;
  double rate = 0;
  REQUIRE(octocap_motion_info(cmu.m, &frames, &rate) == OCTOCAP_OK);
  CHECK(frames == 2752);
  CHECK(rate == Approx(120));
  octocap_bone_pose_t bones[OCTOCAP_BONE_COUNT];
  uint32_t n = 0;
  REQUIRE(octocap_motion_bones(cmu.m, 0, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_OK);
  const double leg = bones[OCTOCAP_BONE_L_UPPER_LEG].length_m + bones[OCTOCAP_BONE_L_LOWER_LEG].length_m;
  CHECK(leg == Approx(0.83).margin(0.05));  // an adult's hip-knee-ankle, found from CMU's own unit

  CHECK(octocap_motion_bones(cmu.m, frames, OCTOCAP_FRAME_RIG, bones, OCTOCAP_BONE_COUNT, &n) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(octocap_last_error()).find("out of range") != std::string::npos);
  CHECK(octocap_motion_bones(cmu.m, 0, OCTOCAP_FRAME_RIG, bones, 3, &n) == OCTOCAP_ERROR_BUFFER_TOO_SMALL);
  testing::TempDir dir;
  octocap_motion_t* m = nullptr;
  CHECK(octocap_motion_open(dir.file("absent.bvh").c_str(), &m) == OCTOCAP_ERROR_IO);
  CHECK(m == nullptr);
  CHECK(octocap_motion_open(dir.write("a.txt", "x").c_str(), &m) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_motion_open(dir.write("b.csv", "frame,A_x,A_y,A_z\n0,1,2,3\n").c_str(), &m) == OCTOCAP_ERROR_PARSE);
  CHECK(std::string(octocap_last_error()).find("match no keypoint layout") != std::string::npos);
  CHECK(octocap_motion_open(dir.write("c.bvh", "HIERARCHY\nROOT Pelvis\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition "
                                               "Yposition Zposition\n End Site\n {\n OFFSET 0 1 0\n }\n}\nMOTION\n"
                                               "Frames: 1\nFrame Time: 0.1\n0 0 0\n").c_str(), &m) == OCTOCAP_ERROR_PARSE);
  CHECK(std::string(octocap_last_error()).find("no humanoid skeleton") != std::string::npos);
  CHECK(octocap_motion_open(nullptr, &m) == OCTOCAP_ERROR_INVALID_ARGUMENT);
  CHECK(octocap_motion_info(nullptr, &frames, &rate) == OCTOCAP_ERROR_INVALID_HANDLE);
  octocap_motion_t* gone = cmu.m;
  octocap_motion_destroy(cmu.m);
  cmu.m = nullptr;
  CHECK(octocap_motion_info(gone, &frames, &rate) == OCTOCAP_ERROR_INVALID_HANDLE);
}
