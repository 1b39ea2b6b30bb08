#include "rig/foot_lock.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <limits>

namespace octocap::internal {

namespace {

struct LegJoints {
  int hip, knee, ankle, heel, toe;
};
constexpr std::array<LegJoints, 2> kLegs = {{{kRHip, kRKnee, kRFoot, kRHeel, kRToe}, {kLHip, kLKnee, kLFoot, kLHeel, kLToe}}};
constexpr size_t kStillHeights = 300;  // ten seconds of a still foot at 30 frames/s
constexpr double kFloorQuantile = 0.2;

double horizontal(const Eigen::Vector3d& v) { return std::hypot(v.x(), v.z()); }

}  // namespace

FootLock::FootLock(FootLockParams params) : p_(params) { reset(); }

FootLock::Foot FootLock::idle_foot() const {
  Foot f;
  f.speed = p_.exit_speed_mps;  // not known to be still before it has moved
  return f;
}

void FootLock::reset() {
  for (Foot& f : feet_) f = idle_foot();
  floor_ = std::nan("");
  still_heights_.clear();
  next_still_ = 0;
}

void FootLock::update_floor(double ankle_height) {
  if (still_heights_.size() < kStillHeights) {
    still_heights_.push_back(ankle_height);
  } else {
    still_heights_[next_still_] = ankle_height;
    next_still_ = (next_still_ + 1) % kStillHeights;
  }
  std::vector<double> sorted = still_heights_;
  const size_t at = static_cast<size_t>(kFloorQuantile * static_cast<double>(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(at), sorted.end());
  floor_ = sorted[at];
}

FootContacts FootLock::apply(SkeletonJoints& joints, double dt) {
  FootContacts contacts;
  for (size_t side = 0; side < 2; ++side) {
    Foot& foot = feet_[side];
    const LegJoints& leg = kLegs[side];
    const Eigen::Vector3d ankle = joints[leg.ankle];
    if (!ankle.allFinite()) {
      foot = idle_foot();
      continue;
    }
    // Speed: the horizontal way from the oldest ankle within the window (or the nearest older one) to this one.
    for (int i = 0; i < foot.count; ++i) foot.age[i] += std::max(dt, 0.0);
    int from = -1, youngest = -1;  // the oldest within the window, else the youngest before now
    for (int i = 0; i < foot.count; ++i) {
      if (!(foot.age[i] > 0)) continue;
      if (foot.age[i] <= p_.speed_window_s && (from < 0 || foot.age[i] > foot.age[from])) from = i;
      if (youngest < 0 || foot.age[i] < foot.age[youngest]) youngest = i;
    }
    if (from < 0) from = youngest;
    if (from >= 0) foot.speed = horizontal(ankle - foot.recent[from]) / foot.age[from];
    foot.recent[foot.next] = ankle;
    foot.age[foot.next] = 0;
    foot.next = (foot.next + 1) % static_cast<int>(foot.recent.size());
    foot.count = std::min(foot.count + 1, static_cast<int>(foot.recent.size()));
    if (foot.speed < p_.enter_speed_mps) update_floor(ankle.y());
    const double height = std::isfinite(floor_) ? ankle.y() - floor_ : std::numeric_limits<double>::infinity();

    if (!foot.contact) {
      // Far below the learnt floor is another level (the ground beside a box it stood on): not this floor's contact.
      if (foot.speed < p_.enter_speed_mps && height < p_.enter_height_m && height > -p_.exit_height_m) {
        foot.contact = true;
        foot.anchor = ankle;
        foot.samples = 1;
      }
    } else if (foot.speed > p_.exit_speed_mps || std::abs(height) > p_.exit_height_m ||
               (ankle - foot.anchor).norm() > p_.max_drift_m) {
      foot.contact = false;
      foot.release = foot.anchor - ankle;
    } else if (dt > 0) {
      // The lock follows the measured ankle slowly: a planted foot still rolls from heel to toe (its ankle moves a
      // few centimetres a step), which a hard lock would fight and a slow one keeps, without the solve's jitter.
      // It starts as the mean of the contact's ankles (the solve's noise averages out) and becomes a slow follower.
      foot.samples = std::min(foot.samples + 1, std::max(1, static_cast<int>(p_.follow_s / dt)));
      foot.anchor += (ankle - foot.anchor) / static_cast<double>(foot.samples);
    }
    const double step = dt > 0 ? dt / p_.blend_s : 1.0;
    foot.weight = foot.contact ? std::min(1.0, foot.weight + step) : std::max(0.0, foot.weight - step);

    // Locked, the ankle goes onto the anchor (blending in); let go, the offset it had is carried along and fades, so
    // a foot that leaves fast is never held back toward where it stood.
    Eigen::Vector3d target = ankle + foot.weight * (foot.contact ? Eigen::Vector3d(foot.anchor - ankle) : foot.release);
    // A planted foot never goes through the floor (a free one may: the floor is learnt, and a step or a box is not it).
    if (foot.weight > 0 && std::isfinite(floor_)) target.y() = std::max(target.y(), floor_);
    if (side == 0) contacts.right = foot.contact, contacts.right_weight = static_cast<float>(foot.weight);
    else contacts.left = foot.contact, contacts.left_weight = static_cast<float>(foot.weight);
    const Eigen::Vector3d delta = target - ankle;
    if (delta.squaredNorm() == 0) continue;

    const Eigen::Vector3d hip = joints[leg.hip], knee = joints[leg.knee];
    // The leg turns about the hip onto the lock: the knee moves with it by as little as the ankle does. (Two-bone IK
    // that kept both lengths would swing a nearly straight standing leg's knee by centimetres for a millimetre.)
    if (hip.allFinite() && knee.allFinite() && (ankle - hip).norm() > 1e-6 && (target - hip).norm() > 1e-6)
      joints[leg.knee] = hip + Eigen::Quaterniond::FromTwoVectors(ankle - hip, target - hip) * (knee - hip);
    joints[leg.ankle] = target;
    for (int j : {leg.heel, leg.toe})
      if (joints[j].allFinite()) joints[j] += delta;
  }
  return contacts;
}

}  // namespace octocap::internal
