#pragma once
/// @file
/// What a DBC must mean to be usable, checked after parsing (parse_dbc calls it): message
/// lengths that a CAN (FD) frame can have, signals that do not share bits (multiplexed signals
/// of different pages may), multiplexer values the multiplexor can carry, and [min|max] ranges
/// that are not inverted. Each failure is config::ConfigError("file:line: ...").

#include "io/can/dbc/dbc_database.h"

namespace rig::io::can::dbc {

/// True for the data lengths of a CAN FD frame (DLC 0..15): 0..8, 12, 16, 20, 24, 32, 48, 64.
bool is_can_fd_length(std::uint32_t length_bytes);

/// Throws config::ConfigError at the first line that breaks a rule above.
void check_semantics(const Database& database);

}  // namespace rig::io::can::dbc
