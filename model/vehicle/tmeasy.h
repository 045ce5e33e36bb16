#pragma once
/// @file
/// The vehicle's use of the one TMeasy implementation (model/tire, method.md sec. 3): the
/// load-dependent curves, normalizing factors and f(s) = F(s)/s of eqs. (14-17) at the current
/// wheel load and road friction, once per wheel and step, shared by the tire deflection elements
/// (eq. 24), the wheel-spin stage and the framework. All characteristic math is
/// model/tire/tmeasy_characteristic.h (and the curves are tire::TmeasyCurvePair in TireParams);
/// this file guards lift-off and the far ends of the load law. The deflection dynamics
/// (eqs. 22-26) live in tire_deflection.h, wheel_spin.cpp and vehicle_framework.cpp.

#include "model/tire/tmeasy_characteristic.h"
#include "model/tire/tmeasy_params.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

/// The characteristic of one tire at one wheel load, ready for eqs. (16), (24).
struct TmeasyLoadCurves {
  tire::TmeasyCurve x{};   ///< longitudinal, at the current load and mu
  tire::TmeasyCurve y{};   ///< lateral
  double normalize_x = 1;  ///< s^x of eqs. (14), (24)
  double normalize_y = 1;  ///< s^y
};

/// The result of eqs. (14-17) at one kinematic state.
struct TmeasySlip {
  double slip_x = 0;      ///< s_x^N (normalized)
  double slip_y = 0;      ///< s_y^N
  double f_per_slip = 0;  ///< f(s) = F(s)/s [N], f(0) = dF0 of the slip direction
};

/// The load-dependent curves (tire::curve_at_load: degressive in the load, slips linear; mu/mu0
/// scales F_M, F_S, s_M, s_S) and the normalizing factors (tire::slip_normalization). Lift-off
/// (F_z <= 0) gives zero forces, s^x = s^y = 1 and so f = 0.
[[nodiscard]] TmeasyLoadCurves tmeasy_curves(const TireParams& tire, double load_n,
                                             double mu) noexcept;

/// Generalized slip and f(s) for contact point speeds v_x, v_y, spin rate omega and dynamic
/// rolling radius r_D (eqs. 14-17, with the small velocity v_N).
[[nodiscard]] TmeasySlip tmeasy_slip(const TmeasyLoadCurves& c, double vx_mps, double vy_mps,
                                     double spin_radps, double radius_dynamic_m,
                                     double velocity_floor_mps) noexcept;

/// F(s) / s of the combined characteristic for the normalized slips (eq. 16):
/// tire::generalized_curve + tire::evaluate_characteristic.
[[nodiscard]] double tmeasy_f_per_slip(const TmeasyLoadCurves& c, double slip_x,
                                       double slip_y) noexcept;

}  // namespace rig::model::vehicle
