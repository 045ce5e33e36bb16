#include "model/vehicle/steering/steering_axis.h"

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rig::model::vehicle {
namespace {

using Vec3 = Eigen::Vector3d;

/// The left wheel's axis direction e and ground point G relative to C (steering_axis.h).
struct Axis {
  Vec3 e;
  Vec3 ground;
};
Axis left_axis(const AxleParams& a) noexcept {
  const Vec3 e =
      Vec3(-std::tan(a.caster_angle_rad), -std::tan(a.kingpin_inclination_rad), 1.0).normalized();
  return {e, Vec3(a.caster_trail_m, -a.scrub_radius_m, 0.0)};
}

/// z' of a vector v rotated by psi about e (Rodrigues), and its z at psi.
struct RotatedZ {
  double z = 0, dz = 0;
};
RotatedZ rotated_z(const Vec3& e, const Vec3& v, double psi) noexcept {
  const double c = std::cos(psi), s = std::sin(psi);
  const double exv_z = e.x() * v.y() - e.y() * v.x();
  const double ev = e.dot(v);
  return {v.z() * c + exv_z * s + e.z() * ev * (1.0 - c), -v.z() * s + exv_z * c + e.z() * ev * s};
}

}  // namespace

double jacking_torque_left_nm(const AxleParams& axle, double load_n, double wheel_radius_m,
                              double steer_rad) noexcept {
  const Axis ax = left_axis(axle);
  const RotatedZ w = rotated_z(ax.e, Vec3(0.0, 0.0, wheel_radius_m) - ax.ground, steer_rad);
  const RotatedZ a = rotated_z(ax.e, Vec3::UnitY(), steer_rad);
  // the disc's lowest point: h = W_z - R sqrt(1 - a_z^2); M = F_z dh/dpsi
  const double dh = w.dz + wheel_radius_m * a.z * a.dz / std::sqrt(1.0 - a.z * a.z);
  return load_n * dh;
}

double steering_axis_moment_nm(const AxleParams& axle, const SteeringAxisLoads& loads,
                               double steer_rad, int side) noexcept {
  if (axle.caster_angle_rad == 0.0 && axle.kingpin_inclination_rad == 0.0 &&
      axle.scrub_radius_m == 0.0) {
    // M = M_z - caster trail F_y: the kingpin axis meets the ground the caster trail ahead of
    // the contact centre, so F_y acts on the lever n + trail (Rill 2011, sec. 3.4.3); the
    // vertical axis through the contact gives no jacking and no F_x moment
    double m = loads.aligning_nm - axle.caster_trail_m * loads.lat_force_n;
    if (loads.bore_nm != 0.0) m += loads.bore_nm;  // (today's results bit for bit without it)
    return m;
  }
  // the left wheel's geometry on mirrored loads (y, steer and moments about z flip sign)
  const double sd = static_cast<double>(side);
  const Axis ax = left_axis(axle);
  const Vec3 arm = -ax.ground;  // C - G
  const Vec3 force(loads.long_force_n, sd * loads.lat_force_n, 0.0);
  const double contact = ax.e.dot(arm.cross(force)) +
                         ax.e.z() * sd * (loads.aligning_nm + loads.bore_nm) +
                         ax.e.y() * loads.shaft_torque_nm;  // e.a T_s, a = e_y
  const double jack =
      jacking_torque_left_nm(axle, loads.load_n, loads.wheel_radius_m, sd * steer_rad);
  return sd * (contact + jack);
}

}  // namespace rig::model::vehicle
