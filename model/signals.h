#pragma once
/// @file
/// The only contract between the model and the outside world (io/, rig/): an enum-indexed set of
/// named SI quantities with validity flags and a source. CAN mappings and LCM bind to these by
/// name; the driver fills the inputs that no ECU provides.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "model/report.h"

namespace rig::model {

/// Every model input and output. Names carry their unit; all values are SI.
enum class Signal : std::uint16_t {
  // ---- inputs ----
  kSteeringWheelAngleCmd,    ///< driver steering wheel angle command [rad] (angle mode)
  kSteeringWheelTorqueCmd,   ///< driver hand torque on the steering wheel [N m] (torque mode)
  kAssistTorque,             ///< power-assist (EPS motor) torque on the pinion [N m]
  kThrottlePedal,            ///< accelerator pedal position [0..1]
  kBrakePressureFront,       ///< brake circuit pressure, front axle(s) [Pa]
  kBrakePressureRear,        ///< brake circuit pressure, rear axle(s) [Pa]
  kGearRequest,              ///< requested gear: -1 reverse, 0 neutral, 1..n, 99 = automatic [-]
  kSteeringOverlayAngleCmd,  ///< overriding gear: angle superimposed at the pinion [rad]
  kIgnition,                 ///< terminal state: 0 off, 1 accessory (Kl. 75), 2 on (Kl. 15),
                             ///< 3 start (Kl. 50); not valid (unrouted): on [-]
  // the steering bench (issue 15; model/vehicle/steering/README.md)
  kSteeringWheelFeedbackTorqueCmd,  ///< steer-by-wire: hand-wheel actuator torque [N m]
  kRackForceCmd,                    ///< steer-by-wire: road-wheel actuator force on the rack [N]
  kRackPositionCmd,                 ///< steer-by-wire: road-wheel actuator rack position [m]
  kRackPositionMeasured,            ///< rack-in-the-loop: the real rack's travel [m]
  kRackSpeedMeasured,               ///< rack-in-the-loop: the real rack's speed [m/s]
  // the driver's differential locks (issue 17; model/vehicle/differential/README.md)
  kDifferentialLockBetweenCmd,  ///< 1: lock every lockable centre / inter-axle differential [-]
  kDifferentialLockAxleCmd,     ///< 1: lock every lockable cross-axle differential [-]
  // ---- outputs ----
  kVehicleSpeed,        ///< longitudinal speed of the (first) unit's CG [m/s]
  kWheelSpeedFL,        ///< wheel spin rate, front left [rad/s]
  kWheelSpeedFR,        ///< wheel spin rate, front right [rad/s]
  kWheelSpeedRL,        ///< wheel spin rate, rear left [rad/s]
  kWheelSpeedRR,        ///< wheel spin rate, rear right [rad/s]
  kLongitudinalAccel,   ///< longitudinal acceleration in body axes [m/s^2]
  kLateralAccel,        ///< lateral acceleration in body axes [m/s^2]
  kYawRate,             ///< yaw rate [rad/s]
  kSteeringWheelAngle,  ///< measured steering wheel angle [rad]
  kSteeringWheelSpeed,  ///< measured steering wheel speed [rad/s]
  kTorsionBarTorque,    ///< torsion bar torque, what the assist senses [N m]
  kRackPosition,        ///< rack travel [m]
  kRackForce,           ///< sum of tie-rod forces on the rack [N]
  kEngineSpeed,         ///< engine speed [rad/s]
  kGear,                ///< engaged gear [-]
  kBrakePressureFL,     ///< effective wheel brake pressure, front left [Pa]
  kBrakePressureFR,     ///< effective wheel brake pressure, front right [Pa]
  kBrakePressureRL,     ///< effective wheel brake pressure, rear left [Pa]
  kBrakePressureRR,     ///< effective wheel brake pressure, rear right [Pa]
  kPositionX,           ///< CG position x in the road frame [m]
  kPositionY,           ///< CG position y in the road frame [m]
  kHeading,             ///< yaw angle [rad]
  kCount
};

inline constexpr std::size_t kSignalCount = static_cast<std::size_t>(Signal::kCount);
inline constexpr Signal kFirstOutput = Signal::kVehicleSpeed;

/// Where an input value comes from. Set once from configuration (routing is config, not code).
enum class SignalSource : std::uint8_t { kModel, kDriver, kCan };

/// Static description of one signal.
struct SignalInfo {
  Signal id;
  std::string_view name;  ///< snake_case with unit suffix, used by CAN mapping and LCM
  std::string_view unit;
  bool is_input;
};

inline constexpr std::array<SignalInfo, kSignalCount> kSignalTable{{
    {Signal::kSteeringWheelAngleCmd, "steering_wheel_angle_cmd_rad", "rad", true},
    {Signal::kSteeringWheelTorqueCmd, "steering_wheel_torque_cmd_nm", "N m", true},
    {Signal::kAssistTorque, "assist_torque_nm", "N m", true},
    {Signal::kThrottlePedal, "throttle_pedal", "1", true},
    {Signal::kBrakePressureFront, "brake_pressure_front_pa", "Pa", true},
    {Signal::kBrakePressureRear, "brake_pressure_rear_pa", "Pa", true},
    {Signal::kGearRequest, "gear_request", "1", true},
    {Signal::kSteeringOverlayAngleCmd, "steering_overlay_angle_cmd_rad", "rad", true},
    {Signal::kIgnition, "ignition_state", "1", true},
    {Signal::kSteeringWheelFeedbackTorqueCmd, "steering_wheel_feedback_torque_cmd_nm", "N m", true},
    {Signal::kRackForceCmd, "rack_force_cmd_n", "N", true},
    {Signal::kRackPositionCmd, "rack_position_cmd_m", "m", true},
    {Signal::kRackPositionMeasured, "rack_position_measured_m", "m", true},
    {Signal::kRackSpeedMeasured, "rack_speed_measured_mps", "m/s", true},
    {Signal::kDifferentialLockBetweenCmd, "differential_lock_between_cmd", "1", true},
    {Signal::kDifferentialLockAxleCmd, "differential_lock_axle_cmd", "1", true},
    {Signal::kVehicleSpeed, "vehicle_speed_mps", "m/s", false},
    {Signal::kWheelSpeedFL, "wheel_speed_fl_radps", "rad/s", false},
    {Signal::kWheelSpeedFR, "wheel_speed_fr_radps", "rad/s", false},
    {Signal::kWheelSpeedRL, "wheel_speed_rl_radps", "rad/s", false},
    {Signal::kWheelSpeedRR, "wheel_speed_rr_radps", "rad/s", false},
    {Signal::kLongitudinalAccel, "longitudinal_accel_mps2", "m/s^2", false},
    {Signal::kLateralAccel, "lateral_accel_mps2", "m/s^2", false},
    {Signal::kYawRate, "yaw_rate_radps", "rad/s", false},
    {Signal::kSteeringWheelAngle, "steering_wheel_angle_rad", "rad", false},
    {Signal::kSteeringWheelSpeed, "steering_wheel_speed_radps", "rad/s", false},
    {Signal::kTorsionBarTorque, "torsion_bar_torque_nm", "N m", false},
    {Signal::kRackPosition, "rack_position_m", "m", false},
    {Signal::kRackForce, "rack_force_n", "N", false},
    {Signal::kEngineSpeed, "engine_speed_radps", "rad/s", false},
    {Signal::kGear, "gear", "1", false},
    {Signal::kBrakePressureFL, "brake_pressure_fl_pa", "Pa", false},
    {Signal::kBrakePressureFR, "brake_pressure_fr_pa", "Pa", false},
    {Signal::kBrakePressureRL, "brake_pressure_rl_pa", "Pa", false},
    {Signal::kBrakePressureRR, "brake_pressure_rr_pa", "Pa", false},
    {Signal::kPositionX, "position_x_m", "m", false},
    {Signal::kPositionY, "position_y_m", "m", false},
    {Signal::kHeading, "heading_rad", "rad", false},
}};

constexpr std::size_t index(Signal s) { return static_cast<std::size_t>(s); }
constexpr const SignalInfo& info(Signal s) { return kSignalTable[index(s)]; }

/// Looks a signal up by its name; std::nullopt if there is none (load time only).
constexpr std::optional<Signal> signal_by_name(std::string_view name) {
  for (const auto& entry : kSignalTable) {
    if (entry.name == name) return entry.id;
  }
  return std::nullopt;
}

/// The values an input may take: what a source (driver table, CAN) may ask of the model.
/// Beyond them a request is impossible (a pedal past 1, a negative pressure, half a gear).
struct InputRange {
  double min = 0.0;
  double max = 0.0;
  bool whole = false;  ///< whole numbers only (the gear request; 99 = automatic)
};
constexpr InputRange input_range(Signal s) {
  switch (s) {
    case Signal::kSteeringWheelAngleCmd:
      return {-20.0, 20.0};  // +-3.2 turns [rad]
    case Signal::kSteeringWheelTorqueCmd:
      return {-200.0, 200.0};
    case Signal::kAssistTorque:
      return {-1e4, 1e4};
    case Signal::kThrottlePedal:
      return {0.0, 1.0};
    case Signal::kBrakePressureFront:
    case Signal::kBrakePressureRear:
      return {0.0, 3e7};  // 300 bar
    case Signal::kGearRequest:
      return {-1.0, 99.0, true};
    case Signal::kSteeringOverlayAngleCmd:
      return {-1.0, 1.0};  // +-57 deg at the pinion, beyond any superposition gear's travel
    case Signal::kIgnition:
      return {0.0, 3.0, true};
    case Signal::kSteeringWheelFeedbackTorqueCmd:
      return {-100.0, 100.0};
    case Signal::kRackForceCmd:
      return {-5e4, 5e4};  // beyond any passenger car or light truck rack
    case Signal::kRackPositionCmd:
    case Signal::kRackPositionMeasured:
      return {-0.3, 0.3};
    case Signal::kRackSpeedMeasured:
      return {-5.0, 5.0};
    case Signal::kDifferentialLockBetweenCmd:
    case Signal::kDifferentialLockAxleCmd:
      return {0.0, 1.0, true};
    default:
      return {0.0, 0.0};  // outputs: no source sets them
  }
}

/// Input slots. Every model input has one slot in Signals: the enum's signals first (slot =
/// index(signal)), then, from kSignalCount on, a block of kUnitInputCount slots per unit of a
/// combination (model/report.h kMaxUnits): its wheels' brake pressures (wheel i as in the
/// report: axles front to rear, left before right) and its two brake circuits. A valid wheel
/// pressure replaces its circuit's for that wheel (an ESC's modulated pressure); a unit's
/// circuit that is not valid follows the enum's circuits (kBrakePressureFront/Rear), which are
/// the first unit's. The first unit's block keeps its two circuit slots unused (the enum's serve).
inline constexpr std::size_t kUnitInputCount = static_cast<std::size_t>(kMaxWheelsPerUnit) + 2;
inline constexpr std::size_t kSlotCount =
    kSignalCount + static_cast<std::size_t>(kMaxUnits) * kUnitInputCount;

/// Slot of the brake pressure input of wheel `wheel` of unit `unit` (both from 0).
constexpr std::size_t wheel_brake_slot(int unit, int wheel) {
  return kSignalCount + static_cast<std::size_t>(unit) * kUnitInputCount +
         static_cast<std::size_t>(wheel);
}
/// Slot of brake circuit `circuit` (0 front, 1 rear) of unit `unit`: the enum's for unit 0.
constexpr std::size_t brake_circuit_slot(int unit, int circuit) {
  if (unit == 0) {
    return index(circuit == 0 ? Signal::kBrakePressureFront : Signal::kBrakePressureRear);
  }
  return kSignalCount + static_cast<std::size_t>(unit) * kUnitInputCount +
         static_cast<std::size_t>(kMaxWheelsPerUnit) + static_cast<std::size_t>(circuit);
}
/// Whether a slot holds an input (the enum's inputs and every unit block) or an output.
constexpr bool slot_is_input(std::size_t slot) {
  return slot < index(kFirstOutput) || slot >= kSignalCount;
}
/// The values an input slot may take (the unit blocks: pressures, 0..300 bar).
constexpr InputRange slot_range(std::size_t slot) {
  return slot < kSignalCount ? input_range(static_cast<Signal>(slot)) : InputRange{0.0, 3e7};
}

/// The values of all slots (the enum's signals, then the unit input blocks), their validity and
/// (for inputs) their source. Plain data: copied by value into snapshots, never allocates.
struct Signals {
  std::array<double, kSlotCount> value{};
  std::array<bool, kSlotCount> valid{};
  std::array<SignalSource, kSlotCount> source{};

  double& operator[](Signal s) { return value[index(s)]; }
  double operator[](Signal s) const { return value[index(s)]; }
  void set(Signal s, double v, bool is_valid = true) {
    value[index(s)] = v;
    valid[index(s)] = is_valid;
  }
};

static_assert(
    [] {
      for (std::size_t i = 0; i < kSignalCount; ++i) {
        if (index(kSignalTable[i].id) != i) return false;
        if (kSignalTable[i].is_input != (i < index(kFirstOutput))) return false;
      }
      return true;
    }(),
    "kSignalTable must list every Signal in enum order");

}  // namespace rig::model
