#pragma once
/// @file
/// The in-plane hold of a combination's settle (CombinationShell::settle, vehicle_equilibrium.h):
/// after each settling step every unit runs at the speed with no yaw rate, the leading unit with
/// no lateral speed at its CG, each trailing unit with the lateral speed that keeps its joint
/// point moving with the leading unit's. Holding every CG at lateral speed 0 instead breaks the
/// joint's velocity constraint whenever the units roll (the joint point sits at another height
/// above each unit's CG: it moves sideways at roll rate x height in each); the next step's joint
/// force then pumps the chain's roll mode, and with the cab tractor's suspended cab the settle
/// diverged (stop 28: the 40 t combination settled rolled 0.016 rad, its cab 60 mm aside).
#include <memory>
#include <vector>

#include "model/combination/joint.h"
#include "model/vehicle/vehicle_model.h"

namespace rig::model::combination {

/// The lateral speed (body axes) of unit b's CG for which b's joint point moves sideways (road
/// frame) as fast as a's, b's other speeds as they are. Points in each unit's body axes from
/// its CG (JointParams::leading_point_m, trailing_point_m).
[[nodiscard]] double joint_following_lateral_speed_mps(const vehicle::VehicleState& a,
                                                       const Vec3& point_a,
                                                       const vehicle::VehicleState& b,
                                                       const Vec3& point_b) noexcept;

/// The hold above on the chain (units[i] and units[i+1] joined by joints[i]), front to back.
void hold_in_line(std::vector<std::unique_ptr<vehicle::VehicleModel>>& units,
                  const std::vector<JointParams>& joints, double speed_mps) noexcept;

}  // namespace rig::model::combination
