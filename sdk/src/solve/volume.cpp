#include "solve/volume.h"

#include <algorithm>
#include <cmath>

namespace octocap::internal {

Eigen::AlignedBox3d derive_capture_volume(const Calibration& calib, double max_range) {
  Eigen::AlignedBox3d rig;
  for (const Camera& c : calib) rig.extend(c.center());
  const Eigen::Vector3d lo = rig.min().array() - max_range, hi = rig.max().array() + max_range;
  constexpr int kSteps = 32;
  const Eigen::Vector3d step = (hi - lo) / kSteps;
  const int need = calib.size() <= 2 ? static_cast<int>(calib.size()) : 2;
  Eigen::AlignedBox3d seen;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j)
      for (int k = 0; k <= kSteps; ++k) {
        const Eigen::Vector3d p = lo + Eigen::Vector3d(i * step.x(), j * step.y(), k * step.z());
        int views = 0;
        for (const Camera& c : calib) {
          if (views >= need) break;
          const Eigen::Vector3d pc = c.to_camera(p);
          // Closer than 0.3 m or farther than max_range is not where a person is filmed.
          if (pc.z() < 0.3 || pc.norm() > max_range) continue;
          const Eigen::Vector2d px = c.project(p);
          if (px.allFinite() && px.x() >= 0 && px.y() >= 0 && px.x() < c.width && px.y() < c.height) ++views;
        }
        if (views >= need) seen.extend(p);
      }
  if (seen.isEmpty()) return seen;
  // One grid cell of slack: the true boundary lies between a seen sample and an unseen one.
  return Eigen::AlignedBox3d(seen.min() - step, seen.max() + step);
}

}  // namespace octocap::internal
