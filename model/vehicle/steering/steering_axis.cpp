#include "model/vehicle/steering/steering_axis.h"

namespace rig::model::vehicle {

double steering_axis_moment_nm(const AxleParams& axle, const SteeringAxisLoads& loads,
                               double steer_rad, int side) noexcept {
  (void)steer_rad;
  (void)side;
  // M = M_z - caster trail F_y: the kingpin axis meets the ground the caster trail ahead of the
  // contact centre, so F_y acts on the lever n + trail (Rill 2011, sec. 3.4.3)
  return loads.aligning_nm - axle.caster_trail_m * loads.lat_force_n;
}

}  // namespace rig::model::vehicle
