#include "rig/motion_source.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "io/bvh.h"
#include "io/motion_files.h"

namespace octocap {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string lower_extension(const std::string& path) {
  const size_t dot = path.rfind('.');
  std::string e = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

// The layout whose keypoint names cover most markers (at least 12 of them).
const KeypointLayout& layout_for_markers(const std::vector<std::string>& markers, const std::string& path) {
  const KeypointLayout* best = nullptr;
  size_t best_hits = 0;
  for (LayoutId id : all_layouts()) {
    const KeypointLayout& l = layout(id);
    size_t hits = 0;
    for (const char* k : l.keypoints) hits += std::count(markers.begin(), markers.end(), k);
    // Ties go to the smaller layout: every COCO name is also in BODY_25B and HALPE_26.
    if (hits > best_hits || (hits == best_hits && best && l.keypoints.size() < best->keypoints.size())) best = &l, best_hits = hits;
  }
  if (!best || best_hits < 12)
    throw Error(Errc::parse, path + ": its marker names match no keypoint layout (BODY_25, BODY_25B, COCO_17, HALPE_26, BLAZEPOSE_33)");
  return *best;
}

SkeletonMotion from_track(const MotionTrack& track, const std::string& path, bool maybe_z_up) {
  const KeypointLayout& l = layout_for_markers(track.markers, path);
  SkeletonMotion m;
  m.rate_hz = track.rate_hz;
  m.source_kind = std::string(lower_extension(path) == "csv" ? "CSV" : "TRC") + " (" + l.name + ")";
  for (const MarkerFrame& f : track.frames) {
    std::vector<Eigen::Vector3d> kp(l.keypoints.size(), Eigen::Vector3d::Constant(kNaN));
    for (size_t k = 0; k < l.keypoints.size(); ++k)
      for (size_t i = 0; i < track.markers.size(); ++i)
        if (track.markers[i] == l.keypoints[k]) kp[k] = f[i];
    m.frames.push_back(joints_from_keypoints(l, kp));
  }
  if (maybe_z_up) {
    // A CSV is in the calibration's world: Z up when the neck is mostly above the root along Z.
    Eigen::Vector3d up = Eigen::Vector3d::Zero();
    for (const auto& j : m.frames)
      if (j[kNeck].allFinite() && j[kRoot].allFinite()) up += j[kNeck] - j[kRoot];
    if (std::abs(up.z()) > std::abs(up.y()))
      for (auto& j : m.frames)
        for (auto& p : j) p = zup_to_yup(p);
  }
  return m;
}

MotionTrack read_octocap_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(Errc::io, "cannot open " + path);
  std::string line;
  if (!std::getline(in, line)) throw Error(Errc::parse, path + ": empty");
  MotionTrack t;
  std::vector<std::string> header;
  {
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) header.push_back(cell);
  }
  if (header.size() < 4 || header[0] != "frame" || (header.size() - 1) % 3 != 0)
    throw Error(Errc::parse, path + ": not a `frame,NAME_x,NAME_y,NAME_z,...` CSV");
  for (size_t i = 1; i < header.size(); i += 3) {
    const std::string& h = header[i];
    if (h.size() < 3 || h.compare(h.size() - 2, 2, "_x") != 0) throw Error(Errc::parse, path + ": column " + h + " is not NAME_x");
    t.markers.push_back(h.substr(0, h.size() - 2));
  }
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    while (cells.size() < header.size()) cells.emplace_back();
    MarkerFrame f(t.markers.size(), Eigen::Vector3d::Constant(kNaN));
    for (size_t m = 0; m < t.markers.size(); ++m) {
      const std::string* c = &cells[1 + 3 * m];
      if (c[0].empty() || c[1].empty() || c[2].empty()) continue;
      const std::string where = path + ":" + std::to_string(line_no);
      f[m] = {parse_coordinate(c[0], where), parse_coordinate(c[1], where), parse_coordinate(c[2], where)};
    }
    t.frames.push_back(std::move(f));
  }
  return t;
}

