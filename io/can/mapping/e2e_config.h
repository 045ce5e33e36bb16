#pragma once
/// @file
/// Reads the `e2e = { profile, data_id, data_id_mode, data_id_list, crc_offset_bits,
/// counter_offset_bits, max_delta_counter }` table of a mapped message (docs/e2e.md), called by
/// read_protection (protection_config.h). Every inconsistency is a ConfigError("file:line").

#include "io/can/dbc/dbc_database.h"
#include "io/can/e2e/e2e_profile.h"
#include "io/config/strict_table.h"

namespace rig::io::can::mapping {

e2e::E2eSpec parse_e2e(config::StrictTable table, const dbc::MessageDef& m);

}  // namespace rig::io::can::mapping
