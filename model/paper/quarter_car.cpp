#include "model/paper/quarter_car.h"

#include <algorithm>
#include <cmath>

namespace rig::model::paper {

QuarterCarInputs paper_maneuver_inputs(double t_s) noexcept {
  QuarterCarInputs in;
  in.drive_torque_nm = (t_s >= 0.0 && t_s < 6.0) ? 1000.0 : 0.0;
  if (t_s >= 8.0 && t_s < kPaperBrakeRelease_s) {
    in.brake_torque_limit_nm = 1500.0 * std::min(1.0, (t_s - 8.0) / 0.5);
  }
  return in;
}

// ---- framework: eq. (9) on the grade ----
QuarterCarBody::QuarterCarBody(const QuarterCarParams& params, const QuarterCarTire& tire,
                               Vector& y, Vector& z, const Eigen::Vector2d& deflection)
    : params_(params), tire_(tire), y_(y), z_(z), deflection_(deflection) {}

void QuarterCarBody::mass_matrix(const Vector&, Matrix& m) const noexcept {
  m << params_.mass_kg, 0.0, 0.0, params_.wheel_inertia_kgm2;
}

void QuarterCarBody::applied_forces(const Vector&, const Vector& z, Vector& q) const noexcept {
  const double sin_alpha = params_.grade / std::sqrt(1.0 + params_.grade * params_.grade);
  const TireLongitudinalState st = tire_.evaluate(deflection_(0), z(0), z(1));
  q(0) = st.force_n - params_.mass_kg * params_.gravity_mps2 * sin_alpha;  // eq. (9) + grade
  q(1) = drive_torque_nm_ - params_.wheel_radius_m * st.force_n;
}

bool QuarterCarBody::force_jacobians(const Vector&, const Vector& z, Matrix& dq_dy,
                                     Matrix& dq_dz) const noexcept {
  // F_x = c x_e + d x_e'(x_e, v, omega): the stiff dependence on the speeds (eq. 22, 24)
  const TireLongitudinalState st = tire_.evaluate(deflection_(0), z(0), z(1));
  const double dfx_dv = st.d_force_d_speed;
  const double dfx_dw = st.d_force_d_spin;
  const double r = params_.wheel_radius_m;
  dq_dy.setZero();
  dq_dz << dfx_dv, dfx_dw, -r * dfx_dv, -r * dfx_dw;
  return true;
}

// ---- the assembled quarter car ----
QuarterCar::QuarterCar(const QuarterCarParams& params)
    : params_(params),
      tire_(params.tire,
            params.mass_kg * params.gravity_mps2 / std::sqrt(1.0 + params.grade * params.grade),
            params.wheel_radius_m),
      tire_element_(tire_.params(), contact_, deflection_),
      body_(params_, tire_, y_, z_, deflection_),
      tire_stepper_(tire_element_),
      body_stepper_(body_) {}

QuarterCar::State QuarterCar::state() const noexcept {
  return {time_s_, y_(0), y_(1), z_(0), z_(1), deflection_(0)};
}

void QuarterCar::set_state(const State& state) noexcept {
  time_s_ = state.time_s;
  y_ << state.position_m, state.wheel_angle_rad;
  z_ << state.speed_mps, state.spin_radps;
  deflection_ << state.deflection_m, 0.0;
}

double QuarterCar::tire_force_n() const noexcept {
  return tire_.evaluate(deflection_(0), z_(0), z_(1)).force_n;
}

void QuarterCar::step(double h, const QuarterCarInputs& inputs) noexcept {
  const double v_old = z_(0);
  drive_torque_nm_ = inputs.drive_torque_nm;
  body_.set_drive_torque_nm(inputs.drive_torque_nm);
  // eq. (8): force element first (at the contact of the step's start), then the framework with
  // the new deflection
  contact_ = tire_.contact(z_(0), z_(1));
  tire_stepper_.advance(h);
  body_stepper_.begin_step(h);
  // Dry-friction brake, implicit (method.md sec. 6): the brake torque T acts on the wheel as the
  // generalized force e_b T with e_b = [0, -1]; its response is mu_b = M_VI^-1 e_b. Stick if the
  // torque that makes omega(k+1) = 0 is within the limit.
  body_stepper_.solve_mass(brake_direction_, brake_response_);
  const double omega_free = z_(1) + h * body_stepper_.unconstrained_rate()(1);
  const double limit = std::max(0.0, inputs.brake_torque_limit_nm);
  const double torque_to_stop = -omega_free / (h * brake_response_(1));
  brake_sticking_ = limit > 0.0 && std::abs(torque_to_stop) <= limit;
  brake_torque_nm_ = std::clamp(torque_to_stop, -limit, limit);
  extra_rate_ = brake_response_ * brake_torque_nm_;
  body_stepper_.finish_step(h, extra_rate_);
  if (brake_sticking_) z_(1) = 0.0;  // exact stick (removes the round-off of the solve)
  acceleration_mps2_ = (z_(0) - v_old) / h;
  time_s_ += h;
}

}  // namespace rig::model::paper
