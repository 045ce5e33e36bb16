#pragma once
/// @file
/// The start pose on a road with a surface (model/road/surface.h): the vehicle put at rest on
/// the road's height and slope where it starts. The plane fitted (least squares) through the
/// ground under the wheels' design positions gives the CG's height (cg_height along the plane's
/// normal above it) and the body's pitch and roll (its z axis along that normal). On the plane
/// road nothing changes (its grade and bank tilt gravity instead). Allocation-free.

#include "model/vehicle/vehicle_framework.h"
#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

/// The ground plane under the vehicle at the pose of `s` (x, y, yaw), road frame: z = z0 + a
/// (X - x) + b (Y - y).
struct GroundPlane {
  double z0_m = 0;
  double dz_dx = 0;  ///< a
  double dz_dy = 0;  ///< b
};
[[nodiscard]] GroundPlane ground_under(const VehicleFramework& f, double x_m, double y_m,
                                       double yaw_rad) noexcept;

/// Sets z, pitch and roll of `s` (at rest at the design position, place_at_rest) so that the
/// vehicle stands on the ground under it; a road without a surface leaves `s` as it is.
void place_on_road(VehicleState& s, const VehicleParams& p, const VehicleFramework& f) noexcept;

}  // namespace rig::model::vehicle
