#pragma once
/// @file
/// The quarter car's tire: model/tire's TMeasy law (eqs. 14-26) at the quarter car's constant
/// wheel load, longitudinal only (v_y = 0, y_e = 0): the contact the force element needs, and
/// the force with the stiff partials the framework needs.

#include "model/tire/tmeasy_tire.h"

namespace rig::model::paper {

/// F_x (eq. 22, limited by eq. 26) and its partials (complete: tire_force_partials).
struct TireLongitudinalState {
  double force_n = 0;          ///< F_x = c_x x_e + d_x x_e', or +-F_xM
  bool limited = false;        ///< eq. (26) active
  double d_force_d_speed = 0;  ///< d F_x / d v_x       [N s/m]
  double d_force_d_spin = 0;   ///< d F_x / d omega     [N s]
};

class QuarterCarTire {
 public:
  /// @param wheel_load_n F_z; @param radius_m rolling radius r (the paper's r_D).
  QuarterCarTire(const tire::TmeasyParams& params, double wheel_load_n, double radius_m);

  [[nodiscard]] const tire::TmeasyParams& params() const noexcept { return params_; }
  [[nodiscard]] double wheel_load_n() const noexcept { return wheel_load_n_; }
  /// F_xM at the wheel load (the limit of eq. 26).
  [[nodiscard]] double max_force_n() const noexcept { return characteristic_.x.max_force_n; }
  /// The tire's contact at contact point speed v_x and wheel spin omega (f at that state).
  [[nodiscard]] tire::TireContact contact(double speed_mps, double spin_radps) const noexcept;
  /// Eq. (22, 26) at deflection x_e, v_x and omega.
  [[nodiscard]] TireLongitudinalState evaluate(double deflection_m, double speed_mps,
                                               double spin_radps) const noexcept;

 private:
  tire::TmeasyParams params_;
  double wheel_load_n_;
  double radius_m_;
  tire::TireCharacteristic characteristic_;  ///< at the constant load, mu = 1
};

}  // namespace rig::model::paper
