#include "model/vehicle/rigid_axle.h"

#include <cmath>

namespace rig::model::vehicle {

RigidAxleGeometry rigid_axle_geometry(const AxleParams& a, double cg_height_m,
                                      const Vec3& left_centre_m,
                                      const Vec3& right_centre_m) noexcept {
  RigidAxleGeometry g;
  g.roll_centre_m = Vec3(a.position_x_m, 0.0, a.rigid.roll_centre_height_m - cg_height_m);
  g.wheel_from_centre_m = {left_centre_m - g.roll_centre_m, right_centre_m - g.roll_centre_m};
  g.half_track_m = 0.5 * a.track_m;
  // the wheels' point masses (half the axle's mass each, at +-track/2) already carry
  // m (track/2)^2 of the roll inertia about the axle's centre
  g.extra_roll_inertia_kgm2 =
      a.rigid.roll_inertia_kgm2 - a.rigid.mass_kg * g.half_track_m * g.half_track_m;
  return g;
}

RigidWheelPoint rigid_wheel_point(const RigidAxleGeometry& g, int side, double heave_m,
                                  const SinCos& roll) noexcept {
  const Vec3& d0 = g.wheel_from_centre_m[static_cast<std::size_t>(side)];
  const double c = roll.cos, s = roll.sin;
  RigidWheelPoint w;
  w.from_axis_m = Vec3(d0.x(), c * d0.y() - s * d0.z(), s * d0.y() + c * d0.z());
  w.centre_m = g.roll_centre_m + w.from_axis_m;
  w.centre_m.z() += heave_m;
  w.d_droll_m = Vec3(0.0, -w.from_axis_m.z(), w.from_axis_m.y());  // e_x x from_axis
  return w;
}

SpringDamperAxleSuspension::SpringDamperAxleSuspension(const AxleParams& a, double preload_left_n,
                                                       double preload_right_n)
    : stiffness_npm_(a.spring_stiffness_npm),
      stop_stiffness_npm_(a.stop_stiffness_npm),
      bump_stop_m_(a.bump_stop_travel_m),
      rebound_stop_m_(a.rebound_stop_travel_m),
      damper_bump_nspm_(a.damper_bump_nspm),
      damper_rebound_nspm_(a.damper_rebound_nspm),
      spring_half_track_m_(0.5 * a.rigid.spring_track_m),
      damper_half_track_m_(0.5 * a.rigid.damper_track_m),
      bar_nmprad_(a.rigid.anti_roll_stiffness_nmprad),
      preload_n_{preload_left_n, preload_right_n} {}

void SpringDamperAxleSuspension::forces(double heave_m, double roll_rad, double heave_rate_mps,
                                        double roll_rate_radps,
                                        AxleSuspensionForces& out) const noexcept {
  out.q.setZero();
  out.dq_dy.setZero();
  out.dq_dz.setZero();
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? 1.0 : -1.0;
    // spring and stops on the spring's travel; a force F (compression +) pushes the axle down:
    // q -= F d(travel)/d(h, phi) with d(travel)/d(h, phi) = (1, +-spring_track/2)
    const Eigen::Vector2d ds(1.0, sign * spring_half_track_m_);
    const double travel = ds.dot(Eigen::Vector2d(heave_m, roll_rad));
    double force = preload_n_[static_cast<std::size_t>(side)] + stiffness_npm_ * travel;
    double rate = stiffness_npm_;
    if (travel > bump_stop_m_) {
      force += stop_stiffness_npm_ * (travel - bump_stop_m_);
      rate += stop_stiffness_npm_;
    } else if (travel < -rebound_stop_m_) {
      force += stop_stiffness_npm_ * (travel + rebound_stop_m_);
      rate += stop_stiffness_npm_;
    }
    out.spring_n[static_cast<std::size_t>(side)] = force;
    out.q -= force * ds;
    out.dq_dy.noalias() -= (rate * ds) * ds.transpose();
    // damper on its own track, bump and rebound rates
    const Eigen::Vector2d dd(1.0, sign * damper_half_track_m_);
    const double speed = dd.dot(Eigen::Vector2d(heave_rate_mps, roll_rate_radps));
    const double c = speed > 0 ? damper_bump_nspm_ : damper_rebound_nspm_;
    out.q -= (c * speed) * dd;
    out.dq_dz.noalias() -= (c * dd) * dd.transpose();
  }
  out.q(1) -= bar_nmprad_ * roll_rad;
  out.dq_dy(1, 1) -= bar_nmprad_;
}

}  // namespace rig::model::vehicle
