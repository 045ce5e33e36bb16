#pragma once
/// @file
/// Contact kinematics of one wheel on the road plane z = 0 (road frame), as a function of the
/// framework state: contact point, tire axes, contact point velocity, tire penetration.
/// The hub moves along the body z axis (hub travel s, up +); the wheel steers about body z.

#include "model/vehicle/chassis_kinematics.h"

namespace rig::model::vehicle {

struct WheelContact {
  Vec3 lever_m;         ///< contact point relative to the CG, body axes (for J_P = [I, -[r]x, e_z])
  Vec3 ex, ey, normal;  ///< tire longitudinal, lateral and road normal, body axes
  Vec3 spin_axis;       ///< wheel spin axis, body axes
  double vx_mps = 0;    ///< contact point velocity along ex
  double vy_mps = 0;    ///< along ey
  double penetration_m = 0;  ///< r0 - wheel centre height (> 0 in contact)
  double penetration_rate_mps = 0;
};

/// @param mount_m wheel centre at zero hub travel, relative to the CG (body axes)
inline WheelContact wheel_contact(const Mat3& r_body_to_road, const Vec3& cg_road_m,
                                  const Vec3& v_body, const Vec3& w_body, const Vec3& mount_m,
                                  double hub_travel_m, double hub_rate_mps, double steer_rad,
                                  double radius_unloaded_m) noexcept {
  WheelContact c;
  const Vec3 centre = mount_m + Vec3(0, 0, hub_travel_m);
  const double height = cg_road_m.z() + r_body_to_road.row(2).dot(centre);
  c.normal = r_body_to_road.row(2).transpose();
  c.lever_m = centre - height * c.normal;
  c.spin_axis = Vec3(-std::sin(steer_rad), std::cos(steer_rad), 0);
  c.ex = c.spin_axis.cross(c.normal).normalized();
  c.ey = c.normal.cross(c.ex);
  const Vec3 vp = v_body + w_body.cross(c.lever_m) + Vec3(0, 0, hub_rate_mps);
  c.vx_mps = c.ex.dot(vp);
  c.vy_mps = c.ey.dot(vp);
  c.penetration_m = radius_unloaded_m - height;
  c.penetration_rate_mps = -c.normal.dot(vp);
  return c;
}

/// Vertical tire force from deflection with lift-off (never pulls).
inline double vertical_tire_force_n(double penetration_m, double penetration_rate_mps,
                                    double stiffness_npm, double damping_nspm) noexcept {
  if (penetration_m <= 0) return 0.0;
  const double f = stiffness_npm * penetration_m + damping_nspm * penetration_rate_mps;
  return f > 0 ? f : 0.0;
}

/// TMeasy dynamic rolling radius r_D = 2/3 r0 + 1/3 r_S.
inline double dynamic_radius_m(double radius_unloaded_m, double penetration_m) noexcept {
  return radius_unloaded_m - (penetration_m > 0 ? penetration_m : 0.0) / 3.0;
}

}  // namespace rig::model::vehicle
