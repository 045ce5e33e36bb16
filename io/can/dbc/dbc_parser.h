#pragma once
/// @file
/// Reads DBC text into a dbc::Database. Load time only (allocates, throws).
///
/// Supported: VERSION, NS_ (skipped), BS_, BU_, BO_ (extended ids with bit 31, CAN FD lengths up
/// to 64 bytes), SG_ (Intel/Motorola, signed/unsigned, factor, offset, [min|max], unit,
/// receivers, `M` and `mN` multiplexing), CM_ (multi-line strings, `\"` escapes), BA_DEF_,
/// BA_DEF_DEF_, BA_ (GenMsgCycleTime per message, GenSigStartValue per signal), VAL_,
/// SIG_VALTYPE_ (1 = float32, 2 = double). Every other section is skipped up to its `;` and
/// noted in Database::warnings.
///
/// Errors throw io::config::ConfigError("file:line: what is wrong"), e.g. a bad BO_ or SG_, a
/// number that does not parse, an unterminated string, a duplicate message id, a signal that does
/// not fit in its message; then the meaning (dbc_semantics.h: CAN FD lengths, overlapping
/// signals, unreachable multiplexer values, inverted ranges). Hostile input is safe: no recursion,
/// bounded work per byte, sizes checked before use (the parser is fuzzed by
/// tests/fuzz/dbc_fuzzer.cpp).

#include <filesystem>
#include <string_view>

#include "io/can/dbc/dbc_database.h"
#include "io/config/config_error.h"

namespace rig::io::can::dbc {

/// Parses DBC text. `file_name` is only used in messages.
Database parse_dbc(std::string_view text, std::string_view file_name);

/// Reads and parses a DBC file. Throws config::ConfigError if it cannot be read or is malformed.
Database load_dbc(const std::filesystem::path& file);

}  // namespace rig::io::can::dbc
