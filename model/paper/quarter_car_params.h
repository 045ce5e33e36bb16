#pragma once
/// @file
/// Parameters of the paper's quarter car (eq. 9, Fig. 6) on a grade.

#include "model/tire/tmeasy_params.h"

namespace rig::model::paper {

/// The 215/55 R18 TMeasy tire, without rolling resistance: eq. (9) has none.
constexpr tire::TmeasyParams quarter_car_tire_params() noexcept {
  tire::TmeasyParams p = tire::default_215_55_r18();
  p.rolling_resistance = 0.0;
  return p;
}

struct QuarterCarParams {
  double mass_kg = 400.0;           ///< m
  double wheel_inertia_kgm2 = 0.8;  ///< Theta
  double wheel_radius_m = 0.3;      ///< r (also the dynamic rolling radius r_D)
  double grade = 0.10;              ///< uphill grade, tan of the slope angle (10 %)
  double gravity_mps2 = 9.81;
  double max_drive_torque_nm = 1000.0;                  ///< drive torque at throttle_pedal = 1
  double brake_gain_nm_per_pa = 1500.0 / 1e7;           ///< brake torque limit per brake pressure
  tire::TmeasyParams tire = quarter_car_tire_params();  ///< the TMeasy tire (model/tire)
};

/// Inputs of one step.
struct QuarterCarInputs {
  double drive_torque_nm = 0;        ///< on the wheel, positive drives forward (uphill)
  double brake_torque_limit_nm = 0;  ///< dry-friction limit of the brake, >= 0
};

/// The paper's maneuver as an open-loop schedule: drive 1000 N m for 0 <= t < 6 s; from t = 8 s
/// the brake limit ramps to 1500 N m within 0.5 s; released at t = 18 s; the run ends at 20 s.
QuarterCarInputs paper_maneuver_inputs(double t_s) noexcept;
inline constexpr double kPaperManeuverEnd_s = 20.0;
inline constexpr double kPaperBrakeRelease_s = 18.0;

}  // namespace rig::model::paper
