#pragma once
/// @file
/// Reads the protection of one mapped message, the keys `counter`, `checksum` and `e2e` of a
/// [[rx]] or [[tx]] table (and of every message a [[restbus]] expands into): THE one reader of
/// these keys, with their contradictions (counter and checksum sharing bits; e2e with either).
/// Formats: can_mapping.h, docs/e2e.md. Load time; errors are config::ConfigError("file:line").

#include <array>
#include <cstdint>
#include <optional>

#include "io/can/dbc/dbc_database.h"
#include "io/can/mapping/can_mapping.h"
#include "io/config/strict_table.h"

namespace rig::io::can::mapping {

struct Protection {
  std::optional<CounterSpec> counter;
  std::optional<ChecksumSpec> checksum;
  std::optional<e2e::E2eSpec> e2e;
};

/// Reads `counter`, `checksum` and `e2e` (each optional) of `message_table` for message `m`.
Protection read_protection(config::StrictTable& message_table, const dbc::MessageDef& m);

/// The bits of a frame the protection writes (counter, checksum, E2E fields), a 64-byte mask.
std::array<std::uint8_t, 64> protection_mask(const Protection& p, const dbc::MessageDef& m);

/// Throws (at `dbc` of `signal_table`) if DBC signal `dbc_signal` of `m` shares bits with the
/// protection: such a signal cannot be mapped.
void check_not_protected(config::StrictTable& signal_table, const dbc::MessageDef& m,
                         const Protection& p, std::size_t dbc_signal);

}  // namespace rig::io::can::mapping