SkeletonMotion from_bvh(const std::string& path) {
  const BvhMotion bvh = read_bvh(path);
  auto find_any = [&](std::initializer_list<const char*> names) {
    for (const char* n : names) {
      const int i = bvh.find(n);
      if (i >= 0) return i;
    }
    return -1;
  };
  const int root = find_any({"Hips", "hip", "Pelvis", "pelvis", "Root"});
  const int neck = find_any({"Neck", "neck", "Neck1"});
  const int head = find_any({"Head", "head"}), head_end = find_any({"Head_end", "head_end", "Neck_end"});
  const int j[12] = {find_any({"RightArm", "RightUpperArm", "rShldr"}), find_any({"RightForeArm", "RightLowerArm", "rForeArm"}),
                     find_any({"RightHand", "rHand", "RightForeArm_end"}), find_any({"LeftArm", "LeftUpperArm", "lShldr"}),
                     find_any({"LeftForeArm", "LeftLowerArm", "lForeArm"}), find_any({"LeftHand", "lHand", "LeftForeArm_end"}),
                     find_any({"RightUpLeg", "RightUpperLeg", "rThigh"}), find_any({"RightLeg", "RightLowerLeg", "rShin"}),
                     find_any({"RightFoot", "rFoot", "RightLeg_end"}), find_any({"LeftUpLeg", "LeftUpperLeg", "lThigh"}),
                     find_any({"LeftLeg", "LeftLowerLeg", "lShin"}), find_any({"LeftFoot", "lFoot", "LeftLeg_end"})};
  // Toes are optional (a foot bone then has no target); files have no heel, so a foot's roll is the smallest one.
  const int toes[2] = {find_any({"RightToeBase_end", "RightToeBase", "RightToe", "rToe"}),
                       find_any({"LeftToeBase_end", "LeftToeBase", "LeftToe", "lToe"})};
  // The knuckles: where the fingers start (CMU's RFingers: its FingerBase sits on the wrist; Mixamo-style Index1 or
  // Middle1), else the hand's end site.
  const int knuckles[2] = {find_any({"RFingers", "RightHandMiddle1", "RightHandIndex1", "RightHand_end", "rHand_end"}),
                           find_any({"LFingers", "LeftHandMiddle1", "LeftHandIndex1", "LeftHand_end", "lHand_end"})};
  (void)root;  // required as proof of a humanoid hierarchy; the root joint is taken between the hips
  if (root < 0 || neck < 0 || (head < 0 && head_end < 0) || std::count(j, j + 12, -1) > 0)
    throw Error(Errc::parse, path + ": no humanoid skeleton found (expected CMU / Mixamo-style joint names: Hips, Neck, "
                                    "Head, LeftArm, LeftForeArm, LeftHand, LeftUpLeg, LeftLeg, LeftFoot, ...)");
  // File units: whichever of m, cm, mm, inch or CMU's 1/0.45 inch makes the rest leg (hip-knee-ankle) closest to
  // an adult's 0.85 m. The leg, not the torso: where a file puts its root and neck varies, its knees do not.
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Matrix3d> R;
  bvh.pose(0, P, R);
  const double leg = (P[j[10]] - P[j[9]]).norm() + (P[j[11]] - P[j[10]]).norm();
  double unit = 1;
  for (double u : {1.0, 0.01, 0.001, 0.0254, 0.0254 / 0.45})
    if (std::abs(std::log(leg * u / 0.85)) < std::abs(std::log(leg * unit / 0.85))) unit = u;
  SkeletonMotion m;
  m.rate_hz = bvh.frame_time > 0 ? 1.0 / bvh.frame_time : 30;
  m.source_kind = "BVH";
  for (size_t f = 0; f < bvh.frames.size(); ++f) {
    bvh.pose(f, P, R);
    SkeletonJoints s;
    s[kRoot] = 0.5 * (P[j[6]] + P[j[9]]) * unit;  // between the hip joints (CMU's Hips sits 10 cm above them)
    s[kNeck] = P[neck] * unit;
    s[kHead] = (head >= 0 && head_end >= 0 ? 0.5 * (P[head] + P[head_end]) : P[head >= 0 ? head : head_end]) * unit;
    const int order[12] = {kRShoulder, kRElbow, kRHand, kLShoulder, kLElbow, kLHand, kRHip, kRKnee, kRFoot, kLHip, kLKnee, kLFoot};
    for (int i = 0; i < 12; ++i) s[order[i]] = P[j[i]] * unit;
    s[kRToe] = toes[0] >= 0 ? Eigen::Vector3d(P[toes[0]] * unit) : Eigen::Vector3d::Constant(kNaN);
    s[kLToe] = toes[1] >= 0 ? Eigen::Vector3d(P[toes[1]] * unit) : Eigen::Vector3d::Constant(kNaN);
    s[kRHeel] = s[kLHeel] = Eigen::Vector3d::Constant(kNaN);
    s[kRKnuckles] = knuckles[0] >= 0 ? Eigen::Vector3d(P[knuckles[0]] * unit) : Eigen::Vector3d::Constant(kNaN);
    s[kLKnuckles] = knuckles[1] >= 0 ? Eigen::Vector3d(P[knuckles[1]] * unit) : Eigen::Vector3d::Constant(kNaN);
    m.frames.push_back(s);
  }
  return m;
}

}  // namespace

SkeletonJoints joints_from_keypoints(const KeypointLayout& l, const std::vector<Eigen::Vector3d>& kp) {
  SkeletonJoints s;
  for (int j = 0; j < kJointCount; ++j) {
    s[j] = Eigen::Vector3d::Constant(kNaN);
    for (const auto& alternative : l.joint_sources[j]) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      bool all = true;
      for (int k : alternative) {
        all = all && static_cast<size_t>(k) < kp.size() && kp[k].allFinite();
        if (all) sum += kp[k];
      }
      if (!all) continue;
      s[j] = sum / static_cast<double>(alternative.size());
      break;
    }
  }
  return s;
}

SkeletonMotion load_skeleton_motion(const std::string& path) {
  const std::string ext = lower_extension(path);
  SkeletonMotion m;
  if (ext == "trc") m = from_track(read_trc(path), path, false);
  else if (ext == "csv") m = from_track(read_octocap_csv(path), path, true);
  else if (ext == "bvh") m = from_bvh(path);
  else throw Error(Errc::invalid_argument, path + ": unknown motion format (use .trc, .csv or .bvh)");
  if (m.frames.empty()) throw Error(Errc::parse, path + ": no frames");
  return m;
}

}  // namespace octocap
