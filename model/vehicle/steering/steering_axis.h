#pragma once
/// @file
/// The one room for the moment about a steered wheel's steering (kingpin) axis from its tire's
/// contact forces (sec. 2.2): the aligning torque (pneumatic trail n(s_y) of model/tire), the
/// caster trail's moment of F_y, and - with the steering-axis geometry - the jacking torque of
/// F_z, the scrub radius' moment of F_x and the tire's bore torque. Both steering models load
/// their tie rods with it: the simple one by virtual work at the rack, the enhanced one on the
/// knuckle.

#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

/// One wheel's contact forces and torques, in its wheel frame (x forward along the wheel, y left,
/// z up) [N, N m].
struct SteeringAxisLoads {
  double long_force_n = 0;  ///< F_x
  double lat_force_n = 0;   ///< F_y
  double load_n = 0;        ///< F_z (>= 0)
  double aligning_nm = 0;   ///< the tire's self-aligning torque about the contact normal
  double bore_nm = 0;       ///< the tire's bore torque about the contact normal
};

/// The moment about the steering axis, positive steering the wheel left (raising its steer
/// angle) [N m]. side: +1 left wheel, -1 right wheel (the geometry is mirrored).
[[nodiscard]] double steering_axis_moment_nm(const AxleParams& axle, const SteeringAxisLoads& loads,
                                             double steer_rad, int side) noexcept;

}  // namespace rig::model::vehicle
