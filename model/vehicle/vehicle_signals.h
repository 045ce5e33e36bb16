#pragma once
/// @file
/// The vehicle's adapter to model/signals.h and model/report.h: free functions that read the
/// step's inputs from the signals and write the outputs and the report from the state and the
/// workspace.

#include "model/report.h"
#include "model/signals.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

/// The inputs of the next step of unit `unit` (from 0) of a combination (0 on its own); an
/// invalid or non-finite input takes its neutral value (no throttle, no brake, straight ahead,
/// no overlay, automatic gearbox, ignition on). Brakes: a wheel's own pressure slot
/// (wheel_brake_slot) while valid, else its axle's circuit (brake_circuit_slot, else the enum's).
[[nodiscard]] VehicleInputs read_inputs(const VehicleParams& params, int unit,
                                        const Signals& s) noexcept;

/// The output signals of the current state.
void write_outputs(const VehicleState& state, const VehicleInputs& in, const VehicleWorkspace& work,
                   Signals& s) noexcept;

/// The first unit of the report (and the steering, drive train and brake pressures).
/// WheelReport::slip_valid of every wheel: the wheel moves (max(|v_x|, r_D |w|)) at least
/// mask_speed_mps (VehicleParams::slip_mask_speed_mps).
void mark_slip_validity(double mask_speed_mps, UnitReport& unit) noexcept;
void fill_report(const VehicleState& state, const VehicleInputs& in, const VehicleWorkspace& work,
                 ModelReport& report) noexcept;

}  // namespace rig::model::vehicle
