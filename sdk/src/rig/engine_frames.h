// Converting rig-frame poses (right-handed, Y up, facing +Z) to game engines' frames.
#pragma once
#include <Eigen/Geometry>

namespace octocap::internal {

enum class CoordFrame : int { rig = 0, unity = 1, godot = 2 };

// Unity is left-handed: mirror X. Godot is right-handed with -Z forward: turn 180 degrees about Y.
// Both are applied to positions and, by conjugation, to rotations (local ones included, since the same
// change of basis applies at every level of the hierarchy).
Eigen::Vector3d convert_position(const Eigen::Vector3d& p, CoordFrame frame);
Eigen::Quaterniond convert_rotation(const Eigen::Quaterniond& q, CoordFrame frame);

}  // namespace octocap::internal
