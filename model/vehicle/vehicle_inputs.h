#pragma once
/// @file
/// The driver's and the ECUs' commands for one step: read once from the signals before the step
/// (vehicle_signals.h), constant while it runs.

#include <array>

#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

struct VehicleInputs {
  double throttle = 0;  ///< accelerator pedal [0..1]
  /// Wheel brake pressure [Pa]: the wheel's own input (an ESC's modulated pressure) while
  /// valid, else its axle's brake circuit (front or rear).
  std::array<double, kMaxWheels> brake_pressure_pa{};
  double steering_angle_cmd_rad = 0;  ///< steering robot (angle mode)
  double hand_torque_cmd_nm = 0;      ///< driver's hand torque (torque mode)
  /// Angle mode: the robot has let go (SteeringParams::angle_from_input and the angle command
  /// not valid): the wheel takes the hand torque, as in torque mode.
  bool robot_released = false;
  /// The assist input acts (SteeringParams::assist_from_input and the input valid); else the
  /// built-in boost curve.
  bool assist_from_input = false;
  double assist_input_nm = 0;
  /// Overriding gear: angle added at the pinion, between the torsion bar and the rack [rad].
  double overlay_angle_rad = 0;
  int gear_request = 99;  ///< -1 reverse, 0 neutral, 1..n, 99 automatic
  /// Ignition on or start (terminal 15 / 50): the engine runs and the EPS assists. Off or
  /// accessory: no combustion torque (the engine drags), no assist (boost curve nor input).
  bool ignition_on = true;
  /// The driver's differential locks (model/vehicle/differential/README.md): every lockable
  /// differential between axles / across an axle turns as one while set.
  bool lock_between = false;
  bool lock_axle = false;
  // ---- the steering bench (model/vehicle/steering/README.md) ----
  /// Steer-by-wire: the hand-wheel actuator's torque on the steering wheel (0 when not valid).
  double feedback_torque_cmd_nm = 0;
  /// Steer-by-wire: the road-wheel actuator's command, a force on the rack or a rack position;
  /// each only while valid (else the actuator holds: no force / the last position).
  double rack_force_cmd_n = 0;
  bool rack_force_cmd_valid = false;
  double rack_position_cmd_m = 0;
  bool rack_position_cmd_valid = false;
  /// Rack-in-the-loop: the real rack's travel and speed while valid (both valid and finite).
  double rack_position_measured_m = 0;
  double rack_speed_measured_mps = 0;
  bool rack_measured_valid = false;
};

}  // namespace rig::model::vehicle
