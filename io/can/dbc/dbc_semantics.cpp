#include "io/can/dbc/dbc_semantics.h"

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "io/can/dbc/signal_codec.h"
#include "io/config/config_error.h"

namespace rig::io::can::dbc {
namespace {

constexpr std::size_t kMaxBits = std::size_t{64} * 8;
constexpr int kFree = -1;

/// Per bit of a frame: the index of the signal that holds it, or kFree.
using Occupancy = std::array<int, kMaxBits>;

[[noreturn]] void fail(const Database& db, int line, const std::string& what) {
  throw config::ConfigError(db.file + ":" + std::to_string(line) + ": " + what);
}

/// Marks the bits of signal `si` in `taken`; on a bit already held by another signal, fails
/// naming both.
void occupy(const Database& db, const MessageDef& m, std::size_t si, Occupancy& taken) {
  const SignalDef& s = m.signals[si];
  std::array<std::uint8_t, 64> mask{};
  SignalCodec(s).insert_raw(~std::uint64_t{0}, mask.data());
  for (std::size_t bit = 0; bit < kMaxBits; ++bit) {
    if ((mask[bit / 8] & (1u << (bit % 8))) == 0) continue;
    if (taken[bit] != kFree) {
      const SignalDef& other = m.signals[static_cast<std::size_t>(taken[bit])];
      fail(db, s.line,
           "signal " + s.name + " overlaps signal " + other.name + " (line " +
               std::to_string(other.line) + ") in message " + m.name + " (bit " +
               std::to_string(bit % 8) + " of byte " + std::to_string(bit / 8) + ")");
    }
    taken[bit] = static_cast<int>(si);
  }
}

void check_range(const Database& db, const SignalDef& s) {
  if (s.minimum > s.maximum) {
    std::ostringstream msg;
    msg << "signal " << s.name << " has an inverted range [" << s.minimum << "|" << s.maximum
        << "] (minimum above maximum)";
    fail(db, s.line, msg.str());
  }
}

/// A page value mN must be a raw value of the multiplexor (its bits, its [min|max] if given).
void check_page_value(const Database& db, const MessageDef& m, const SignalDef& mux,
                      const SignalDef& s) {
  const double raw_max = std::ldexp(1.0, static_cast<int>(mux.length_bits)) - 1.0;
  const double physical = s.mux_value * mux.factor + mux.offset;
  const bool in_bits = s.mux_value <= raw_max;
  const bool in_range = !mux.has_range() || (physical >= mux.minimum && physical <= mux.maximum);
  if (!in_bits || !in_range) {
    fail(db, s.line,
         "multiplexed signal " + s.name + " (m" + std::to_string(s.mux_value) +
             ") is unreachable: multiplexor " + mux.name + " of message " + m.name +
             (in_bits ? " has a smaller [min|max] range" : " has too few bits"));
  }
}

void check_message(const Database& db, const MessageDef& m) {
  if (!is_can_fd_length(m.length_bytes)) {
    fail(db, m.line,
         "message " + m.name + " has length " + std::to_string(m.length_bytes) +
             ", not a CAN FD frame length (0-8, 12, 16, 20, 24, 32, 48 or 64 bytes)");
  }
  const SignalDef* mux = nullptr;
  Occupancy plain;  // every frame: plain signals and the multiplexor
  plain.fill(kFree);
  for (std::size_t i = 0; i < m.signals.size(); ++i) {
    const SignalDef& s = m.signals[i];
    check_range(db, s);
    if (s.mux_role == MuxRole::kMultiplexor) mux = &s;
    if (s.mux_role != MuxRole::kMultiplexed) occupy(db, m, i, plain);
  }
  std::map<std::uint32_t, Occupancy> pages;  // each page: the plain bits plus its own signals
  for (std::size_t i = 0; i < m.signals.size(); ++i) {
    const SignalDef& s = m.signals[i];
    if (s.mux_role != MuxRole::kMultiplexed || mux == nullptr) continue;
    check_page_value(db, m, *mux, s);
    auto [page, fresh] = pages.try_emplace(s.mux_value, plain);
    occupy(db, m, i, page->second);
  }
}

}  // namespace

bool is_can_fd_length(std::uint32_t length_bytes) {
  return length_bytes <= 8 || length_bytes == 12 || length_bytes == 16 || length_bytes == 20 ||
         length_bytes == 24 || length_bytes == 32 || length_bytes == 48 || length_bytes == 64;
}

void check_semantics(const Database& database) {
  for (const MessageDef& m : database.messages) check_message(database, m);
}

}  // namespace rig::io::can::dbc
