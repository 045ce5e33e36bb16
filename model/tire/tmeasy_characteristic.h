#pragma once
/// @file
/// TMeasy's load dependence and its generalized force characteristic F(s), f(s) = F(s)/s
/// (method.md sec. 3, eqs. 14-17). Free functions, allocation-free and noexcept.

#include "model/tire/tmeasy_params.h"

namespace rig::model::tire {

/// TMeasy's degressive load law for forces and initial slopes:
/// w(q) = q (2 w1 - w2/2 - (w1 - w2/2) q), q = F_z / F_zN (w1 at F_zN, w2 at 2 F_zN).
[[nodiscard]] constexpr double degressive_in_load(double w1, double w2, double q) noexcept {
  return q * (2.0 * w1 - 0.5 * w2 - (w1 - 0.5 * w2) * q);
}
/// d/dq of degressive_in_load.
[[nodiscard]] constexpr double degressive_in_load_dq(double w1, double w2, double q) noexcept {
  return 2.0 * w1 - 0.5 * w2 - 2.0 * (w1 - 0.5 * w2) * q;
}
/// Slip values are linear in the load: w(q) = w1 + (w2 - w1) (q - 1).
[[nodiscard]] constexpr double linear_in_load(double w1, double w2, double q) noexcept {
  return w1 + (w2 - w1) * (q - 1.0);
}

/// The curve at load ratio q = F_z/F_zN and friction ratio mu/mu0: forces and initial slope on
/// the degressive parabola, slips linear in q. Friction (Rill 2011, sec. 3.4.2): F_M, F_S and
/// s_M, s_S scale with mu/mu0, the initial slope dF0 (carcass stiffness) is kept.
[[nodiscard]] TmeasyCurve curve_at_load(const TmeasyCurvePair& pair, double load_ratio,
                                        double friction_ratio) noexcept;
/// d(curve)/dq at fixed friction ratio (component-wise), for dF/dF_z.
[[nodiscard]] TmeasyCurve curve_at_load_dq(const TmeasyCurvePair& pair, double load_ratio,
                                           double friction_ratio) noexcept;

/// Normalizing factors s^x, s^y of eqs. (14-15), TMeasy's choice (Rill 2011, eq. 3.83) so that
/// both directions contribute about equally to the generalized slip:
///   s^x = s_xM/(s_xM + s_yM) + (F_xM/dFx0) / (F_xM/dFx0 + F_yM/dFy0), s^y likewise;
/// s^x + s^y = 2. Evaluated with the curves at the current load.
struct SlipNormalization {
  double x = 1.0;  ///< s^x
  double y = 1.0;  ///< s^y
};
[[nodiscard]] SlipNormalization slip_normalization(const TmeasyCurve& longitudinal,
                                                   const TmeasyCurve& lateral) noexcept;

/// One value of a characteristic: F(s), f(s) = F(s)/s (f(0) = dF0) and their slip derivatives.
struct CharacteristicValue {
  double force_n = 0;    ///< F(s)
  double f_n = 0;        ///< f(s) = F(s)/s
  double dforce_ds = 0;  ///< dF/ds
  double df_ds = 0;      ///< df/ds
};

/// TMeasy's characteristic F(s) for s >= 0 (Rill 2011, eq. 3.63):
///  - 0 <= s <= s_M: rational, F = dF0 s / (1 + sigma (sigma + dF0 s_M/F_M - 2)), sigma = s/s_M
///    (initial slope dF0, maximum F_M at s_M with dF/ds = 0);
///  - s_M < s <= s_S: cubic smoothstep F = F_M - (F_M - F_S) sigma^2 (3 - 2 sigma),
///    sigma = (s - s_M)/(s_S - s_M) (C1 at both ends);
///  - s > s_S: F = F_S (full sliding).
[[nodiscard]] CharacteristicValue evaluate_characteristic(const TmeasyCurve& curve,
                                                          double slip) noexcept;

/// The generalized characteristic of combined slip (Rill 2011, eqs. 3.84-3.86): with the
/// normalized slips s_x^N, s_y^N (eqs. 14-15), s = sqrt(s_x^N^2 + s_y^N^2), cos(phi) = s_x^N/s,
/// sin(phi) = s_y^N/s, each of dF0, s_M, F_M, s_S, F_S combines the directional values as
///   dF0 = sqrt((dFx0 s^x cos)^2 + (dFy0 s^y sin)^2),  s_M = sqrt((s_xM/s^x cos)^2 + (s_yM/s^y
///   sin)^2), F_M = sqrt((F_xM cos)^2 + (F_yM sin)^2)  (s_S, F_S as s_M, F_M).
/// At s = 0 the direction is undefined; phi = 0 is taken (f(0) = dFx0 s^x).
[[nodiscard]] TmeasyCurve generalized_curve(const TmeasyCurve& longitudinal,
                                            const TmeasyCurve& lateral,
                                            const SlipNormalization& norm, double cos_phi,
                                            double sin_phi) noexcept;

}  // namespace rig::model::tire
