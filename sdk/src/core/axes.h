#pragma once
// World-frame conventions between the tools of the field. octocap's world is right-handed, Y up, metres (DESIGN.md);
// Pose2Sim, OpenSim's TRC from Z-up labs and most calibration boards laid on the floor give Z up.
#include <Eigen/Core>

namespace octocap::internal {

// The rotation a Z-up world gets to become Y up: (x, y, z) -> (y, z, x). A rotation (determinant +1), not a mirror,
// so handedness and bone twists survive it.
inline Eigen::Vector3d zup_to_yup(const Eigen::Vector3d& p) { return {p.y(), p.z(), p.x()}; }
// Its inverse, (x, y, z) -> (z, x, y): a rig-frame point back into a Z-up world.
inline Eigen::Vector3d yup_to_zup(const Eigen::Vector3d& p) { return {p.z(), p.x(), p.y()}; }

}  // namespace octocap::internal
