#include "rig/bvh_export.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>

#include "core/error.h"

namespace octocap::internal {
namespace {

constexpr double kCm = 100.0;

const char* const kNames[kBoneCount] = {"Hips",     "Spine",       "Neck",         "RightShoulder", "RightArm",
                                        "RightForeArm", "LeftShoulder", "LeftArm", "LeftForeArm",   "RightUpLeg",
                                        "RightLeg", "LeftUpLeg",   "LeftLeg",       "RightFoot", "LeftFoot",
                                        "RightHand", "LeftHand"};

// Where bone b's head sits in its parent bone's frame at rest (metres).
Eigen::Vector3d rest_offset(int b, const std::vector<double>& len) {
  const auto& dirs = tpose_directions();
  const BoneDef& d = bone_table()[b];
  if (d.parent < 0) return Eigen::Vector3d::Zero();
  if (b == kBoneTorso) return Eigen::Vector3d::Zero();  // the torso starts at the root joint, like the root bone
  if (b == kBoneRUpperLeg) return -dirs[kBoneRoot] * len[kBoneRoot];
  if (b == kBoneLUpperLeg) return dirs[kBoneRoot] * len[kBoneRoot];
  return dirs[d.parent] * len[d.parent];
}

void write_joint(std::ostream& out, int b, int depth, const std::vector<double>& len) {
  const std::string pad(static_cast<size_t>(depth) * 2, ' ');
  const Eigen::Vector3d off = rest_offset(b, len) * kCm;
  out << pad << (b == kBoneRoot ? "ROOT " : "JOINT ") << kNames[b] << "\n" << pad << "{\n";
  out << pad << "  OFFSET " << off.x() << " " << off.y() << " " << off.z() << "\n";
  out << pad << "  CHANNELS " << (b == kBoneRoot ? "6 Xposition Yposition Zposition " : "3 ")
      << "Zrotation Xrotation Yrotation\n";
  bool children = false;
  for (int c = 0; c < kBoneCount; ++c)
    if (bone_table()[c].parent == b) {
      write_joint(out, c, depth + 1, len);
      children = true;
    }
  // The root's tail is the left hip, which the leg joints already place; other leaves end at their tail.
  if (!children && b != kBoneRoot) {
    const Eigen::Vector3d tail = tpose_directions()[b] * len[b] * kCm;
    out << pad << "  End Site\n" << pad << "  {\n"
        << pad << "    OFFSET " << tail.x() << " " << tail.y() << " " << tail.z() << "\n" << pad << "  }\n";
  }
  out << pad << "}\n";
}

void order(int b, std::vector<int>& out) {
  out.push_back(b);
  for (int c = 0; c < kBoneCount; ++c)
    if (bone_table()[c].parent == b) order(c, out);
}

}  // namespace

const char* bvh_joint_name(int bone) { return bone >= 0 && bone < kBoneCount ? kNames[bone] : nullptr; }

void write_bvh(const std::string& path, const std::vector<SkeletonPose>& frames, double rate_hz) {
  if (!(rate_hz > 0)) throw Error(Errc::invalid_argument, "BVH: the frame rate must be > 0");
  std::ofstream out(path);
  if (!out) throw Error(Errc::io, path + ": cannot open for writing");
  out << std::setprecision(9);
  // Offsets are fixed in BVH: the median length of each bone over the take.
  std::vector<double> len(kBoneCount, 0.0);
  for (int b = 0; b < kBoneCount; ++b) {
    std::vector<double> l;
    for (const auto& f : frames)
      if (f[b].valid) l.push_back(f[b].length);
    if (!l.empty()) {
      std::nth_element(l.begin(), l.begin() + l.size() / 2, l.end());
      len[b] = l[l.size() / 2];
    }
  }
  out << "HIERARCHY\n";
  write_joint(out, kBoneRoot, 0, len);
  std::vector<int> joints;
  order(kBoneRoot, joints);  // the channel order of the MOTION rows is the hierarchy's depth-first order
  out << "MOTION\nFrames: " << frames.size() << "\nFrame Time: " << 1.0 / rate_hz << "\n";
  std::vector<Eigen::Quaterniond> last(kBoneCount, Eigen::Quaterniond::Identity());
  Eigen::Vector3d root = Eigen::Vector3d::Zero();
  for (const auto& f : frames) {
    if (f[kBoneRoot].valid) root = f[kBoneRoot].head;
    out << root.x() * kCm << " " << root.y() * kCm << " " << root.z() * kCm;
    for (int b : joints) {
      if (f[b].valid) last[b] = f[b].local;
      // R = Rz(a) Rx(b) Ry(c), the channel order written above.
      const Eigen::Vector3d e = last[b].toRotationMatrix().eulerAngles(2, 0, 1) * (180.0 / M_PI);
      out << " " << e[0] << " " << e[1] << " " << e[2];
    }
    out << "\n";
  }
  if (!out) throw Error(Errc::io, path + ": write failed");
}

}  // namespace octocap::internal
