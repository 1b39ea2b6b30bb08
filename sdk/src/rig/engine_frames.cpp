#include "rig/engine_frames.h"

namespace octocap::internal {

Eigen::Vector3d convert_position(const Eigen::Vector3d& p, CoordFrame frame) {
  switch (frame) {
    case CoordFrame::unity: return {-p.x(), p.y(), p.z()};
    case CoordFrame::godot: return {-p.x(), p.y(), -p.z()};
    case CoordFrame::rig: break;
  }
  return p;
}

Eigen::Quaterniond convert_rotation(const Eigen::Quaterniond& q, CoordFrame frame) {
  switch (frame) {
    // M q M^-1 with M = diag(-1, 1, 1): the axis is mirrored and the sense of rotation flips.
    case CoordFrame::unity: return Eigen::Quaterniond(q.w(), q.x(), -q.y(), -q.z());
    // Conjugation by a half turn about Y.
    case CoordFrame::godot: return Eigen::Quaterniond(q.w(), -q.x(), q.y(), -q.z());
    case CoordFrame::rig: break;
  }
  return q;
}

}  // namespace octocap::internal
