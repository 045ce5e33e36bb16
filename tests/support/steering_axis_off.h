#pragma once
/// @file
/// A vehicle whose steered wheels turn about vertical axes through their contact centres and whose
/// tires have no bore torque: the steering-axis geometry of issue 15 (caster angle, kingpin
/// inclination, scrub radius, spindle offset) and the bore torque off, the caster trail kept. For
/// tests whose hand formulas know only the trails' moments (the aligning torque and the caster
/// trail's F_y): with the geometry the jacking torques' straight-ahead parts, equal and opposite
/// left and right, load each tie rod, and a sticking bore holds the rack at rest.

#include "model/vehicle/vehicle_params.h"

namespace rig::test {

inline void without_steering_axis(model::vehicle::AxleParams& axle) {
  axle.caster_angle_rad = axle.kingpin_inclination_rad = axle.scrub_radius_m = 0;
  axle.spindle_offset_m = 0;
  axle.tire.tmeasy.bore.enabled = false;
}

/// Every axle's geometry and bore torque off.
inline void without_steering_axis(model::vehicle::VehicleParams& p) {
  for (model::vehicle::AxleParams& axle : p.axles) without_steering_axis(axle);
}

}  // namespace rig::test
