#pragma once
/// @file
/// TMeasy, the one tire law of the project (G. Rill; method.md sec. 3, eqs. 14-26). A user
/// (the vehicle, the paper's quarter car) calls it in three stages:
///   1. once per contact and step: characteristic_at(params, F_z, mu) - the curves at the wheel
///      load and road friction and the normalizing factors (the load is frozen over the step);
///   2. per evaluation: slip_of(...) - the generalized slip and f(s) = F(s)/s (eqs. 14-17);
///   3. the first-order deflection dynamics (eqs. 22-24) with f given (the caller chooses the f of
///      the start of the step for the force element's rate, or the newest for the forces):
///      deflection_rates(), tire_forces(), damping_paths(), and the stick-slip limit of eq. (26):
///      ONE elliptic limit on the combined force |(F_x/F_xM, F_y/F_yM)| <= kappa, applied to the
///      dynamic force (tire_forces) and to the spring force of the state (limit_deflection);
///      kappa = F(s)/F_M (the sliding ratio, 1 up to s_M) lets a sliding tire transmit the
///      characteristic's F(s) -> F_S instead of F_M, while at stand-still (s -> 0) the stick-slip
///      hold keeps the full F_M.
/// Frames: the wheel's ground frame at the contact point (x along the wheel heading in the road
/// plane, y lateral to the left, z along the road normal); F_x > 0 drives forward.
/// Everything is allocation-free and noexcept; the per-evaluation functions are inline so that
/// each caller compiles only what it uses.

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Core>

#include "model/tire/dual.h"
#include "model/tire/tmeasy_params.h"

