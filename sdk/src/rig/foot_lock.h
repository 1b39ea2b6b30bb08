// Feet that stay planted: per person, causal. A foot is in contact while its ankle is still and near the floor
// (with hysteresis: it takes more to leave contact than to enter it, so contacts do not flicker on noise); while it
// is, the ankle is held on a lock that follows it slowly (a foot rolls from heel to toe) and the leg turns about the
// hip to reach it (the thigh keeps its length, the knee its bend; the lock is never more than max_drift from the
// measured ankle, so the shin changes by less), blended in and out over a few frames. Markerless ankles wander while
// a foot is planted (three to five times the motion that is really there, tests/rig/test_foot_lock.cpp): locking is what makes an avatar
// stand instead of skate, and engines read the contacts for their own IK.
#pragma once
#include <array>
#include <cmath>
#include <vector>

#include "core/skeleton.h"
#include "rig/bone_solver.h"

namespace octocap::internal {

struct FootLockParams {
  // Contact begins when the ankle's horizontal speed falls below enter_speed and its height above a planted ankle's
  // (floor_ankle_height(), learnt from the feet: the calibration's ground says nothing of the ankle's height above
  // it) below enter_height; it ends when the speed rises above exit_speed, the height leaves +-exit_height (far below
  // is another level: the ground beside a box the person stood on), or the ankle drifts max_drift from its lock.
  double enter_speed_mps = 0.3, exit_speed_mps = 0.45;
  double enter_height_m = 0.05, exit_height_m = 0.07;
  // A planted foot whose measured ankle wanders this far from its lock is let go (a missed step).
  double max_drift_m = 0.03;
  // The lock's time constant (seconds) in following the measured ankle while the foot is planted.
  double follow_s = 0.6;
  // Seconds a foot takes to blend into and out of its lock.
  double blend_s = 0.15;
  // The speed is measured over this window (seconds): a noisy ankle's frame-to-frame speed is mostly noise.
  double speed_window_s = 0.1;
};

struct FootContacts {
  bool right = false, left = false;
  float right_weight = 0, left_weight = 0;  // how far each ankle is pulled onto its lock, 0..1
};

class FootLock {
 public:
  explicit FootLock(FootLockParams params = {});
  // Locks the feet of one frame's joints in place (ankle, heel, toe and knee of a planted foot change; nothing
  // else). dt: seconds since the previous frame (<= 0: the first). Missing ankles end their foot's contact.
  FootContacts apply(SkeletonJoints& joints, double dt);
  void reset();
  // The ankle height of a planted foot, learnt from the feet (NaN until a foot has stood still): the floor.
  double floor_ankle_height() const { return floor_; }

 private:
  struct Foot {
    bool contact = false;
    double weight = 0;  // blend, 0 (free) to 1 (locked)
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
    Eigen::Vector3d release = Eigen::Vector3d::Zero();  // the lock's offset from the ankle as it was let go
    int samples = 0;  // measurements averaged into the anchor since the contact began
    std::array<Eigen::Vector3d, 16> recent;  // the last ankles, a ring (speed over the window)
    std::array<double, 16> age{};             // seconds before now of each
    int count = 0, next = 0;
    double speed = 0;
  };
  Foot idle_foot() const;
  void update_floor(double ankle_height);
  FootLockParams p_;
  std::array<Foot, 2> feet_;
  double floor_ = std::nan("");
  std::vector<double> still_heights_;  // a bounded ring of still ankles' heights (the floor is a low quantile)
  size_t next_still_ = 0;
};

}  // namespace octocap::internal
