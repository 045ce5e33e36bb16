#pragma once
/// @file
/// The CSV of rig.vehicle_state_t: its columns are the rows of io/lcm/vehicle_state_fields.h
/// (arrays flattened per element: unit0_x_m, wheel3_load_n, joint0_force_x_n) after the
/// message's frame (timing, group counts, wheel<i>_unit).

#include <memory>

#include "rig/log2csv/channel_csv.h"

namespace rig::log2csv {

std::unique_ptr<ChannelCsv> make_vehicle_state_csv();

}  // namespace rig::log2csv
