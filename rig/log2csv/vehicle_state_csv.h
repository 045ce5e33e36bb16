#pragma once
/// @file
/// The CSV of rig.vehicle_state_t: its columns are the rows of io/lcm/vehicle_state_fields.h
/// (arrays flattened per element: unit0_x_m, wheel3_load_n, joint0_force_x_n) after the
/// message's frame (timing, group counts, wheel<i>_unit). A log of an earlier layout
/// (legacy_vehicle_state.h) has the columns of the rows it had.

#include <memory>

#include "rig/log2csv/channel_csv.h"
#include "rig/log2csv/legacy_vehicle_state.h"

namespace rig::log2csv {

std::unique_ptr<ChannelCsv> make_vehicle_state_csv(const VehicleStateLayout& layout);

}  // namespace rig::log2csv
