#pragma once
/// @file
/// The interface through which the executive steps any model (quarter car, vehicle, combination).

#include <cstdint>
#include <string_view>

#include "model/report.h"
#include "model/signals.h"

namespace rig::model {

/// Result of one step. The RT path uses codes, never exceptions. After kNonFinite and
/// kVehicleFault the model is at its last good state and last_fault() says what and where.
enum class StepStatus { kOk, kNonFinite, kVehicleFault };

/// What a failed step found (SteppedModel::last_fault()), in the order the vehicle checks it
/// (model/vehicle/vehicle_faults.h). The model reports what and where; what to do about it is
/// the caller's decision (the rig: [rig] on_vehicle_fault).
enum class FaultKind : std::uint8_t {
  kNone,
  kNonFinite,   ///< a NaN or infinity in the state (value NaN)
  kSpeed,       ///< CG speed magnitude [m/s]
  kRate,        ///< angular rate magnitude, body axes [rad/s]
  kWheelSpin,   ///< |spin| of wheel `index` beyond speed limit / unloaded radius [rad/s]
  kRoll,        ///< |roll| [rad]
  kPitch,       ///< |pitch| [rad]
  kBodyGround,  ///< body point `index` below the road: value = its height above it [m]
  /// free body `index` (`[[free_body]]` order) through its stops: value = the deflection beyond
  /// the stop clearance, limit = the body's through_margin_m [m]
  kFreeBodyStops,
};

/// One fault: plain data, copied by value.
struct ModelFault {
  FaultKind kind = FaultKind::kNone;
  std::int32_t unit = 0;    ///< unit of a combination (0 on its own); -1: the coupling itself
  std::int32_t index = -1;  ///< wheel or body point; -1: the unit as a whole
  double time_s = 0;        ///< end of the step that produced it (the model stays at its start)
  double value = 0;         ///< what was found (roll, pitch, spin: signed)
  double limit = 0;         ///< the limit it went beyond
};

/// "speed", "rate", "wheel_spin", "roll", "pitch", "body_ground", "free_body_stops",
/// "non_finite", "none".
constexpr std::string_view fault_kind_name(FaultKind k) noexcept {
  switch (k) {
    case FaultKind::kNone:
      return "none";
    case FaultKind::kNonFinite:
      return "non_finite";
    case FaultKind::kSpeed:
      return "speed";
    case FaultKind::kRate:
      return "rate";
    case FaultKind::kWheelSpin:
      return "wheel_spin";
    case FaultKind::kRoll:
      return "roll";
    case FaultKind::kPitch:
      return "pitch";
    case FaultKind::kBodyGround:
      return "body_ground";
    case FaultKind::kFreeBodyStops:
      return "free_body_stops";
  }
  return "?";
}

/// The unit of a fault's value and limit.
constexpr std::string_view fault_value_unit(FaultKind k) noexcept {
  switch (k) {
    case FaultKind::kSpeed:
      return "m/s";
    case FaultKind::kBodyGround:
    case FaultKind::kFreeBodyStops:
      return "m";
    case FaultKind::kRate:
    case FaultKind::kWheelSpin:
      return "rad/s";
    case FaultKind::kRoll:
    case FaultKind::kPitch:
      return "rad";
    case FaultKind::kNone:
    case FaultKind::kNonFinite:
      return "";
  }
  return "";
}

/// The step status that reports a fault of kind `k`.
constexpr StepStatus step_status(FaultKind k) noexcept {
  if (k == FaultKind::kNone) return StepStatus::kOk;
  return k == FaultKind::kNonFinite ? StepStatus::kNonFinite : StepStatus::kVehicleFault;
}

/// A model advanced by fixed steps of the modified implicit Euler method. Implementations
/// allocate only at construction; step() and fill_report() never allocate, block or throw.
class SteppedModel {
 public:
  SteppedModel() = default;
  SteppedModel(const SteppedModel&) = delete;
  SteppedModel& operator=(const SteppedModel&) = delete;
  virtual ~SteppedModel() = default;

  /// Integration step size h [s].
  [[nodiscard]] virtual double step_size_s() const noexcept = 0;
  /// Simulated time [s].
  [[nodiscard]] virtual double time_s() const noexcept = 0;
  /// Advances by one step h: reads the input signals, writes the output signals.
  /// Returns kNonFinite (and leaves the state at its last finite value) if the step produced a
  /// NaN or infinity, kVehicleFault (and leaves the state at its last fault-free value) if it
  /// went beyond a physical limit (model/vehicle/vehicle_faults.h).
  virtual StepStatus step(Signals& signals) noexcept = 0;
  /// What the last failed step found; kind kNone after a good step, and for models that report
  /// no more than their StepStatus.
  [[nodiscard]] virtual ModelFault last_fault() const noexcept { return {}; }
  /// Writes the current state for tools.
  virtual void fill_report(ModelReport& report) const noexcept = 0;
};

}  // namespace rig::model
