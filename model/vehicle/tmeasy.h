#pragma once
/// @file
/// TMeasy steady-state tire characteristic (eqs. 14-17) at the current wheel load and road
/// friction: the generalized slip with its normalizing factors and f(s) = F(s)/s. The dynamic
/// part (eqs. 22-26) lives in tire_deflection.h and vehicle_framework.cc.

#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

/// The characteristic of one tire at one wheel load, ready for eqs. (16), (24).
struct TmeasyLoadCurves {
  TmeasyCurve x{};         ///< longitudinal, at the current load and mu
  TmeasyCurve y{};         ///< lateral
  double normalize_x = 1;  ///< s^x of eqs. (14), (24)
  double normalize_y = 1;  ///< s^y
};

/// The result of eqs. (14-17) at one kinematic state.
struct TmeasySlip {
  double slip_x = 0;      ///< s_x^N (normalized)
  double slip_y = 0;      ///< s_y^N
  double f_per_slip = 0;  ///< f(s) = F(s)/s [N], f(0) = dF0 of the slip direction
};

/// The load-dependent curves (TMeasy's degressive interpolation between F_zN and 2 F_zN), with
/// the maximum and sliding forces scaled by the road friction mu.
TmeasyLoadCurves tmeasy_curves(const TireParams& tire, double load_n, double mu) noexcept;

/// Generalized slip and f(s) for contact point speeds v_x, v_y, spin rate omega and dynamic
/// rolling radius r_D (eqs. 14-17, with the small velocity v_N).
TmeasySlip tmeasy_slip(const TmeasyLoadCurves& c, double vx_mps, double vy_mps, double spin_radps,
                       double radius_dynamic_m, double velocity_floor_mps) noexcept;

/// F(s) / s of the combined characteristic for the normalized slips (eq. 16).
double tmeasy_f_per_slip(const TmeasyLoadCurves& c, double slip_x, double slip_y) noexcept;

}  // namespace rig::model::vehicle
