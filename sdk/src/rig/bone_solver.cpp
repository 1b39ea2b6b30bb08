#include "rig/bone_solver.h"

#include <algorithm>
#include <cmath>

namespace octocap::internal {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

constexpr double kDegree = M_PI / 180;
// A limb bent less than this gives no hinge plane to trust (noise swings it round); fully trusted from the second.
constexpr double kHingeFrom = 10 * kDegree, kHingeFull = 25 * kDegree;
// Trusted fully once bent so far, every frame: smoothing the plane's roll over frames (half way each frame) lags behind
// real motion more than it removes noise (tests/rig/test_rig_rotations.cpp: upper arms 3.0 deg median instead of 2.4).
// A cue direction this close to the bone (sine of the angle between them) says nothing about its roll.
constexpr double kCueFrom = 0.2, kCueFull = 0.5;
// Per frame, how far a held roll moves toward the smallest rotation (about 1 s to halve at 30 frames/s).
constexpr double kHoldDecay = 0.02;
// How far the pelvis's up follows the spine (neck - root) rather than the world's up. Measured against CMU motion's
// own hip rotations (tests/rig/test_rig_rotations.cpp): 0 (the world's up) 5.3 deg median / 14.5 deg at the 90th
// percentile, 0.5 2.7 / 6.0, 0.7 2.2 / 5.4, 0.75 2.5 / 5.3, 1 (the spine) 3.7 / 8.2.
constexpr double kPelvisFollowsSpine = 0.7;

// The rotation taking the template direction d0 to d and the template side s0 (perpendicular to d0) to the part of
// s perpendicular to d. `sine` receives how far s is from d (0: along it, no roll to be had).
std::optional<Eigen::Quaterniond> aim(const Eigen::Vector3d& d0, const Eigen::Vector3d& s0, const Eigen::Vector3d& d,
                                      const Eigen::Vector3d& s, double& sine) {
  sine = 0;
  if (!finite(s) || !(s.norm() > 1e-9)) return std::nullopt;
  const Eigen::Vector3d dn = d.normalized();
  const Eigen::Vector3d side = s - s.dot(dn) * dn;
  sine = side.norm() / s.norm();
  if (!(sine > 1e-6)) return std::nullopt;
  Eigen::Matrix3d rest, now;
  rest << d0, s0, d0.cross(s0);
  const Eigen::Vector3d sn = side.normalized();
  now << dn, sn, dn.cross(sn);
  const Eigen::Quaterniond q(now * rest.transpose());
  if (!q.coeffs().allFinite()) return std::nullopt;
  return q.normalized();
}

// How a bone's roll is decided (see bone_solver.h).
enum class Roll { none, hinge, shoulders, face, foot, palm };

struct RollRule {
  Roll kind = Roll::none;
  int far_joint = -1;          // hinge: the end of the limb's second bone (hand, ankle); foot: the heel; palm: the wrist
  Eigen::Vector3d side_rest;   // the template's side direction: hinge axis, or left (+X)
  bool smoothed = false;       // the cue is noisy for its size: follow it part of the way each frame (follow())
  double max_roll = M_PI;      // the largest roll about the bone's own axis away from the smallest rotation
};

// How far toward its cue a bone moves this frame. Most cues are followed at once: smoothing them lags behind real
// motion more than it removes noise (tests/rig/test_rig_rotations.cpp, arms: 1.5-2.7 deg median at once, 2.0-2.9 even with
// an adaptive filter). A foot's roll comes from a heel 6-9 cm off the ankle, where a centimetre of detection noise is
// many degrees, and feet seldom roll fast: there the roll moves a quarter of the way each frame. Measured (90th
// percentile of the frame-to-frame turn of the right foot on the real take; CMU feet against the truth, median / 90th):
// at once 26 deg, CMU 2.1-2.3 / 4.9; a quarter 19 deg, CMU 1.7-1.8 / 3.9-4.6; an adaptive filter (small changes a fifth,
// 10 deg at once) 26 deg: the noise's jumps are large too. Per frame, so it is a little slower at higher frame rates.
constexpr double kFootFollow = 0.25;
constexpr double kFootRollRange = 35 * kDegree;
// A heel this close to the ankle (as a fraction of the foot's length) gives no roll to trust; fully from the second.
// Feet are 2.5-3 times as long as heel to ankle; on the real take some heels were found 2 cm from the ankle.
constexpr double kHeelFrom = 0.15, kHeelFull = 0.35;
// Knuckles (index to little finger, ~8 cm) as a fraction of wrist to knuckles (~9 cm): below the first, no palm.
constexpr double kKnucklesFrom = 0.3, kKnucklesFull = 0.6;

// `target` (a local rotation with the same direction as `smallest`) with its roll about the bone's axis clamped to the
// rule's range.
Eigen::Quaterniond within_range(const RollRule& rule, const Eigen::Vector3d& axis, const Eigen::Quaterniond& smallest,
                                const Eigen::Quaterniond& target) {
  if (rule.max_roll >= M_PI) return target;
  const double roll = twist_angle(smallest.conjugate() * target, axis);
  if (std::abs(roll) <= rule.max_roll) return target;
  return (smallest * Eigen::AngleAxisd(std::copysign(rule.max_roll, roll), axis)).normalized();
}

double follow(const RollRule& rule) { return rule.smoothed ? kFootFollow : 1.0; }

const std::array<RollRule, kBoneCount>& roll_rules() {
  // Elbows flex toward the front (+Z): about +Y for the right arm (template direction -X), -Y for the left (+X);
  // knees flex toward the back: about +X for both legs (template direction -Y).
  static const std::array<RollRule, kBoneCount> rules = [] {
    std::array<RollRule, kBoneCount> r{};
    r[kBoneTorso] = {Roll::shoulders, -1, Eigen::Vector3d::UnitX()};
    r[kBoneHead] = {Roll::face, -1, Eigen::Vector3d::UnitX()};
    r[kBoneRUpperArm] = {Roll::hinge, kRHand, Eigen::Vector3d::UnitY()};
    r[kBoneLUpperArm] = {Roll::hinge, kLHand, -Eigen::Vector3d::UnitY()};
    r[kBoneRUpperLeg] = {Roll::hinge, kRFoot, Eigen::Vector3d::UnitX()};
    r[kBoneLUpperLeg] = {Roll::hinge, kLFoot, Eigen::Vector3d::UnitX()};
    // A foot (template forward, +Z) spans a plane with its heel (below the ankle): the plane's normal, toe direction
    // x heel direction, is +X in the template for both feet.
    // A foot's own roll (inversion, eversion) goes a little past 30 deg: a heel that says more is a wrong detection
    // (on the real take, heels 2 cm from the ankle flipped the foot over).
    r[kBoneRFoot] = {Roll::foot, kRHeel, Eigen::Vector3d::UnitX(), true, kFootRollRange};
    r[kBoneLFoot] = {Roll::foot, kLHeel, Eigen::Vector3d::UnitX(), true, kFootRollRange};
    // A hand in the T-pose, palm down, has its index knuckle in front of its little finger's (+Z) on either side. The
    // knuckles are 7-9 cm apart, noisy as the heel is: followed a quarter of the way each frame. Wrist and forearm
    // together turn a palm up or down and a little past: the roll is not clamped.
    r[kBoneRHand] = {Roll::palm, kRHand, Eigen::Vector3d::UnitZ(), true};
    r[kBoneLHand] = {Roll::palm, kLHand, Eigen::Vector3d::UnitZ(), true};
    return r;
  }();
  return rules;
}

// The bone's rotation (global) from its cue, and how much to trust it (0..1); nullopt when there is no cue.
std::optional<Eigen::Quaterniond> roll_cue(int b, const SkeletonJoints& j, const BodyCues& cues,
                                           const Eigen::Vector3d& d, double& weight) {
  const RollRule& rule = roll_rules()[b];
  const Eigen::Vector3d& rest = tpose_directions()[b];
  const BoneDef& def = bone_table()[b];
  weight = 0;
  double sine = 0;
  std::optional<Eigen::Quaterniond> q;
  switch (rule.kind) {
    case Roll::none:
      return std::nullopt;
    case Roll::hinge: {
      if (!finite(j[rule.far_joint])) return std::nullopt;
      const Eigen::Vector3d next = j[rule.far_joint] - j[def.tail];
      const double bend = std::atan2(d.cross(next).norm(), d.dot(next));
      q = aim(rest, rule.side_rest, d, d.cross(next), sine);
      weight = smoothstep(kHingeFrom, kHingeFull, bend);
      break;
    }
    case Roll::foot: {
      if (!finite(j[rule.far_joint])) return std::nullopt;
      const Eigen::Vector3d heel = j[rule.far_joint] - j[def.head];
      const Eigen::Vector3d side = d.cross(heel);
      q = aim(rest, rule.side_rest, d, side, sine);
      const double heel_sine = side.norm() / (d.norm() * heel.norm());
      weight = smoothstep(kCueFrom, kCueFull, heel_sine) * smoothstep(kHeelFrom, kHeelFull, heel.norm() / d.norm());
      break;
    }
    case Roll::shoulders:
      if (!finite(j[kLShoulder]) || !finite(j[kRShoulder])) return std::nullopt;
      q = aim(rest, rule.side_rest, d, j[kLShoulder] - j[kRShoulder], sine);
      weight = smoothstep(kCueFrom, kCueFull, sine);
      break;
    case Roll::palm: {
      const Eigen::Vector3d& across = rule.far_joint == kRHand ? cues.r_palm_across : cues.l_palm_across;
      if (!finite(across)) return std::nullopt;
      q = aim(rest, rule.side_rest, d, across, sine);
      // Knuckles found on top of each other (a hand seen edge-on in every view) say nothing.
      weight = smoothstep(kCueFrom, kCueFull, sine) * smoothstep(kKnucklesFrom, kKnucklesFull, across.norm() / d.norm());
      break;
    }
    case Roll::face:
      // Left = up x forward in the template (+X = +Y x +Z): the nose turns the head when the ears are not seen.
      q = aim(rest, rule.side_rest, d, cues.head_across, sine);
      if (!q && finite(cues.head_forward)) q = aim(rest, rule.side_rest, d, d.normalized().cross(cues.head_forward), sine);
      weight = smoothstep(kCueFrom, kCueFull, sine);
      break;
  }
  if (!q) weight = 0;
  return q;
}

}  // namespace

