#pragma once
/// @file
/// The longitudinal tire of the quarter car: TMeasy steady state (eqs. 14-17) at the constant
/// wheel load of the quarter car, the deflection dynamics of eq. (24) and the limiter of
/// eq. (26), with the partial derivatives the solver needs.

namespace rig::model::examples {

/// Deflection rate and force of the longitudinal first-order tire model at one state.
struct TireLongitudinalState {
  double deflection_rate_mps = 0;  ///< x_e', eq. (24) (0 when limited, eq. 26)
  double force_n = 0;              ///< F_x = c_x x_e + d_x x_e' (eq. 22), or F_xM sign(x_e)
  bool limited = false;            ///< eq. (26) active
  double d_rate_d_deflection = 0;  ///< d x_e' / d x_e      [1/s]
  double d_rate_d_speed = 0;       ///< d x_e' / d v_x      [-]
  double d_rate_d_spin = 0;        ///< d x_e' / d omega    [m]
};

class QuarterCarTire {
 public:
  /// @param wheel_load_n F_z; @param radius_m dynamic rolling radius r_D.
  QuarterCarTire(double wheel_load_n, double radius_m);

  [[nodiscard]] double wheel_load_n() const noexcept { return wheel_load_n_; }
  [[nodiscard]] double max_force_n() const noexcept;
  [[nodiscard]] double stiffness_npm() const noexcept;

  /// Eq. (24)/(26) at deflection x_e, contact point speed v_x and wheel spin omega, with the
  /// partial derivatives (at fixed limiter state).
  [[nodiscard]] TireLongitudinalState evaluate(double deflection_m, double speed_mps,
                                               double spin_radps) const noexcept;
  /// Eq. (26) applied to a state after the implicit update: the deflection whose spring force
  /// alone exceeds F_xM is clamped to F_xM / c_x (then x_e' = 0 holds the force at F_xM).
  [[nodiscard]] double limit_deflection(double deflection_m) const noexcept;

 private:
  double wheel_load_n_;
  double radius_m_;
};

}  // namespace rig::model::examples
