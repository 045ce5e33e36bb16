#pragma once
/// @file
/// The quarter car's tire: the TMeasy tire of model/tire (eqs. 14-26) at the quarter car's
/// constant wheel load, longitudinal only (v_y = 0, y_e = 0), with the partial derivatives the
/// solver needs.

#include "model/tire/tmeasy_dual_law.h"

namespace rig::model::paper {

/// Deflection rate, force and partials of the longitudinal first-order tire model at one state.
struct TireLongitudinalState {
  double deflection_rate_mps = 0;  ///< x_e', eq. (24) (0 when limited, eq. 26)
  double force_n = 0;              ///< F_x = c_x x_e + d_x x_e' (eq. 22), or F_xM sign(x_e)
  bool limited = false;            ///< eq. (26) active
  double d_rate_d_deflection = 0;  ///< d x_e' / d x_e      [1/s]
  double d_force_d_speed = 0;      ///< d F_x / d v_x       [N s/m]
  double d_force_d_spin = 0;       ///< d F_x / d omega     [N s]
  double rolling_torque_nm = 0;    ///< T_R on the wheel (opposes the spin)
  double d_rolling_torque_d_spin = 0;
};

class QuarterCarTire {
 public:
  /// @param wheel_load_n F_z; @param radius_m dynamic rolling radius r_D.
  QuarterCarTire(const tire::TmeasyParams& params, double wheel_load_n, double radius_m);

  [[nodiscard]] double wheel_load_n() const noexcept { return wheel_load_n_; }
  /// F_xM at the wheel load (the limit of eq. 26).
  [[nodiscard]] double max_force_n() const noexcept;

  /// Eq. (24)/(26) at deflection x_e, contact point speed v_x and wheel spin omega.
  [[nodiscard]] TireLongitudinalState evaluate(double deflection_m, double speed_mps,
                                               double spin_radps) const noexcept;
  /// Eq. (26) after the implicit update: |c_x x_e| <= F_xM.
  [[nodiscard]] double limit_deflection(double deflection_m) const noexcept;

 private:
  tire::legacy::TmeasyTire tire_;
  double wheel_load_n_;
  double radius_m_;
  // The last evaluation: the solver asks for rate and Jacobian (and forces and their partials)
  // at the same state, so one TMeasy evaluation serves both.
  mutable double cached_x_e_ = 0, cached_v_ = 0, cached_w_ = 0;
  mutable bool cache_valid_ = false;
  mutable TireLongitudinalState cached_{};
};

}  // namespace rig::model::paper
