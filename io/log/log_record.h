#pragma once
/// @file
/// One entry of the overrun/event log (plain data, fixed size: it travels through the rig's
/// lock-free ring) and its JSON line.

#include <array>
#include <cstdint>
#include <string>

#include "io/snapshot.h"

namespace rig::io::log {

struct LogRecord {
  enum class Kind : std::uint8_t { kMiss, kEvent };
  Kind kind = Kind::kEvent;
  std::int64_t realtime_ns = 0;    ///< CLOCK_REALTIME
  std::int64_t monotonic_ns = 0;   ///< CLOCK_MONOTONIC
  CycleTiming timing{};            ///< kMiss: the late cycle
  std::array<char, 24> name{};     ///< kEvent: event name; kMiss: the policy's action
  std::array<char, 160> detail{};  ///< kEvent: free text (JSON-escaped on output)
};

/// Formats one record as a JSON line (no newline).
std::string format_record(const LogRecord& record);

}  // namespace rig::io::log
