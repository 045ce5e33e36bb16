#pragma once
/// @file
/// The paper's quarter car (eq. 9) with first-order tire dynamics (eq. 24) on a grade, stepped by
/// the modified implicit Euler:
///   force element:  s = (x_e, y_e) (tire deflection; y_e stays 0), model/tire's TMeasy force
///                   element: eq. (24) with the limiter of eq. (26);
///   framework:      y = [x, phi], z = [v, omega],  m v' = F_x - m g sin(alpha),
///                   Theta omega' = T_drive - T_brake - r F_x,
///   with F_x = c_x x_e + d_x x_e'(x_e, v, omega) (eq. 22), whose partial derivatives with
///   respect to v and omega are the stiff part of M_VI.
/// The brake is dry friction handled implicitly (method.md sec. 6): after the framework's z^u
/// and mu_b = M_VI^-1 e_omega are known, the torque that stops the wheel at t + h is
/// T = -(omega + h z^u_omega) / (h mu_b,omega); within the limit it is applied exactly (stick),
/// else the limit against the motion (slip). The same structure as the constraint coupling of
/// eq. (45) with a bounded multiplier.

#include "model/paper/quarter_car_params.h"
#include "model/paper/quarter_car_tire.h"
#include "model/solver/force_element_stepper.h"
#include "model/solver/mechanical_block.h"
#include "model/solver/mechanical_stepper.h"
#include "model/tire/tmeasy_force_element.h"

namespace rig::model::paper {

/// Vehicle + wheel on the grade: y = [x, phi], z = [v, omega] (K = I).
class QuarterCarBody final : public solver::MechanicalBlock<2> {
 public:
  /// y, z: the framework states (owned by the caller); deflection: the tire's x_e.
  QuarterCarBody(const QuarterCarParams& params, const QuarterCarTire& tire, Vector& y, Vector& z,
                 const Eigen::Vector2d& deflection);
  [[nodiscard]] Eigen::Index size() const noexcept override { return 2; }
  [[nodiscard]] Vector& coordinates() noexcept override { return y_; }
  [[nodiscard]] Vector& speeds() noexcept override { return z_; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;

  void set_drive_torque_nm(double t) noexcept { drive_torque_nm_ = t; }

 private:
  QuarterCarParams params_;
  const QuarterCarTire& tire_;
  Vector& y_;
  Vector& z_;
  const Eigen::Vector2d& deflection_;
  double drive_torque_nm_ = 0;
};

/// The quarter car simulation. Construction allocates nothing but is not copyable (blocks refer
/// to each other); step() never allocates.
class QuarterCar {
 public:
  explicit QuarterCar(const QuarterCarParams& params = {});
  QuarterCar(const QuarterCar&) = delete;
  QuarterCar& operator=(const QuarterCar&) = delete;

  /// One step of size h with the given inputs (held over the step).
  void step(double h, const QuarterCarInputs& inputs) noexcept;

  /// The integrated states (plain data), e.g. to roll back a step that went non-finite.
  struct State {
    double time_s = 0, position_m = 0, wheel_angle_rad = 0, speed_mps = 0, spin_radps = 0,
           deflection_m = 0;
  };
  [[nodiscard]] State state() const noexcept;
  void set_state(const State& state) noexcept;

  [[nodiscard]] double time_s() const noexcept { return time_s_; }
  [[nodiscard]] double position_m() const noexcept { return y_(0); }
  [[nodiscard]] double speed_mps() const noexcept { return z_(0); }
  [[nodiscard]] double wheel_speed_radps() const noexcept { return z_(1); }
  [[nodiscard]] double deflection_m() const noexcept { return deflection_(0); }
  /// F_x (eq. 22) at the current state [N].
  [[nodiscard]] double tire_force_n() const noexcept;
  /// The wheel load F_z = m g cos(alpha) [N].
  [[nodiscard]] double wheel_load_n() const noexcept { return tire_.wheel_load_n(); }
  /// Longitudinal acceleration over the last step [m/s^2].
  [[nodiscard]] double acceleration_mps2() const noexcept { return acceleration_mps2_; }
  [[nodiscard]] double drive_torque_nm() const noexcept { return drive_torque_nm_; }
  /// Brake torque applied in the last step, opposing positive wheel spin when positive [N m].
  [[nodiscard]] double brake_torque_nm() const noexcept { return brake_torque_nm_; }
  /// True if the brake held the wheel (stick) in the last step.
  [[nodiscard]] bool brake_sticking() const noexcept { return brake_sticking_; }
  [[nodiscard]] const QuarterCarParams& params() const noexcept { return params_; }

 private:
  QuarterCarParams params_;
  QuarterCarTire tire_;
  Eigen::Vector2d deflection_ = Eigen::Vector2d::Zero();  ///< x_e, y_e
  Eigen::Vector2d y_ = Eigen::Vector2d::Zero();           ///< [x, phi]
  Eigen::Vector2d z_ = Eigen::Vector2d::Zero();           ///< [v, omega]
  tire::TireContact contact_{};                           ///< of the step's start
  tire::TmeasyForceElement tire_element_;
  QuarterCarBody body_;
  solver::ForceElementStepper<2> tire_stepper_;
  solver::MechanicalStepper<2> body_stepper_;
  Eigen::Vector2d brake_direction_ = Eigen::Vector2d(0.0, -1.0);  ///< generalized brake force
  Eigen::Vector2d brake_response_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d extra_rate_ = Eigen::Vector2d::Zero();
  double time_s_ = 0;
  double acceleration_mps2_ = 0;
  double drive_torque_nm_ = 0;
  double brake_torque_nm_ = 0;
  bool brake_sticking_ = false;
};

}  // namespace rig::model::paper