SkeletonPose BoneSolver::solve(const SkeletonJoints& j, const BodyCues& cues) {
  SkeletonPose pose;
  const auto& bones = bone_table();
  const auto& rest = tpose_directions();

  // Root: x toward the left hip (the template's left is +X), y as close to world up as the hips allow.
  BonePose& root = pose[kBoneRoot];
  if (finite(j[kRoot]) && finite(j[kLHip]) && finite(j[kRHip])) {
    const Eigen::Vector3d across = j[kLHip] - j[kRHip];
    Eigen::Vector3d x = across.normalized();
    // The pelvis tilts with the trunk, not as far: its up is most of the way from the world's up to the spine.
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    const Eigen::Vector3d spine = (j[kNeck] - j[kRoot]).normalized();
    if (finite(spine)) up = ((1 - kPelvisFollowsSpine) * up + kPelvisFollowsSpine * spine).normalized();
    Eigen::Vector3d z = x.cross(up);
    // Finite inputs can still overflow (coordinates near 1e308): only finite rotations are valid.
    if (std::isfinite(across.norm()) && across.norm() > 1e-6 && z.norm() > 1e-6) {
      z.normalize();
      const Eigen::Vector3d y = z.cross(x);
      Eigen::Matrix3d R;
      R << x, y, z;
      root.global = Eigen::Quaterniond(R).normalized();
      root.local = root.global;
      root.head = j[kRoot];
      root.length = (j[kLHip] - j[kRoot]).norm();
      root.valid = true;
    }
  }

  for (int b = 1; b < kBoneCount; ++b) {
    const BoneDef& def = bones[b];
    const BonePose& parent = pose[def.parent];
    BonePose& bone = pose[b];
    if (!parent.valid || !finite(j[def.head]) || !finite(j[def.tail])) continue;
    const Eigen::Vector3d d = j[def.tail] - j[def.head];
    const double len = d.norm();
    if (!(len >= 1e-6) || !std::isfinite(len)) continue;
    const Eigen::Vector3d in_parent = parent.global.conjugate() * (d / len);
    Eigen::Quaterniond local = Eigen::Quaterniond::FromTwoVectors(rest[b], in_parent).normalized();
    const Eigen::Quaterniond smallest = local;
    if (!local.coeffs().allFinite()) continue;
    if (roll_rules()[b].kind != Roll::none) {
      // Held: last frame's roll carried onto today's direction (in the parent's frame, so that a body turning round
      // carries it along), drifting slowly toward the smallest rotation. Then the cue, as far as it is trusted.
      Eigen::Quaterniond held = local;
      if (previous_[b]) {
        const Eigen::Quaterniond carried =
            (Eigen::Quaterniond::FromTwoVectors(*previous_[b] * rest[b], in_parent) * *previous_[b]).normalized();
        if (carried.coeffs().allFinite()) held = carried;
      }
      double weight = 0;
      const std::optional<Eigen::Quaterniond> cue = roll_cue(b, j, cues, d, weight);
      if (cue && weight > 0) {  // roll_cue gives weight 0 without a cue
        const Eigen::Quaterniond target = within_range(roll_rules()[b], rest[b], smallest, parent.global.conjugate() * *cue);
        held = held.slerp(weight * (previous_[b] ? follow(roll_rules()[b]) : 1.0), target).normalized();
      }
      // What the cue does not say drifts slowly toward the smallest rotation (a cue seen in full stops the drift).
      local = held.slerp(kHoldDecay * (1 - weight), smallest).normalized();
      previous_[b] = local;
    }
    bone.local = local;
    bone.global = (parent.global * bone.local).normalized();
    bone.head = j[def.head];
    bone.length = len;
    bone.valid = true;
  }
  for (int b = 0; b < kBoneCount; ++b)
    if (!pose[b].valid) previous_[b].reset();  // nothing to hold across a gap in the bone
  return pose;
}

SkeletonPose solve_bones(const SkeletonJoints& joints) { return BoneSolver{}.solve(joints); }

Eigen::Matrix3d naive_bone_frame(const Eigen::Vector3d& direction, const Eigen::Vector3d& ref) {
  const Eigen::Vector3d x = direction.normalized();
  const Eigen::Vector3d y = x.cross(ref).normalized();
  const Eigen::Vector3d z = x.cross(y);
  Eigen::Matrix3d R;
  R << x, y, z;
  return R;
}

double twist_angle(const Eigen::Quaterniond& q, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d a = axis.normalized();
  const double p = q.vec().dot(a);
  return 2.0 * std::atan2(p, q.w());
}

}  // namespace octocap::internal
