#pragma once
/// @file
/// How one catalogue entry is read or written, resolved once at load time: an input is a slot
/// of model::Signals, an output one value of the cycle's model::ModelReport (a row of the field
/// table io/lcm/vehicle_state_fields.h at a unit, wheel or joint). RT-safe: no strings, no
/// lookups, no allocation; a switch and a function pointer per read.

#include <cstddef>
#include <cstdint>

#include "model/report.h"
#include "model/signals.h"

namespace rig::io::signals {

enum class Direction : std::uint8_t { kIn, kOut };

inline constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);

/// What an adapter sees of one cycle after the model step: the signals (inputs as fed, the
/// enum's outputs) and the report the executive filled from the model.
struct CycleView {
  const model::Signals& signals;
  const model::ModelReport& report;
};

/// One value of a model::ModelReport: a field table row's source at an element.
struct ReportReader {
  enum class Group : std::uint8_t {
    kNone,
    kVehicle,
    kVehicleInt,
    kUnit,
    kWheel,
    kWheelFlag,
    kJoint,
    kDiff,
    kDiffFlag,
    kBody,
    kBodyFlag
  };
  Group group = Group::kNone;
  std::uint8_t unit = 0;   ///< the unit (kUnit, kWheel, kWheelFlag)
  std::uint8_t index = 0;  ///< the wheel of that unit, the joint or the free body
  double (*vehicle)(const model::ModelReport&) = nullptr;
  std::int32_t (*vehicle_int)(const model::ModelReport&) = nullptr;
  double (*of_unit)(const model::UnitReport&) = nullptr;
  double (*wheel)(const model::WheelReport&) = nullptr;
  std::int8_t (*wheel_flag)(const model::WheelReport&) = nullptr;
  double (*joint)(const model::JointReport&) = nullptr;
  double (*diff)(const model::DifferentialReport&) = nullptr;
  std::int32_t (*diff_flag)(const model::DifferentialReport&) = nullptr;
  double (*body)(const model::FreeBodyReport&) = nullptr;
  std::int8_t (*body_flag)(const model::FreeBodyReport&) = nullptr;

  [[nodiscard]] double read(const model::ModelReport& r) const noexcept {
    const auto& u = r.units[unit];
    switch (group) {
      case Group::kVehicle:
        return vehicle(r);
      case Group::kVehicleInt:
        return static_cast<double>(vehicle_int(r));
      case Group::kUnit:
        return of_unit(u);
      case Group::kWheel:
        return wheel(u.wheels[index]);
      case Group::kWheelFlag:
        return static_cast<double>(wheel_flag(u.wheels[index]));
      case Group::kJoint:
        return joint(r.joints[index]);
      case Group::kDiff:
        return diff(r.differentials[index]);
      case Group::kDiffFlag:
        return static_cast<double>(diff_flag(r.differentials[index]));
      case Group::kBody:
        return body(r.bodies[index]);
      case Group::kBodyFlag:
        return static_cast<double>(body_flag(r.bodies[index]));
      case Group::kNone:
        break;
    }
    return 0.0;
  }
};

/// An entry's access. Outputs are valid while the report is (ModelReport::valid) and, for the
/// quantities of the enum's outputs, while their slot is: the executive invalidates those after
/// a vehicle fault, and a model that writes only some of them (the quarter car) leaves the
/// others invalid, as they were before the catalogue.
struct Binding {
  Direction direction = Direction::kIn;
  std::size_t slot = kNoSlot;  ///< input: its slot; output: its enum output slot, or kNoSlot
  ReportReader reader{};       ///< outputs

  [[nodiscard]] bool is_input() const noexcept { return direction == Direction::kIn; }
  [[nodiscard]] double value(const CycleView& v) const noexcept {
    return is_input() ? v.signals.value[slot] : reader.read(v.report);
  }
  [[nodiscard]] bool valid(const CycleView& v) const noexcept {
    if (is_input()) return v.signals.valid[slot];
    return v.report.valid != 0 && (slot == kNoSlot || v.signals.valid[slot]);
  }
};

}  // namespace rig::io::signals
