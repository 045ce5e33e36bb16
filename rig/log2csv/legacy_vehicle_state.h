#pragma once
/// @file
/// rig.vehicle_state_t as logs written before its last change carry it: each earlier layout is
/// frozen in io/lcm/lcmtypes/legacy/ (its fingerprint is the old one) and decoded here into
/// today's message, with the rows of the field table it did not have named, so that rig-log2csv
/// writes such a log's CSV with the columns it had (and only those).

#include <cstdint>
#include <string_view>

#include "rig/log2csv/channel_csv.h"
#include "rig/vehicle_state_t.hpp"

namespace rig::log2csv {

/// How one layout of rig.vehicle_state_t is read.
struct VehicleStateLayout {
  const char* type_name;  ///< as rig-log2csv reports it
  /// Decodes `event` into today's message; false if it does not decode.
  bool (*decode)(const Event& event, rig::vehicle_state_t& msg);
  /// Whether the layout has the field table's row `name` (io/lcm/vehicle_state_fields.h).
  bool (*has_row)(std::string_view name);
};

/// Today's layout.
[[nodiscard]] const VehicleStateLayout& current_vehicle_state_layout();
/// The earlier layout whose fingerprint is `hash`, or nullptr.
[[nodiscard]] const VehicleStateLayout* legacy_vehicle_state_layout(std::int64_t hash);

}  // namespace rig::log2csv
