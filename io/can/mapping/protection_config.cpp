#include "io/can/mapping/protection_config.h"

#include <cmath>
#include <string>
#include <string_view>

#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/e2e_config.h"

namespace rig::io::can::mapping {
namespace {

using Mask = std::array<std::uint8_t, 64>;

std::size_t signal_index(config::StrictTable& t, std::string_view key, const dbc::MessageDef& m) {
  const std::string name = t.string(key);
  for (std::size_t i = 0; i < m.signals.size(); ++i) {
    if (m.signals[i].name == name) return i;
  }
  throw t.error(key, "no signal '" + name + "' in message " + m.name);
}

/// The bits a signal occupies in a frame.
Mask bit_mask(const dbc::SignalDef& s) {
  Mask mask{};
  dbc::SignalCodec(s).insert_raw(~std::uint64_t{0}, mask.data());
  return mask;
}

bool overlap(const Mask& a, const Mask& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if ((a[i] & b[i]) != 0) return true;
  }
  return false;
}

Mask checksum_mask(const ChecksumSpec& c, const dbc::MessageDef& m) {
  if (!c.position_byte) return bit_mask(m.signals[c.dbc_signal]);
  Mask mask{};
  for (unsigned i = 0; i < c.crc.params().width / 8u; ++i) mask[*c.position_byte + i] = 0xFF;
  return mask;
}

CounterSpec parse_counter(config::StrictTable t, const dbc::MessageDef& m) {
  CounterSpec c;
  c.dbc_signal = signal_index(t, "signal", m);
  const auto& s = m.signals[c.dbc_signal];
  const double max_modulus =
      s.length_bits >= 32 ? 4294967295.0 : std::ldexp(1.0, static_cast<int>(s.length_bits));
  if (s.value_type != dbc::ValueType::kInteger || s.mux_role == dbc::MuxRole::kMultiplexed)
    throw t.error("signal", "counter must be an integer signal present in every frame");
  c.modulus =
      static_cast<std::uint32_t>(t.integer_in("modulus", 2, static_cast<long long>(max_modulus)));
  c.max_step = static_cast<std::uint32_t>(t.integer_in("max_step", 1, 1, c.modulus - 1LL));
  c.unlatch_steps = static_cast<std::uint32_t>(t.integer_in("unlatch_steps", 1, 1, 1000));
  t.finish();
  return c;
}

/// `type = "crc"`: width, poly, init, refin, refout, xorout (width 8, 16 or 32).
e2e::CrcParams parse_crc_params(config::StrictTable& t) {
  const long long width = t.integer("width");
  if (width != 8 && width != 16 && width != 32) {
    throw t.error("width", "CRC width " + std::to_string(width) + " is not supported: 8, 16 or 32");
  }
  const long long max = (1LL << width) - 1;
  e2e::CrcParams p;
  p.width = static_cast<std::uint8_t>(width);
  p.poly = static_cast<std::uint32_t>(t.integer_in("poly", 1, max));
  p.init = static_cast<std::uint32_t>(t.integer_in("init", 0, 0, max));
  p.refin = t.boolean("refin", false);
  p.refout = t.boolean("refout", false);
  p.xorout = static_cast<std::uint32_t>(t.integer_in("xorout", 0, 0, max));
  return p;
}

/// Where the checksum goes: a DBC signal (`signal`, its own byte order) or `position`.
void parse_checksum_place(config::StrictTable& t, const dbc::MessageDef& m, ChecksumSpec& c) {
  const unsigned width = c.type == ChecksumType::kCrc ? c.crc.params().width : 8u;
  if (t.has("position") && t.has("signal"))
    throw t.error("position", "give the checksum's signal or its position, not both");
  if (t.has("position")) {
    if (c.type != ChecksumType::kCrc) throw t.error("position", "position is for type = \"crc\"");
    const long long at = t.integer("position");
    if (at < 0 || at + width / 8 > static_cast<long long>(m.length_bytes)) {
      throw t.error("position", "a " + std::to_string(width) + "-bit CRC at byte " +
                                    std::to_string(at) + " does not fit message " + m.name + " (" +
                                    std::to_string(m.length_bytes) + " bytes)");
    }
    c.position_byte = static_cast<std::uint32_t>(at);
    return;
  }
  c.dbc_signal = signal_index(t, "signal", m);
  const auto& s = m.signals[c.dbc_signal];
  if (s.length_bits != width || s.value_type != dbc::ValueType::kInteger ||
      s.mux_role == dbc::MuxRole::kMultiplexed) {
    throw t.error("signal", "checksum signal " + s.name + " must be a plain " +
                                std::to_string(width) + "-bit integer");
  }
}

void parse_checksum_bytes(config::StrictTable& t, const dbc::MessageDef& m, ChecksumSpec& c) {
  const Mask own = checksum_mask(c, m);  // the bytes of the checksum itself
  if (t.has("bytes")) {
    // At most one entry per byte of the message: the covered bytes are gathered on the stack.
    bool listed[64] = {};
    for (const long long b : t.integers("bytes", m.length_bytes)) {
      if (b < 0 || b >= m.length_bytes) {
        throw t.error("bytes", "byte index " + std::to_string(b) + " is outside message " + m.name +
                                   " (" + std::to_string(m.length_bytes) + " bytes)");
      }
      const auto i = static_cast<std::size_t>(b);
      if (own[i] != 0) throw t.error("bytes", "covered bytes include the checksum itself");
      if (listed[i]) throw t.error("bytes", "byte " + std::to_string(i) + " is listed twice");
      listed[i] = true;
      c.bytes.push_back(static_cast<std::uint8_t>(b));
    }
  } else {
    for (std::uint32_t b = 0; b < m.length_bytes; ++b) {
      if (own[b] == 0) c.bytes.push_back(static_cast<std::uint8_t>(b));
    }
  }
}

ChecksumSpec parse_checksum(config::StrictTable t, const dbc::MessageDef& m) {
  ChecksumSpec c;
  const std::string type = t.choice("type", "crc8_sae_j1850", {"crc8_sae_j1850", "xor", "crc"});
  c.type = type == "xor"   ? ChecksumType::kXor
           : type == "crc" ? ChecksumType::kCrc
                           : ChecksumType::kCrc8SaeJ1850;
  if (c.type == ChecksumType::kCrc) c.crc = e2e::Crc(parse_crc_params(t));
  parse_checksum_place(t, m, c);
  parse_checksum_bytes(t, m, c);
  t.finish();
  return c;
}

}  // namespace

