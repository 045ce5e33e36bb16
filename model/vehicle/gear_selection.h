#pragma once
/// @file
/// The automatic gearbox's logic (sec. 2.3): the shift schedule on the turbine speed with a
/// throttle-dependent upshift point and a dwell time, or the requested gear; and the gear an
/// automatic would hold at a given speed (for maneuver starts).

#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

/// The gear for the next step from the request (99: automatic) and the carrier speed (wheel
/// units); updates state.gear and state.last_shift_s, returns the total ratio (gear x final drive,
/// signed, 0 in neutral).
double select_gear(const DrivetrainParams& d, const VehicleInputs& in, double carrier_speed_radps,
                   VehicleState& state) noexcept;

/// The automatic's gear at a carrier speed: the lowest gear below the part-load upshift point.
[[nodiscard]] int gear_for_speed(const DrivetrainParams& d, double carrier_speed_radps) noexcept;

}  // namespace rig::model::vehicle
