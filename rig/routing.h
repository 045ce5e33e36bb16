#pragma once
/// @file
/// Which source feeds each model input, decided once at start from [routing] and the [driver]:
///
///   CAN     an input [routing] sends from "can" (the ECU's value, decoded by the CAN bridge);
///   driver  an input the driver writes, or one [routing] names "driver";
///   model   every other input (nobody writes it; the model sees it invalid).
///
/// Each consumer is handed, at construction, the set it feeds: the CAN bridge its inputs, the
/// driver its inputs, the model the assist choice. Nobody decides from model::Signals::source
/// at run time; it is filled once, for the tools (LCM signals_t.source).

#include <array>
#include <cstdint>
#include <string>

#include "io/config/strict_table.h"
#include "io/cycle_io.h"
#include "io/signals/catalogue.h"
#include "model/signals.h"

namespace rig {

/// One input's entry in [routing], as written.
enum class RouteRequest : std::uint8_t { kNone, kDriver, kCan };
using RoutingRequests = std::array<RouteRequest, model::kSlotCount>;

/// Each input's [routing] entry: its `file:line` and its name as written ("" for the others).
struct RouteEntry {
  std::string at;
  std::string name;
};
using RouteLocations = std::array<RouteEntry, model::kSlotCount>;

/// Reads [routing]: `<input> = "driver" | "can"`, the input a catalogue name or alias of
/// `catalogue` (io/signals), as one quoted key ("unit1.axle1.left.brake_pressure_pa" = "can") or
/// dotted (unit1.axle1.left.brake_pressure_pa = "can", TOML's nested tables): both are read.
/// ConfigError (file:line) for unknown names (with the closest ones), outputs, values, or an
/// input named twice (by a name and an alias). `where`: each entry's location, if given.
RoutingRequests read_routing(
    io::config::StrictTable& routing_table,
    const io::signals::Catalogue& catalogue = io::signals::Catalogue::two_axle_vehicle(),
    RouteLocations* where = nullptr);

struct Routing {
  std::array<model::SignalSource, model::kSlotCount> source{};  ///< published, per input
  io::InputSet can_inputs;                                      ///< what the CAN bridge feeds
  io::InputSet driver_inputs;                                   ///< what the driver feeds
  /// The assist torque: the ECU's (`assist_torque_nm = "can"`) or the driver table's (a column
  /// `assist_torque_nm`: the maneuver plays the ECU, e.g. 0 for assist off with the ignition on),
  /// else the built-in boost curve.
  bool assist_from_input = false;
  /// The steering angle command has a source (driver or CAN): the robot lets go of the wheel
  /// while it is not valid (model::vehicle::SteeringParams::angle_from_input).
  bool angle_from_input = false;
};

/// `driver_writes`: the inputs the configured driver can write (none without a driver). A
/// request for CAN wins over the driver.
Routing resolve_routing(const RoutingRequests& requests, const io::InputSet& driver_writes);

}  // namespace rig
