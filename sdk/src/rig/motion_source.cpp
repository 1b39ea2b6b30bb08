#include "rig/motion_source.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/axes.h"
#include "core/error.h"
#include "core/take_timing.h"
#include "io/bvh.h"
#include "io/motion_files.h"

namespace octocap::internal {
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

// Joints interpolated between two frames (NaN where either is missing).
SkeletonJoints blend(const SkeletonJoints& a, const SkeletonJoints& b, double w) {
  SkeletonJoints out;
  for (size_t j = 0; j < out.size(); ++j) out[j] = (1 - w) * a[j] + w * b[j];
  return out;
}

// Frames at `times` (seconds) put 1 / rate apart at their mean rate, when they are not already.
void put_on_even_rate(SkeletonMotion& m, const std::vector<double>& times) {
  if (times.size() < 2 || times.size() != m.frames.size() || !times_increase(times)) return;
  const double rate = mean_rate(times);
  if (!(rate >= 1e-3 && rate <= 1e5)) return;
  m.rate_hz = rate;
  if (evenly_spaced(times, rate)) return;
  SkeletonJoints missing;
  missing.fill(Eigen::Vector3d::Constant(kNaN));
  std::vector<std::vector<SkeletonJoints>> even;
  for (const Resampled& r : resample_plan(times, rate, max_interpolated_gap_s(rate))) {
    std::vector<SkeletonJoints> people(m.ids.size(), missing);
    if (!r.gap)
      for (size_t p = 0; p < people.size(); ++p) people[p] = blend(m.frames[r.before][p], m.frames[r.after][p], r.weight);
    even.push_back(std::move(people));
  }
  m.frames = std::move(even);
}

SkeletonMotion from_track(const MotionTrack& track, const std::string& path, bool maybe_z_up) {
  const KeypointLayout& l = layout_for_markers(track.markers, path);
  SkeletonMotion m;
  m.rate_hz = track.rate_hz;
  m.source_kind = std::string(lower_extension(path) == "csv" ? "CSV" : "TRC") + " (" + l.name + ")";
  std::vector<int> column(l.keypoints.size(), -1);  // each layout keypoint's marker
  for (size_t k = 0; k < l.keypoints.size(); ++k)
    for (size_t i = 0; i < track.markers.size(); ++i)
      if (track.markers[i] == l.keypoints[k]) column[k] = static_cast<int>(i);
  auto joints_of = [&](const MarkerFrame& f) {
    std::vector<Eigen::Vector3d> kp(l.keypoints.size(), Eigen::Vector3d::Constant(kNaN));
    for (size_t k = 0; k < kp.size(); ++k)
      if (column[k] >= 0) kp[k] = f[static_cast<size_t>(column[k])];
    return joints_from_keypoints(l, kp);
  };
  std::vector<double> times;  // when each frame happened
  if (!track.per_person) {
    for (const MarkerFrame& f : track.frames) m.frames.push_back({joints_of(f)});
    times = track.times_s;
  } else {
    // One frame per frame number from the first to the last, each person where their row is. Numbers without rows
    // (sets where nobody was seen) are frames with nobody, timed between their neighbours.
    m.ids.clear();
    int64_t first = INT64_MAX, last = INT64_MIN;
    for (const auto& row : track.rows) {
      m.ids.push_back(row.second);
      first = std::min(first, row.first);
      last = std::max(last, row.first);
    }
    std::sort(m.ids.begin(), m.ids.end());
    m.ids.erase(std::unique(m.ids.begin(), m.ids.end()), m.ids.end());
    if (m.ids.empty()) m.ids = {1};
    if (!track.rows.empty()) {
      if (last - first >= 10000000) throw Error(Errc::parse, path + ": frame numbers span more than 10 million frames");
      SkeletonJoints missing;
      missing.fill(Eigen::Vector3d::Constant(kNaN));
      m.frames.assign(static_cast<size_t>(last - first + 1), std::vector<SkeletonJoints>(m.ids.size(), missing));
      times.assign(m.frames.size(), kNaN);
      for (size_t r = 0; r < track.frames.size(); ++r) {
        const size_t f = static_cast<size_t>(track.rows[r].first - first);
        const auto at = std::lower_bound(m.ids.begin(), m.ids.end(), track.rows[r].second);
        m.frames[f][static_cast<size_t>(at - m.ids.begin())] = joints_of(track.frames[r]);
        times[f] = track.times_s.empty() ? static_cast<double>(f) / track.rate_hz : track.times_s[r];
      }
      // Frames with nobody: between the known times of their neighbours, by frame number.
      size_t known = 0;
      for (size_t f = 1; f < times.size(); ++f) {
        if (std::isnan(times[f])) continue;
        for (size_t g = known + 1; g < f; ++g)
          times[g] = times[known] + (times[f] - times[known]) * static_cast<double>(g - known) / static_cast<double>(f - known);
        known = f;
      }
    }
  }
  if (maybe_z_up) {
    // A CSV is in the calibration's world: Z up when the neck is mostly above the root along Z.
    Eigen::Vector3d up = Eigen::Vector3d::Zero();
    for (const auto& people : m.frames)
      for (const auto& j : people)
        if (j[kNeck].allFinite() && j[kRoot].allFinite()) up += j[kNeck] - j[kRoot];
    if (std::abs(up.z()) > std::abs(up.y()))
      for (auto& people : m.frames)
        for (auto& j : people)
          for (auto& p : j) p = zup_to_yup(p);
  }
  put_on_even_rate(m, times);
  return m;
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
    m.frames.push_back({s});
  }
  return m;
}

}  // namespace

SkeletonJoints joints_from_keypoints(const KeypointLayout& l, const std::vector<Eigen::Vector3d>& kp) {
  SkeletonJoints s;
  for (int j = 0; j < kJointCount; ++j) {
    s[j] = Eigen::Vector3d::Constant(kNaN);
    const std::vector<int>* alternative = first_present_alternative(
        l.joint_sources[j], [&](int k) { return static_cast<size_t>(k) < kp.size() && kp[k].allFinite(); });
    if (!alternative) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k : *alternative) sum += kp[k];
    s[j] = sum / static_cast<double>(alternative->size());
  }
  return s;
}

SkeletonMotion load_skeleton_motion(const std::string& path) {
  const std::string ext = lower_extension(path);
  SkeletonMotion m;
  if (ext == "trc") m = from_track(read_trc(path), path, false);
  else if (ext == "csv") m = from_track(read_csv(path), path, true);
  else if (ext == "bvh") m = from_bvh(path);
  else throw Error(Errc::invalid_argument, path + ": unknown motion format (use .trc, .csv or .bvh)");
  if (m.frames.empty()) throw Error(Errc::parse, path + ": no frames");
  return m;
}

}  // namespace octocap::internal
