#pragma once
/// @file
/// The automatic gearbox's logic (sec. 2.3): the shift schedule on the turbine speed with a
/// throttle-dependent upshift point, hysteresis and a dwell time, or the requested gear; the
/// timed clutch-to-clutch shift (torque phase, inertia phase); and the gear an automatic would
/// hold at a given speed (for maneuver starts).

#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

/// The gearbox's ratios over one step (frozen: evaluated from the step's start state).
struct Engagement {
  double turbine_ratio = 0;  ///< turbine speed / carrier speed (signed; 0 in neutral)
  double output_ratio = 0;   ///< carrier torque / turbine torque (before efficiency)
  /// d(turbine_ratio)/dt: the inertia phase sweeps the turbine to the new gear's speed.
  double turbine_ratio_rate_per_s = 0;
  /// The gearbox's request to the engine in a power-on upshift's inertia phase (<= 0): the
  /// engine inertia's torque J_e w_t', so that the slipping clutch passes on the engine's torque
  /// rather than its flywheel's (the usual torque intervention of an automatic).
  double engine_torque_cut_nm = 0;
};

/// The gear for the next step from the request (99: automatic) and the carrier speed (wheel
/// units); starts and ends the timed shifts (state.gear, last_shift_s, shift_from_gear,
/// shift_torque_first) and returns the step's ratios.
Engagement select_gear(const DrivetrainParams& d, const VehicleInputs& in,
                       double carrier_speed_radps, VehicleState& state) noexcept;

/// The automatic's gear at a carrier speed: the lowest gear below the part-load upshift point.
[[nodiscard]] int gear_for_speed(const DrivetrainParams& d, double carrier_speed_radps) noexcept;

/// Gear x final drive of a gear (signed: reverse < 0; 0 in neutral).
[[nodiscard]] double ratio_of(const DrivetrainParams& d, int gear) noexcept;

}  // namespace rig::model::vehicle
