#include "model/paper/quarter_car_tire.h"

namespace rig::model::paper {

QuarterCarTire::QuarterCarTire(const tire::TmeasyParams& params, double wheel_load_n,
                               double radius_m)
    : params_(params),
      wheel_load_n_(wheel_load_n),
      radius_m_(radius_m),
      characteristic_(tire::characteristic_at(params, wheel_load_n, 1.0)) {}

tire::TireContact QuarterCarTire::contact(double speed_mps, double spin_radps) const noexcept {
  tire::TireContact c;
  c.characteristic = characteristic_;
  c.kinematics = {speed_mps, 0.0, spin_radps, radius_m_};
  const tire::TireSlip slip =
      tire::slip_of(characteristic_, c.kinematics, params_.velocity_floor_mps);
  c.f_per_slip = slip.f_per_slip;
  c.sliding_ratio = slip.sliding_ratio;
  return c;
}

TireLongitudinalState QuarterCarTire::evaluate(double x_e, double v, double w) const noexcept {
  const tire::TireContact c = contact(v, w);
  const Eigen::Vector2d s(x_e, 0.0);
  const tire::DeflectionDynamics d =
      tire::deflection_dynamics(params_, characteristic_, c.kinematics, c.f_per_slip, s);
  const tire::TireForces f = tire::limited_forces(params_, characteristic_, c.sliding_ratio, s, d);
  TireLongitudinalState st;
  st.force_n = f.long_force_n;
  st.limited = f.limited;
  // the whole force linearized (the paper's large steps need the slope of f(s) too)
  const tire::TireForcePartials partials =
      tire::tire_force_partials(params_, characteristic_, c.kinematics, s);
  st.d_force_d_speed = partials.d_force(0, 0);
  st.d_force_d_spin = partials.d_force(0, 2);
  return st;
}

}  // namespace rig::model::paper