namespace rig::model::tire {

/// The tire at one wheel load and road friction: the longitudinal and lateral curves (TMeasy's
/// load law, mu/mu0 scaling F_M, F_S, s_M, s_S) and the normalizing factors s^x, s^y of
/// eqs. (14-15). Lift-off (F_z <= 0) gives zero curves, s^x = s^y = 1 and so f = 0.
struct TireCharacteristic {
  TmeasyCurve x{};                      ///< longitudinal, at the load and friction
  TmeasyCurve y{};                      ///< lateral
  double normalize_x = 1;               ///< s^x
  double normalize_y = 1;               ///< s^y
  double low_speed_damping_x_nspm = 0;  ///< d_low of x at the load (TmeasyParams), at rest
  double low_speed_damping_y_nspm = 0;  ///< d_low of y
};

/// What the tire sees of the wheel's motion: the contact point's velocity in the ground frame,
/// the spin rate and the dynamic rolling radius.
struct TireKinematics {
  double long_speed_mps = 0;    ///< v_x
  double lat_speed_mps = 0;     ///< v_y
  double spin_radps = 0;        ///< omega
  double rolling_radius_m = 0;  ///< r_D
};

/// Eqs. (14-17) at one kinematic state.
struct TireSlip {
  double slip_x = 0;         ///< s_x^N (normalized, eq. 14)
  double slip_y = 0;         ///< s_y^N (eq. 15)
  double f_per_slip = 0;     ///< f(s) = F(s)/s [N], f(0) = dF0 of the slip direction
  double sliding_ratio = 1;  ///< kappa = F(s)/F_M beyond s_M (F_S/F_M at full slide), else 1
};

/// What a force element needs of the tire for one step: its characteristic and kinematics at the
/// start of the step, and f of that state (frozen over the step, eq. 24).
struct TireContact {
  TireCharacteristic characteristic{};
  TireKinematics kinematics{};
  double f_per_slip = 0;
  double sliding_ratio = 1;  ///< kappa of that state (TireSlip)
};

/// The characteristic at load F_z [N] and road friction mu (stage 1). Beyond 2 F_zN the degressive
/// load law is kept physical (no force of the wrong sign, s_S > s_M > 0).
[[nodiscard]] TireCharacteristic characteristic_at(const TmeasyParams& params, double load_n,
                                                   double friction) noexcept;

/// The generalized slip and f(s) of eqs. (14-17) with the small velocity v_N (stage 2).
[[nodiscard]] TireSlip slip_of(const TireCharacteristic& c, const TireKinematics& k,
                               double velocity_floor_mps) noexcept;

/// F(s)/s of the combined characteristic for the normalized slips (eq. 16).
[[nodiscard]] double f_per_slip_of(const TireCharacteristic& c, double slip_x,
                                   double slip_y) noexcept;
/// f(s) and the sliding ratio kappa = F(s)/F_M of the combined characteristic.
struct SlipCurveValue {
  double f_per_slip = 0;
  double sliding_ratio = 1;
};
[[nodiscard]] SlipCurveValue slip_curve_value(const TireCharacteristic& c, double slip_x,
                                              double slip_y) noexcept;

/// Steady-state forces of eqs. (16-17), F^S = f(s) s^N, at load F_z and friction mu (zero lifted
/// off): the characteristic without deflection dynamics.
struct SteadyStateForces {
  double long_force_n = 0;  ///< F_x^S
  double lat_force_n = 0;   ///< F_y^S
  TireSlip slip{};
};
[[nodiscard]] SteadyStateForces steady_state_forces(const TmeasyParams& params,
                                                    const TireKinematics& k, double load_n,
                                                    double friction) noexcept;

// ---- stage 3: eqs. (22-26) ----

/// Eq. (24) in one direction, (d r_D|w| s + f) x_e' = -f v_slip - c x_e r_D|w| s, its
/// derivative by the deflection, and the stiff damping path of the force F = c x_e + d x_e' at
/// frozen f, dF/dv_slip = -d f / (d r_D|w| s + f) (method.md sec. 6: the partial M_VI needs).
/// At stand-still (v_slip = 0, w = 0) x_e' = 0: an existing deflection, and so an existing
/// force, is held; locked (w = 0) x_e' = -v_slip (eq. 25).
/// @param slip_speed_mps v_x - r_D w (laterally v_y); @param rolling_mps r_D |w|.
struct DirectionalDynamics {
  double rate = 0;                 ///< x_e' [m/s]
  double d_rate_d_deflection = 0;  ///< dx_e'/dx_e [1/s]
  double damping_nspm = 0;         ///< -dF/dv_slip [N s/m]
};
[[nodiscard]] inline DirectionalDynamics directional_dynamics(
    double deflection_m, double slip_speed_mps, double rolling_mps, double normalize,
    double f_per_slip, double stiffness_npm, double damping_nspm) noexcept {
  const double rs = rolling_mps * normalize;
  const double denom = damping_nspm * rs + f_per_slip + 1e-9;
  return {(-f_per_slip * slip_speed_mps - stiffness_npm * deflection_m * rs) / denom,
          -stiffness_npm * rs / denom, damping_nspm * f_per_slip / denom};
}

/// The weight (1 + cos(pi |v_x| / v_low)) / 2 of the low-speed damping: 1 at rest, 0 from v_low
/// (in double, or in the dual numbers of tire_force_partials).
template <class T>
[[nodiscard]] inline T low_speed_weight(const TmeasyParams& p, const T& long_speed_mps) noexcept {
  using std::abs;
  using std::cos;
  const T a = abs(long_speed_mps);
  if (internal::value_of(a) >= p.low_speed_damping_speed_mps) return T(0.0);
  return 0.5 * (1.0 + cos(std::numbers::pi * a / p.low_speed_damping_speed_mps));
}
/// The deflection's damping d_x, d_y of eq. (22/24) with the low-speed part at v_x.
struct DeflectionDamping {
  double x_nspm = 0, y_nspm = 0;
};
[[nodiscard]] inline DeflectionDamping deflection_damping(const TmeasyParams& p,
                                                          const TireCharacteristic& c,
                                                          double long_speed_mps) noexcept {
  const double w = low_speed_weight(p, long_speed_mps);
  if (w == 0.0) return {p.longitudinal_damping_nspm, p.lateral_damping_nspm};
  return {p.longitudinal_damping_nspm + w * c.low_speed_damping_x_nspm,
          p.lateral_damping_nspm + w * c.low_speed_damping_y_nspm};
}

/// directional_dynamics() of both directions at deflection s = (x_e, y_e), with f given, and the
/// damping d_x, d_y they used (the force's, eq. 22).
struct DeflectionDynamics {
  DirectionalDynamics x{}, y{};
  DeflectionDamping damping{};
};
[[nodiscard]] inline DeflectionDynamics deflection_dynamics(const TmeasyParams& p,
                                                            const TireCharacteristic& c,
                                                            const TireKinematics& k,
                                                            double f_per_slip,
                                                            const Eigen::Vector2d& s) noexcept {
  const double rolling = k.rolling_radius_m * std::abs(k.spin_radps);
  const DeflectionDamping d = deflection_damping(p, c, k.long_speed_mps);
  return {directional_dynamics(s(0), k.long_speed_mps - k.rolling_radius_m * k.spin_radps, rolling,
                               c.normalize_x, f_per_slip, p.longitudinal_stiffness_npm, d.x_nspm),
          directional_dynamics(s(1), k.lat_speed_mps, rolling, c.normalize_y, f_per_slip,
                               p.lateral_stiffness_npm, d.y_nspm),
          d};
}

/// x_e', y_e' and their diagonal derivative at deflection s = (x_e, y_e), with f given.
struct DeflectionRates {
  Eigen::Vector2d rate = Eigen::Vector2d::Zero();
  Eigen::Vector2d d_rate_d_deflection = Eigen::Vector2d::Zero();
};
[[nodiscard]] inline DeflectionRates deflection_rates(const TmeasyParams& p,
                                                      const TireCharacteristic& c,
                                                      const TireKinematics& k, double f_per_slip,
                                                      const Eigen::Vector2d& s) noexcept {
  const DeflectionDynamics d = deflection_dynamics(p, c, k, f_per_slip, s);
  DeflectionRates r;
  r.rate << d.x.rate, d.y.rate;
  r.d_rate_d_deflection << d.x.d_rate_d_deflection, d.y.d_rate_d_deflection;
  return r;
}

/// rho = |(F_x/F_xM, F_y/F_yM)|, the elliptic measure of eq. (26): > 1 outside the ellipse of
/// the maxima. No force capacity (F_M <= 0: lifted off): infinity.
[[nodiscard]] inline double ellipse_ratio(const TireCharacteristic& c, double fx_n,
                                          double fy_n) noexcept {
  const double fxm = c.x.max_force_n, fym = c.y.max_force_n;
  if (fxm <= 0 || fym <= 0) return std::numeric_limits<double>::infinity();
  return std::sqrt((fx_n / fxm) * (fx_n / fxm) + (fy_n / fym) * (fy_n / fym));
}

/// Eq. (26) on the state, after the implicit update: a deflection whose spring force
/// (c_x x_e, c_y y_e) lies outside the ellipse, scaled by the sliding ratio kappa, is scaled back
/// onto it (no capacity: zero).
inline void limit_deflection(const TmeasyParams& p, const TireCharacteristic& c,
                             double sliding_ratio, Eigen::Vector2d& s) noexcept {
  const double rho =
      ellipse_ratio(c, p.longitudinal_stiffness_npm * s(0), p.lateral_stiffness_npm * s(1)) /
      sliding_ratio;
  if (rho == std::numeric_limits<double>::infinity()) {
    s.setZero();
  } else if (rho > 1.0) {
    s(0) /= rho;
    s(1) /= rho;
  }
}

/// The dynamic force F = c x_e + d x_e' (eq. 22 and its lateral twin) at deflection s with f
/// given, limited by eq. (26): outside the ellipse (scaled by kappa) it is scaled back onto it.
struct TireForces {
  double long_force_n = 0;
  double lat_force_n = 0;
  bool limited = false;  ///< eq. (26) active (or no capacity)
};
/// The same from the deflection dynamics d of state s.
[[nodiscard]] inline TireForces limited_forces(const TmeasyParams& p, const TireCharacteristic& c,
                                               double sliding_ratio, const Eigen::Vector2d& s,
                                               const DeflectionDynamics& d) noexcept {
  TireForces out;
  out.long_force_n = p.longitudinal_stiffness_npm * s(0) + d.damping.x_nspm * d.x.rate;
  out.lat_force_n = p.lateral_stiffness_npm * s(1) + d.damping.y_nspm * d.y.rate;
  const double rho = ellipse_ratio(c, out.long_force_n, out.lat_force_n) / sliding_ratio;
  if (rho == std::numeric_limits<double>::infinity()) {
    out = {0.0, 0.0, true};
  } else if (rho > 1.0) {
    out.long_force_n /= rho;
    out.lat_force_n /= rho;
    out.limited = true;
  }
  return out;
}
/// With the slip state's f and kappa (TireSlip or TireContact).
template <class Slip>
[[nodiscard]] inline TireForces tire_forces(const TmeasyParams& p, const TireCharacteristic& c,
                                            const TireKinematics& k, const Slip& slip,
                                            const Eigen::Vector2d& s) noexcept {
  return limited_forces(p, c, slip.sliding_ratio, s,
                        deflection_dynamics(p, c, k, slip.f_per_slip, s));
}

/// The stiff damping paths of eq. (24) at frozen f, the partials M_VI needs (method.md sec. 6):
/// dF_x/dv_x = -d_x f / (d_x r_D|w| s^x + f) (the force resists the contact point's slip speed;
/// dF_x/dw = -r_D dF_x/dv_x), dF_y/dv_y likewise. Given as the positive damping coefficients.
struct DampingPaths {
  double long_nspm = 0;
  double lat_nspm = 0;
};
[[nodiscard]] inline DampingPaths damping_paths(const TmeasyParams& p, const TireCharacteristic& c,
                                                const TireKinematics& k,
                                                double f_per_slip) noexcept {
  const DeflectionDynamics d = deflection_dynamics(p, c, k, f_per_slip, Eigen::Vector2d::Zero());
  return {d.x.damping_nspm, d.y.damping_nspm};
}

/// The complete partial derivatives d(F_x, F_y)/d(v_x, v_y, omega) of the limited forces
/// (eqs. 14-26) at deflection s, with f moving with the slip (r_D and the characteristic held):
/// for a model that linearizes the whole tire force in M_VI (the paper's quarter car, whose large
/// steps need it). The vehicle uses only the stiff damping paths (damping_paths, spin_force).
/// Exact, by forward-mode dual numbers.
struct TireForcePartials {
  Eigen::Matrix<double, 2, 3> d_force = Eigen::Matrix<double, 2, 3>::Zero();  ///< cols v_x, v_y, w
};
[[nodiscard]] TireForcePartials tire_force_partials(const TmeasyParams& p,
                                                    const TireCharacteristic& c,
                                                    const TireKinematics& k,
                                                    const Eigen::Vector2d& s) noexcept;

/// The longitudinal force on the wheel's spin equation - the same limited force the framework
/// applies to the wheel's contact (eq. 26) - and its stiff derivative dF_x/dw (the damping path at
/// frozen f, not scaled by the limiter), for the wheel-spin stage's implicit inertia.
struct SpinForce {
  double long_force_n = 0;
  double d_force_d_spin = 0;  ///< [N s]
};
[[nodiscard]] inline SpinForce spin_force(const TmeasyParams& p, const TireContact& contact,
                                          const Eigen::Vector2d& s) noexcept {
  const TireCharacteristic& c = contact.characteristic;
  const TireKinematics& k = contact.kinematics;
  const DeflectionDynamics d = deflection_dynamics(p, c, k, contact.f_per_slip, s);
  // dF_x/dw = -r_D dF_x/dv_slip: the spin moves the slip speed v_x - r_D w
  return {limited_forces(p, c, contact.sliding_ratio, s, d).long_force_n,
          d.x.damping_nspm * k.rolling_radius_m};
}

/// TMeasy's self-aligning torque M_z = -n F_y: the pneumatic trail n = (n/L) L over the contact
/// length L = sqrt(8 r_0 dz) falls from (n/L)_0 at zero lateral slip through zero at s_y0 to a
/// negative dip and back to zero at s_yE (TmeasyTrail; Rill 2011, sec. 3.4.3) [N m].
[[nodiscard]] double aligning_torque_nm(const TmeasyParams& params, const TireKinematics& k,
                                        double load_n, double lat_force_n) noexcept;

/// The rolling resistance torque f_r r_D F_z, a dry-friction torque on the wheel's spin (it
/// opposes the spin and holds a wheel at rest like a brake) [N m].
[[nodiscard]] inline double rolling_resistance_torque_nm(const TmeasyParams& p, double load_n,
                                                         double rolling_radius_m) noexcept {
  return p.rolling_resistance * rolling_radius_m * load_n;
}

}  // namespace rig::model::tire
