#pragma once
/// @file
/// TMeasy's bore torque (Rill, Road Vehicle Dynamics, CRC 2012, sec. 3.3.6 "bore torque";
/// the paper's ref. [12]): the tire's resistance to turning about the contact normal, which
/// dominates the steering effort at stand-still (parking) and fades as the wheel rolls.
///
/// A torsional deflection phi of the contact patch with stiffness c_B and damping d_B:
///   M_B = -(c_B phi + d_B phi'),  |M_B| <= M_B,max = (2/3) R_P mu F_z
/// (the dry-friction torque of a circular patch of radius R_P under uniform pressure), with the
/// patch's effective radius R_P = (L/2 + B/2)/2, L = sqrt(8 r_0 F_z / c_z) its length (as the
/// pneumatic trail's, Rill 2011 sec. 3.4.3) and B its width.
/// The patch twists with the wheel's turning speed omega_n about the normal (steer rate + yaw
/// rate) and, rolling, relaxes: rubber enters the patch untwisted at its leading edge, so
///   phi' = omega_n - (r_D |Omega| / lambda_B) phi
/// (our choice of the relaxation form rather than TMeasy's bore slip s_B = -R_P omega_n /
/// (r_D |Omega| + v_N) in the generalized slip: it keeps the bore element apart from eqs. 14-17).
/// lambda_B is the brush model's (rigid carcass, a rectangular patch |x| <= a = L/2, |y| <= b =
/// B/2; Pacejka, Tire and Vehicle Dynamics, 3rd ed. 2012, sec. 3.2): a bristle at (x, y) entered
/// (a - x)/v ago and its deflection grew at omega_n x (-y, x) along the way, so
/// dx = -omega_n y (a - x)/v and dy = omega_n (a - x)(a + x)/(2 v); the rolling patch's moment
/// k integral of (x dy - y dx) dA = k omega_n (4/3) a^2 b^3 / v (the x dy part is odd in x) is
/// that of a rigid twist phi (k I_p phi, I_p = (4/3) a b (a^2 + b^2)) of omega_n lambda_B / v with
///   lambda_B = a b^2 / (a^2 + b^2),
/// so the steady torque is c_B lambda_B omega_n / (r_D |Omega|) well below the limit (checked
/// against a bristle field rolled on an exact circle in tests/model/tire/bore_test.cpp).
/// One step of h: implicit Euler in phi, phi(k+1) = (phi(k) + h omega_n) / (1 + h r_D|Omega| / lambda_B),
/// then the limit as the stick-slip limit of eq. (26): if c_B phi + d_B phi' exceeds M_B,max, phi
/// slides to where it equals it (c_B phi + d_B (phi - phi(k))/h = +-M_B,max), so reversing the
/// twist after sliding walks the torque from +M_B,max to -M_B,max on the slope c_B: a hysteresis
/// of width 2 M_B,max. Unconditionally stable in h; allocation-free.

#include <algorithm>
#include <cmath>

#include "model/tire/tmeasy_params.h"

namespace rig::model::tire {

/// L = sqrt(8 r_0 F_z / c_z) [m] (0 lifted off).
[[nodiscard]] inline double contact_length_m(const TmeasyParams& p, double load_n) noexcept {
  return load_n > 0 ? std::sqrt(8.0 * p.radius_unloaded_m * load_n / p.vertical_stiffness_npm)
                    : 0.0;
}
/// R_P = (L/2 + B/2)/2 [m].
[[nodiscard]] inline double bore_radius_m(const TmeasyParams& p, double load_n) noexcept {
  return 0.5 * (0.5 * contact_length_m(p, load_n) + 0.5 * p.bore.contact_width_m);
}
/// M_B,max = (2/3) R_P mu F_z [N m].
[[nodiscard]] inline double bore_torque_max_nm(const TmeasyParams& p, double load_n,
                                               double friction) noexcept {
  return load_n > 0 ? 2.0 / 3.0 * bore_radius_m(p, load_n) * friction * load_n : 0.0;
}

/// lambda_B = a b^2 / (a^2 + b^2), a = L/2, b = B/2 [m]: the rolling patch's twist relaxation
/// length (the brush model's, above).
[[nodiscard]] inline double bore_relaxation_length_m(const TmeasyParams& p,
                                                     double load_n) noexcept {
  const double a = 0.5 * contact_length_m(p, load_n), b = 0.5 * p.bore.contact_width_m;
  return a > 0 ? a * b * b / (a * a + b * b) : 0.0;
}

/// One step of the bore element: the new twist and the torque on the wheel about the normal.
struct BoreStep {
  double twist_rad = 0;  ///< phi(k+1)
  double torque_nm = 0;  ///< M_B = -(c_B phi + d_B phi'), limited
  double stiffness_nmprad =
      0;  ///< -dM_B/d(turn angle) over the step: c_B + d_B/h sticking, 0 sliding
};
[[nodiscard]] inline BoreStep bore_step(const TmeasyParams& p, double twist_rad,
                                        double turn_rate_radps, double rolling_mps, double load_n,
                                        double friction, double h) noexcept {
  const TmeasyBore& b = p.bore;
  if (!b.enabled || load_n <= 0) return {};
  const double relaxation_m = bore_relaxation_length_m(p, load_n);
  const double next = (twist_rad + h * turn_rate_radps) / (1.0 + h * rolling_mps / relaxation_m);
  const double elastic = b.stiffness_nmprad * next + b.damping_nmsprad * (next - twist_rad) / h;
  const double limit = bore_torque_max_nm(p, load_n, friction);
  if (std::abs(elastic) <= limit) {
    // d(elastic)/d(h omega_n): the twist's stiffness through the step
    return {next, -elastic,
            (b.stiffness_nmprad + b.damping_nmsprad / h) / (1.0 + h * rolling_mps / relaxation_m)};
  }
  const double held = std::copysign(limit, elastic);
  return {(held + b.damping_nmsprad * twist_rad / h) / (b.stiffness_nmprad + b.damping_nmsprad / h),
          -held, 0.0};
}

}  // namespace rig::model::tire
