#include "io/signals/catalogue.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "io/lcm/vehicle_state_fields.h"

namespace rig::io::signals {
namespace {

using Fields = lcm::VehicleStateFields;
using Group = ReportReader::Group;
using model::Signal;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The enum's inputs by their catalogue name (the enum's name becomes an alias).
struct InputName {
  Signal signal;
  std::string_view name;
};
constexpr InputName kUnit1Inputs[] = {
    {Signal::kSteeringWheelAngleCmd, "unit1.steering.wheel_angle_cmd_rad"},
    {Signal::kSteeringWheelTorqueCmd, "unit1.steering.wheel_torque_cmd_nm"},
    {Signal::kAssistTorque, "unit1.steering.eps_motor_torque_nm"},
    {Signal::kSteeringOverlayAngleCmd, "unit1.steering.overlay_angle_cmd_rad"},
    {Signal::kThrottlePedal, "unit1.throttle_pedal"},
    {Signal::kGearRequest, "unit1.gear_request"},
    {Signal::kIgnition, "unit1.ignition_state"},
    {Signal::kSteeringWheelFeedbackTorqueCmd, "unit1.steering.wheel_feedback_torque_cmd_nm"},
    {Signal::kRackForceCmd, "unit1.steering.rack_force_cmd_n"},
    {Signal::kRackPositionCmd, "unit1.steering.rack_position_cmd_m"},
    {Signal::kRackPositionMeasured, "unit1.steering.rack_position_measured_m"},
    {Signal::kRackSpeedMeasured, "unit1.steering.rack_speed_measured_mps"},
    {Signal::kDifferentialLockBetweenCmd, "unit1.drivetrain.differential_lock_between_cmd"},
    {Signal::kDifferentialLockAxleCmd, "unit1.drivetrain.differential_lock_axle_cmd"},
};

/// The enum's outputs: the entry each one's name is an alias of ('#': the last axle).
constexpr InputName kLegacyOutputs[] = {
    {Signal::kVehicleSpeed, "unit1.speed_x_mps"},
    {Signal::kWheelSpeedFL, "unit1.axle1.left.spin_radps"},
    {Signal::kWheelSpeedFR, "unit1.axle1.right.spin_radps"},
    {Signal::kWheelSpeedRL, "unit1.axle#.left.spin_radps"},
    {Signal::kWheelSpeedRR, "unit1.axle#.right.spin_radps"},
    {Signal::kLongitudinalAccel, "unit1.accel_x_mps2"},
    {Signal::kLateralAccel, "unit1.accel_y_mps2"},
    {Signal::kYawRate, "unit1.yaw_rate_radps"},
    {Signal::kSteeringWheelAngle, "unit1.steering.wheel_angle_rad"},
    {Signal::kSteeringWheelSpeed, "unit1.steering.wheel_speed_radps"},
    {Signal::kTorsionBarTorque, "unit1.steering.torsion_bar_torque_nm"},
    {Signal::kRackPosition, "unit1.steering.rack_travel_m"},
    {Signal::kRackForce, "unit1.steering.rack_force_n"},
    {Signal::kEngineSpeed, "unit1.drivetrain.engine_speed_radps"},
    {Signal::kGear, "unit1.drivetrain.gear"},
    {Signal::kBrakePressureFL, "unit1.axle1.left.applied_brake_pressure_pa"},
    {Signal::kBrakePressureFR, "unit1.axle1.right.applied_brake_pressure_pa"},
    {Signal::kBrakePressureRL, "unit1.axle#.left.applied_brake_pressure_pa"},
    {Signal::kBrakePressureRR, "unit1.axle#.right.applied_brake_pressure_pa"},
    {Signal::kPositionX, "unit1.position_x_m"},
    {Signal::kPositionY, "unit1.position_y_m"},
    {Signal::kHeading, "unit1.yaw_rad"},
};

/// Field-table outputs that a bench names without the unit prefix (the rack-in-the-loop forces).
constexpr std::string_view kShortOutputs[] = {"tie_rod_force_left_n", "tie_rod_force_right_n"};

constexpr std::string_view kCorners[] = {"wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr"};

Entry input(std::string name, std::string_view unit, std::size_t slot) {
  const model::InputRange r = model::slot_range(slot);
  return Entry{.name = std::move(name),
               .unit = std::string(unit),
               .direction = Direction::kIn,
               .min = r.min,
               .max = r.max,
               .aliases = {},
               .binding = {.direction = Direction::kIn, .slot = slot, .reader = {}}};
}

Entry output(std::string name, std::string_view unit, const ReportReader& reader) {
  return Entry{.name = std::move(name),
               .unit = std::string(unit),
               .direction = Direction::kOut,
               .min = kNaN,
               .max = kNaN,
               .aliases = {},
               .binding = {.direction = Direction::kOut, .slot = kNoSlot, .reader = reader}};
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string wheel_prefix(int unit, int wheel) {
  return "unit" + std::to_string(unit + 1) + ".axle" + std::to_string(wheel / 2 + 1) +
         (wheel % 2 == 0 ? ".left" : ".right");
}

Catalogue::Catalogue(const ModelShape& shape) : shape_(shape) {
  if (shape.unit_count < 1 || shape.unit_count > model::kMaxUnits)
    throw std::invalid_argument("signal catalogue: 1.." + std::to_string(model::kMaxUnits) +
                                " units");
  for (int k = 0; k < shape.unit_count; ++k) {
    const int axles = shape.axle_count[static_cast<std::size_t>(k)];
    if (axles < 1 || axles > kMaxAxlesPerUnit)
      throw std::invalid_argument("signal catalogue: 1.." + std::to_string(kMaxAxlesPerUnit) +
                                  " axles per unit");
  }
  shape_.joint_count = std::clamp(shape.joint_count, 0, model::kMaxJoints);
  shape_.differential_count = std::clamp(shape.differential_count, 0, model::kMaxDifferentials);
  shape_.body_count = std::clamp(shape.body_count, 0, model::kMaxFreeBodiesPerUnit);
  add_inputs();
  add_outputs();
  add_aliases();
}

const Catalogue& Catalogue::two_axle_vehicle() {
  static const Catalogue catalogue{ModelShape{}};
  return catalogue;
}

void Catalogue::add(Entry e) {
  if (!index_.emplace(e.name, entries_.size()).second)
    throw std::logic_error("signal catalogue: " + e.name + " twice");
  entries_.push_back(std::move(e));
}

void Catalogue::alias(std::string_view name, std::string alias_name) {
  const auto it = index_.find(std::string(name));
  if (it == index_.end()) throw std::logic_error("signal catalogue: no " + std::string(name));
  if (!index_.emplace(alias_name, it->second).second)
    throw std::logic_error("signal catalogue: alias " + alias_name + " twice");
  entries_[it->second].aliases.push_back(std::move(alias_name));
}

void Catalogue::add_inputs() {
  for (const InputName& i : kUnit1Inputs)
    add(input(std::string(i.name), model::info(i.signal).unit, model::index(i.signal)));
  for (int k = 0; k < shape_.unit_count; ++k) {
    const std::string unit = "unit" + std::to_string(k + 1);
    add(input(unit + ".brake_circuit_front_pa", "Pa", model::brake_circuit_slot(k, 0)));
    add(input(unit + ".brake_circuit_rear_pa", "Pa", model::brake_circuit_slot(k, 1)));
    for (int w = 0; w < 2 * shape_.axle_count[static_cast<std::size_t>(k)]; ++w)
      add(input(wheel_prefix(k, w) + ".brake_pressure_pa", "Pa", model::wheel_brake_slot(k, w)));
  }
}

void Catalogue::add_outputs() {
  for (int k = 0; k < shape_.unit_count; ++k) {
    const std::string unit = "unit" + std::to_string(k + 1) + ".";
    ReportReader r{.group = Group::kUnit, .unit = static_cast<std::uint8_t>(k)};
    for (const auto& row : Fields::kUnit) {
      r.of_unit = row.source;
      if (!row.quantity.empty()) add(output(unit + std::string(row.quantity), row.unit, r));
    }
    for (int w = 0; w < 2 * shape_.axle_count[static_cast<std::size_t>(k)]; ++w) {
      const std::string prefix = wheel_prefix(k, w) + ".";
      ReportReader rw{.group = Group::kWheel,
                      .unit = static_cast<std::uint8_t>(k),
                      .index = static_cast<std::uint8_t>(w)};
      for (const auto& row : Fields::kWheel) {
        rw.wheel = row.source;
        if (!row.quantity.empty()) add(output(prefix + std::string(row.quantity), row.unit, rw));
      }
      rw.group = Group::kWheelFlag;
      for (const auto& row : Fields::kWheelFlag) {
        rw.wheel_flag = row.source;
        if (!row.quantity.empty()) add(output(prefix + std::string(row.quantity), row.unit, rw));
      }
    }
  }
  for (const auto& row : Fields::kVehicle) {
    const ReportReader r{.group = Group::kVehicle, .vehicle = row.source};
    if (!row.quantity.empty()) add(output("unit1." + std::string(row.quantity), row.unit, r));
  }
  for (const auto& row : Fields::kVehicleInt) {
    const ReportReader r{.group = Group::kVehicleInt, .vehicle_int = row.source};
    if (!row.quantity.empty()) add(output("unit1." + std::string(row.quantity), row.unit, r));
  }
  for (int i = 0; i < shape_.joint_count; ++i) {
    const ReportReader r{.group = Group::kJoint, .index = static_cast<std::uint8_t>(i)};
    for (const auto& row : Fields::kJoint) {
      ReportReader rj = r;
      rj.joint = row.source;
      if (!row.quantity.empty())
        add(output("joint" + std::to_string(i + 1) + "." + std::string(row.quantity), row.unit,
                   rj));
    }
  }
  add_differential_outputs();
  add_body_outputs();
}

void Catalogue::add_differential_outputs() {
  for (int i = 0; i < shape_.differential_count; ++i) {
    const std::string prefix = "unit1.drivetrain.diff" + std::to_string(i + 1) + ".";
    ReportReader r{.group = Group::kDiff, .index = static_cast<std::uint8_t>(i)};
    for (const auto& row : Fields::kDiff) {
      r.diff = row.source;
      add(output(prefix + std::string(row.quantity), row.unit, r));
    }
    r.group = Group::kDiffFlag;
    for (const auto& row : Fields::kDiffFlag) {
      r.diff_flag = row.source;
      add(output(prefix + std::string(row.quantity), row.unit, r));
    }
  }
}

void Catalogue::add_body_outputs() {
  for (int i = 0; i < shape_.body_count; ++i) {
    const std::string prefix = "body" + std::to_string(i + 1) + ".";
    ReportReader r{.group = Group::kBody, .index = static_cast<std::uint8_t>(i)};
    for (const auto& row : Fields::kBody) {
      r.body = row.source;
      add(output(prefix + std::string(row.quantity), row.unit, r));
    }
    r.group = Group::kBodyFlag;
    for (const auto& row : Fields::kBodyFlag) {
      r.body_flag = row.source;
      add(output(prefix + std::string(row.quantity), row.unit, r));
    }
  }
}

void Catalogue::add_aliases() {
  // wheel_fl .. wheel_rr on two-axle units: every per-wheel name, in and out
  const std::size_t own = entries_.size();
  for (std::size_t e = 0; e < own; ++e) {
    const std::string name = entries_[e].name;
    for (int k = 0; k < shape_.unit_count; ++k) {
      if (shape_.axle_count[static_cast<std::size_t>(k)] != 2) continue;
      for (int w = 0; w < 4; ++w) {
        const std::string prefix = wheel_prefix(k, w) + ".";
        if (name.starts_with(prefix))
          alias(name, "unit" + std::to_string(k + 1) + "." + std::string(kCorners[w]) + "." +
                          name.substr(prefix.size()));
      }
    }
  }
  for (const InputName& i : kUnit1Inputs) alias(i.name, std::string(model::info(i.signal).name));
  for (const std::string_view o : kShortOutputs)
    alias("unit1.steering." + std::string(o), std::string(o));
  alias("unit1.brake_circuit_front_pa", "brake_pressure_front_pa");
  alias("unit1.brake_circuit_rear_pa", "brake_pressure_rear_pa");
  const std::string last = std::to_string(shape_.axle_count[0]);
  for (const InputName& o : kLegacyOutputs) {
    std::string target(o.name);
    if (const auto hash = target.find('#'); hash != std::string::npos)
      target.replace(hash, 1, last);
    alias(target, std::string(model::info(o.signal).name));
    entries_[index_.at(target)].binding.slot = model::index(o.signal);
  }
}

const Entry* Catalogue::find(std::string_view name) const {
  const auto it = index_.find(std::string(name));
  return it == index_.end() ? nullptr : &entries_[it->second];
}

std::vector<std::string> Catalogue::closest(std::string_view name, std::size_t count) const {
  std::vector<std::pair<std::size_t, std::string>> ranked;
  ranked.reserve(index_.size());
  for (const Entry& e : entries_) {
    ranked.emplace_back(edit_distance(name, e.name), e.name);
    for (const std::string& a : e.aliases) ranked.emplace_back(edit_distance(name, a), a);
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> names;
  for (std::size_t i = 0; i < ranked.size() && i < count; ++i) names.push_back(ranked[i].second);
  return names;
}

std::string Catalogue::unknown_message(std::string_view name, std::string_view lead) const {
  std::string text = std::string(lead) + " '" + std::string(name) + "' (closest: ";
  const std::vector<std::string> near = closest(name);
  for (std::size_t i = 0; i < near.size(); ++i) text += (i == 0 ? "" : ", ") + near[i];
  return text + "; `rig signals CONFIG` lists them all)";
}

const Entry& Catalogue::lookup(const config::StrictTable& table, std::string_view key,
                               std::string_view name, bool inputs_only, std::string_view what,
                               std::string_view lead) const {
  const Entry* e = find(name);
  if (e == nullptr) throw table.error(key, unknown_message(name, lead));
  if (inputs_only && e->direction == Direction::kOut)
    throw table.error(key, "'" + std::string(name) + "' is a model output (" + e->name + "); " +
                               std::string(what));
  return *e;
}

}  // namespace rig::io::signals
