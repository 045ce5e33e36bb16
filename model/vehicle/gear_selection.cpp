#include "model/vehicle/gear_selection.h"

#include <algorithm>
#include <cmath>

#include "model/vehicle/drivetrain.h"

namespace rig::model::vehicle {
namespace {

/// Share of a timed shift that is the torque phase (the handover between the clutches); the
/// rest is the inertia phase (the on-coming clutch slips the turbine to the new speed).
constexpr double kTorquePhaseShare = 0.25;

/// In a power-on upshift the on-coming clutch passes the engine's torque plus what slows the
/// engine down (J_e w_e'); the shift control cuts the engine torque for that, at most to its
/// closed-throttle torque. Where that is not enough (part throttle), the inertia phase is
/// stretched so that the clutch passes at most this much more than the engine's torque.
constexpr double kInertiaLiftShare = 0.5;

double lerp(double a, double b, double t) noexcept { return a + (b - a) * t; }

/// The inertia phase's sweep of the turbine ratio from r_old to r_new over u = 0..1 at a
/// constant rate (the turbine speed's slope the shift control holds).
Engagement sweep(double r_old, double r_new, double output_ratio, double u,
                 double inertia_s) noexcept {
  u = std::clamp(u, 0.0, 1.0);
  return {lerp(r_old, r_new, u), output_ratio, (r_new - r_old) / inertia_s};
}

/// The shift schedule: up above the throttle-dependent point when the next gear lands at least
/// the hysteresis above the downshift speed; down when the lower gear stays below twice the
/// downshift speed and the turbine falls below it; no decision within a shift or the dwell.
int automatic_gear(const DrivetrainParams& d, const VehicleInputs& in, double carrier_radps,
                   const VehicleState& state) noexcept {
  const int top = static_cast<int>(d.gear_ratios.size());
  int gear = std::max(state.gear, 1);
  if (state.gear >= 1 &&
      (state.shift_from_gear != 0 || state.time_s - state.last_shift_s < d.shift_dwell_s))
    return gear;
  const double turbine = ratio_of(d, gear) * carrier_radps;
  const double up = d.upshift_speed_low_radps +
                    in.throttle * (d.upshift_speed_high_radps - d.upshift_speed_low_radps);
  if (gear < top && turbine > up &&
      ratio_of(d, gear + 1) * carrier_radps > d.downshift_speed_radps + d.upshift_hysteresis_radps)
    return gear + 1;
  if (gear > 1 && ratio_of(d, gear - 1) * carrier_radps < d.downshift_speed_radps * 2.0 &&
      turbine < d.downshift_speed_radps)
    return gear - 1;
  return gear;
}

/// Starts a shift to `gear`: timed between forward gears, else the ratio jumps. The phase
/// order keeps the slipping clutch dissipative: with power flowing to the wheels (engine
/// faster than the turbine) an upshift hands the torque over first, a downshift first speeds
/// the turbine up; coasting, the other way round.
void begin_shift(const DrivetrainParams& d, const VehicleInputs& in, int gear, double carrier_radps,
                 VehicleState& state) noexcept {
  const bool timed = d.shift_time_s > 0 && gear > 0 && state.gear > 0;
  const double engine_radps = state.drivetrain_z(0);
  const bool power_on = engine_radps > ratio_of(d, state.gear) * carrier_radps;
  state.shift_from_gear = timed ? state.gear : 0;
  state.shift_torque_first = (gear > state.gear) == power_on;
  state.shift_inertia_s = (1 - kTorquePhaseShare) * d.shift_time_s;
  if (timed && power_on && gear > state.gear) {
    const double te = engine_torque_nm(d, in.throttle, engine_radps);
    const double absorbable_nm =
        te - engine_torque_nm(d, 0.0, engine_radps) + kInertiaLiftShare * std::max(te, 0.0);
    const double drop_radps = (ratio_of(d, state.gear) - ratio_of(d, gear)) * carrier_radps;
    state.shift_inertia_s = std::max(
        state.shift_inertia_s, d.engine_inertia_kgm2 * drop_radps / std::max(absorbable_nm, 1.0));
  }
  state.last_shift_s = state.time_s;
  state.gear = gear;
}

/// The ratios at the state's time: in the torque phase the turbine keeps the old gear's speed
/// and the torque ratio moves to the new gear's; in the inertia phase the turbine's ratio
/// sweeps to the new gear at the torque ratio of the clutch that slips.
Engagement engagement(const DrivetrainParams& d, const VehicleState& state) noexcept {
  const double r_new = ratio_of(d, state.gear);
  if (state.shift_from_gear == 0) return {r_new, r_new, 0};
  const double r_old = ratio_of(d, state.shift_from_gear);
  const double torque_s = kTorquePhaseShare * d.shift_time_s;
  const double inertia_s = state.shift_inertia_s;
  const double t = state.time_s - state.last_shift_s;
  if (state.shift_torque_first) {
    if (t < torque_s) return {r_old, lerp(r_old, r_new, t / torque_s), 0};
    return sweep(r_old, r_new, r_new, (t - torque_s) / inertia_s, inertia_s);
  }
  if (t < inertia_s) return sweep(r_old, r_new, r_old, t / inertia_s, inertia_s);
  return {r_new, lerp(r_old, r_new, std::min((t - inertia_s) / torque_s, 1.0)), 0};
}

}  // namespace

double ratio_of(const DrivetrainParams& d, int gear) noexcept {
  if (gear > 0) return d.gear_ratios[static_cast<std::size_t>(gear - 1)] * d.final_drive_ratio;
  if (gear < 0) return -d.reverse_ratio * d.final_drive_ratio;
  return 0;
}

Engagement select_gear(const DrivetrainParams& d, const VehicleInputs& in,
                       double carrier_speed_radps, VehicleState& state) noexcept {
  if (state.shift_from_gear != 0 && state.time_s - state.last_shift_s >=
                                        kTorquePhaseShare * d.shift_time_s + state.shift_inertia_s)
    state.shift_from_gear = 0;  // the shift is through
  const int top = static_cast<int>(d.gear_ratios.size());
  const int gear = in.gear_request != 99 ? std::clamp(in.gear_request, -1, top)
                                         : automatic_gear(d, in, carrier_speed_radps, state);
  if (gear != state.gear) begin_shift(d, in, gear, carrier_speed_radps, state);
  Engagement e = engagement(d, state);
  if (state.shift_torque_first)
    e.engine_torque_cut_nm =
        d.engine_inertia_kgm2 * std::min(e.turbine_ratio_rate_per_s, 0.0) * carrier_speed_radps;
  return e;
}

int gear_for_speed(const DrivetrainParams& d, double carrier_speed_radps) noexcept {
  const int top = static_cast<int>(d.gear_ratios.size());
  int gear = 1;
  while (gear < top &&
         ratio_of(d, gear) * std::abs(carrier_speed_radps) > d.upshift_speed_low_radps)
    ++gear;
  return gear;
}

}  // namespace rig::model::vehicle