Protection read_protection(config::StrictTable& t, const dbc::MessageDef& m) {
  Protection p;
  if (auto c = t.optional_table("counter")) p.counter = parse_counter(std::move(*c), m);
  if (auto c = t.optional_table("checksum")) p.checksum = parse_checksum(std::move(*c), m);
  if (p.counter && p.checksum &&
      overlap(bit_mask(m.signals[p.counter->dbc_signal]), checksum_mask(*p.checksum, m))) {
    const std::string sum = p.checksum->position_byte
                                ? "at byte " + std::to_string(*p.checksum->position_byte)
                                : m.signals[p.checksum->dbc_signal].name;
    throw t.error("checksum", "counter " + m.signals[p.counter->dbc_signal].name +
                                  " and checksum " + sum + " share bits of message " + m.name);
  }
  if (t.has("e2e") && (p.counter || p.checksum)) {
    throw t.error("e2e", std::string("e2e protection brings its own counter and CRC: remove the ") +
                             (p.checksum ? "checksum" : "counter") + " of message " + m.name);
  }
  if (auto e = t.optional_table("e2e")) p.e2e = parse_e2e(std::move(*e), m);
  return p;
}

Mask protection_mask(const Protection& p, const dbc::MessageDef& m) {
  Mask mask{};
  if (p.counter) mask = bit_mask(m.signals[p.counter->dbc_signal]);
  if (p.checksum) {
    const Mask c = checksum_mask(*p.checksum, m);
    for (std::size_t i = 0; i < mask.size(); ++i)
      mask[i] = static_cast<std::uint8_t>(mask[i] | c[i]);
  }
  if (p.e2e) mask = e2e::field_mask(*p.e2e);
  return mask;
}

void check_not_protected(config::StrictTable& st, const dbc::MessageDef& m, const Protection& p,
                         std::size_t dbc_signal) {
  const dbc::SignalDef& s = m.signals[dbc_signal];
  if (p.counter && p.counter->dbc_signal == dbc_signal)
    throw st.error("dbc", "signal " + s.name + " is the alive counter, it cannot be mapped");
  if (p.checksum && !p.checksum->position_byte && p.checksum->dbc_signal == dbc_signal)
    throw st.error("dbc", "signal " + s.name + " is the checksum, it cannot be mapped");
  if (p.checksum && p.checksum->position_byte &&
      overlap(bit_mask(s), checksum_mask(*p.checksum, m)))
    throw st.error("dbc", "signal " + s.name + " overlaps the checksum of message " + m.name);
  if (p.e2e && overlap(bit_mask(s), e2e::field_mask(*p.e2e))) {
    throw st.error("dbc", "signal " + s.name + " overlaps the E2E counter/CRC/header of message " +
                              m.name + ": it cannot be mapped");
  }
}

}  // namespace rig::io::can::mapping
