#pragma once
/// @file
/// The TMeasy tire with first-order deflection dynamics (method.md sec. 3, eqs. 14-26): steady
/// state forces (eqs. 16-17), the deflection rates x_e', y_e' (eq. 24 and its lateral twin),
/// stand-still and locked-wheel behaviour (eq. 25), the stick-slip limiter (eq. 26), rolling
/// resistance and self-aligning torque, and the partial derivatives the solver needs.
///
/// Use as a force element (method.md eq. 8, first line): the states are s = (x_e, y_e); the rate
/// is f = (x_e', y_e') = TireOutput::deflection_rate, df/ds = TireOutput::d_rate_d_deflection
/// (diagonal); the forces go into the framework's q and their partials into M_VI.
///
/// Frames: the inputs are given in the wheel's ground frame at the contact point: x along the
/// wheel's heading in the road plane, y lateral (to the left), z along the road normal. Positive
/// F_x drives the vehicle forward; F_y is the lateral force on the wheel in that frame.

#include <Eigen/Core>

#include "model/tire/tmeasy_params.h"

namespace rig::model::tire::legacy {

/// Per-call inputs of the tire (kinematics from the framework, load from the vertical force).
struct TireInput {
  double long_speed_mps = 0;    ///< v_x: contact point velocity along the wheel heading
  double lat_speed_mps = 0;     ///< v_y: contact point velocity lateral
  double spin_radps = 0;        ///< omega: wheel spin rate about its axle
  double rolling_radius_m = 0;  ///< r_D: dynamic rolling radius (see dynamic_rolling_radius())
  double load_n = 0;            ///< F_z: wheel load; F_z <= 0 means lift-off
  double friction = 1.0;        ///< mu of the road at the contact point
};

/// The tire's states s = (x_e, y_e): longitudinal and lateral deflection of the contact patch.
struct TireDeflection {
  double long_m = 0;  ///< x_e [m]
  double lat_m = 0;   ///< y_e [m]
};

/// Index of the inputs in the partial-derivative matrices of TireOutput.
enum TirePartial : int {
  kByLongSpeed = 0,       ///< d/dv_x
  kByLatSpeed = 1,        ///< d/dv_y
  kBySpin = 2,            ///< d/domega
  kByLoad = 3,            ///< d/dF_z
  kByLongDeflection = 4,  ///< d/dx_e
  kByLatDeflection = 5,   ///< d/dy_e
  kTirePartialCount = 6
};

/// Everything a tire evaluation produces. Partials are exact derivatives of the smooth branch
/// that is active (limiter and lift-off branches are piecewise constant in the inputs).
struct TireOutput {
  double long_force_n = 0;        ///< F_x = c_x x_e + d_x x_e' (eq. 22), or F_xM sign(F_x) (eq. 26)
  double lat_force_n = 0;         ///< F_y = c_y y_e + d_y y_e', or F_yM sign(F_y)
  double aligning_torque_nm = 0;  ///< M_z = -n F_y (pneumatic trail n)
  double rolling_torque_nm = 0;   ///< T_R about the wheel axle, opposes omega; add to the wheel's
                                  ///< spin equation: Theta omega' = T - r_D F_x + T_R
  Eigen::Vector2d deflection_rate = Eigen::Vector2d::Zero();  ///< (x_e', y_e'): eq. (24), twin
  /// df/ds of the force element: d x_e'/d x_e, d y_e'/d y_e (the rates are decoupled in s).
  Eigen::Vector2d d_rate_d_deflection = Eigen::Vector2d::Zero();
  /// d(x_e', y_e')/d(v_x, v_y, omega, F_z, x_e, y_e), columns indexed by TirePartial.
  Eigen::Matrix<double, 2, kTirePartialCount> d_rate = Eigen::Matrix<double, 2, 6>::Zero();
  /// d(F_x, F_y)/d(v_x, v_y, omega, F_z, x_e, y_e): the stiff damping paths through d_x, d_y
  /// (dF_x/dv_x, dF_x/domega, dF_y/dv_y) that M_VI needs, and dF/dF_z.
  Eigen::Matrix<double, 2, kTirePartialCount> d_force = Eigen::Matrix<double, 2, 6>::Zero();
  double d_rolling_torque_d_spin = 0;  ///< dT_R/domega [N m s]
  bool long_limited = false;           ///< eq. (26) active longitudinally
  bool lat_limited = false;            ///< eq. (26) active laterally
  bool lifted_off = false;             ///< F_z <= 0: no forces, the deflections relax
};

/// Steady-state TMeasy forces (eqs. 14-17), without deflection dynamics.
struct SteadyStateForces {
  double long_force_n = 0;          ///< F_x^S = f(s) s_x^N
  double lat_force_n = 0;           ///< F_y^S = f(s) s_y^N
  double long_slip_normalized = 0;  ///< s_x^N, eq. (14)
  double lat_slip_normalized = 0;   ///< s_y^N, eq. (15)
  double generalized_slip = 0;      ///< s
  double f_n = 0;                   ///< f(s) = F(s)/s
};

/// A TMeasy tire: holds its parameters (copied), evaluates without allocation, noexcept.
class TmeasyTire {
 public:
  explicit TmeasyTire(const TmeasyParams& params = default_215_55_r18()) noexcept;

  [[nodiscard]] const TmeasyParams& params() const noexcept { return params_; }

  /// Steady-state forces of eqs. (14-17) at the given inputs (zero if F_z <= 0).
  [[nodiscard]] SteadyStateForces steady_state(const TireInput& in) const noexcept;

  /// Eq. (24) and its lateral twin with the stand-still / locked-wheel behaviour (eq. 25), the
  /// limiter (eq. 26), rolling resistance, aligning torque and all partials, at deflection s.
  /// Lift-off (F_z <= 0) or mu <= 0: forces zero and x_e' = -(c_x/d_x) x_e (the free spring-
  /// damper relaxes with zero force), likewise y_e.
  void evaluate(const TireInput& in, const TireDeflection& deflection,
                TireOutput& out) const noexcept;

  /// Maximum longitudinal / lateral force F_xM, F_yM at load F_z and friction mu (the limits of
  /// eq. 26); 0 if F_z <= 0.
  [[nodiscard]] double max_long_force_n(double load_n, double friction) const noexcept;
  [[nodiscard]] double max_lat_force_n(double load_n, double friction) const noexcept;

  /// Eq. (26) applied after the implicit update (ForceElement::after_update): a deflection whose
  /// spring force alone exceeds the limit is clamped to F_M / c (x_e' = 0 then holds F at F_M).
  void clamp_deflection(double load_n, double friction, TireDeflection& deflection) const noexcept;

 private:
  TmeasyParams params_;
};

}  // namespace rig::model::tire::legacy
