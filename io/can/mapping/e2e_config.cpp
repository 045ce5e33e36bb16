#include "io/can/mapping/e2e_config.h"

#include <cstdio>
#include <string>
#include <string_view>

namespace rig::io::can::mapping {
namespace {

using e2e::DataIdMode;
using e2e::Profile;

std::string hex(long long v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llX", v);
  return buf;
}

Profile parse_profile(config::StrictTable& t) {
  const std::string name = t.string("profile");
  if (name == "P01") return Profile::kP01;
  if (name == "P02") return Profile::kP02;
  if (name == "P04") return Profile::kP04;
  if (name == "P05") return Profile::kP05;
  throw t.error("profile", "unknown E2E profile '" + name + "': give P01, P02, P04 or P05");
}

/// Rejects a key the profile has no use for (a contradiction, not a default).
void reject(config::StrictTable& t, std::string_view key, std::string_view profile) {
  if (t.has(key)) {
    throw t.error(key, std::string(key) + " is not a parameter of E2E profile " +
                           std::string(profile) + " (docs/e2e.md)");
  }
}

std::uint32_t data_id(config::StrictTable& t, long long max, std::string_view what) {
  const long long id = t.integer("data_id");
  if (id < 0 || id > max) {
    throw t.error("data_id", "data_id " + hex(id) + " is outside 0.." + hex(max) + " (" +
                                 std::string(what) + ")");
  }
  return static_cast<std::uint32_t>(id);
}

/// An offset key in bits: a multiple of `step`, the field of `bits` inside the frame.
std::uint32_t offset(config::StrictTable& t, std::string_view key, long long fallback,
                     unsigned step, unsigned bits, const dbc::MessageDef& m) {
  const long long o = t.integer(key, fallback);
  const long long frame_bits = 8LL * m.length_bytes;
  if (o < 0 || o + bits > frame_bits) {
    throw t.error(key, std::string(key) + " = " + std::to_string(o) + ": the " +
                           std::to_string(bits) + "-bit field there lies outside message " +
                           m.name + " (" + std::to_string(m.length_bytes) + " bytes)");
  }
  if (o % step != 0)
    throw t.error(key, std::string(key) + " must be a multiple of " + std::to_string(step));
  return static_cast<std::uint32_t>(o);
}

void parse_p01(config::StrictTable& t, const dbc::MessageDef& m, e2e::E2eSpec& s) {
  reject(t, "data_id_list", "P01");
  const std::string mode = t.choice("data_id_mode", "BOTH", {"BOTH", "ALT", "LOW", "NIBBLE"});
  s.data_id_mode = mode == "ALT"      ? DataIdMode::kAlt
                   : mode == "LOW"    ? DataIdMode::kLow
                   : mode == "NIBBLE" ? DataIdMode::kNibble
                                      : DataIdMode::kBoth;
  const long long max = mode == "LOW" ? 0xFF : mode == "NIBBLE" ? 0xFFF : 0xFFFF;
  s.data_id = data_id(t, max, "P01 data_id_mode " + mode);
  s.crc_offset_bits = offset(t, "crc_offset_bits", 0, 8, 8, m);
  s.counter_offset_bits = offset(t, "counter_offset_bits", 8, 4, 4, m);
  const std::uint32_t c = s.counter_offset_bits;
  if (c / 8 == s.crc_offset_bits / 8)
    throw t.error("counter_offset_bits", "the counter overlaps the CRC byte");
  if (s.data_id_mode == DataIdMode::kNibble) {
    if (m.length_bytes < 2 || c == e2e::kP01NibbleOffsetBits || s.crc_offset_bits == 8) {
      throw t.error("data_id_mode",
                    "NIBBLE sends the Data ID nibble at bit 12, which the counter "
                    "or the CRC occupies (or the message is too short)");
    }
  }
}

void parse_p02(config::StrictTable& t, const dbc::MessageDef& m, e2e::E2eSpec& s) {
  reject(t, "data_id", "P02 (it takes data_id_list)");
  reject(t, "data_id_mode", "P02");
  if (m.length_bytes < 2) throw t.error("profile", "P02 needs a message of 2 bytes at least");
  // The layout of profile 2 is fixed: CRC in byte 0, counter in the low nibble of byte 1.
  if (t.integer("crc_offset_bits", 0) != 0) throw t.error("crc_offset_bits", "P02: must be 0");
  if (t.integer("counter_offset_bits", 8) != 8)
    throw t.error("counter_offset_bits", "P02: must be 8");
  if (!t.has("data_id_list"))
    throw t.error("data_id_list", "P02 needs data_id_list (16 Data IDs, one per counter value)");
  const std::vector<long long> list = t.integers("data_id_list", 64);
  if (list.size() != s.data_id_list.size()) {
    throw t.error("data_id_list", "data_id_list has " + std::to_string(list.size()) +
                                      " entries: P02 needs 16, one per counter value 0..15");
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i] < 0 || list[i] > 0xFF) {
      throw t.error("data_id_list", "data_id_list[" + std::to_string(i) +
                                        "] = " + std::to_string(list[i]) + " is outside 0..255");
    }
    s.data_id_list[i] = static_cast<std::uint8_t>(list[i]);
  }
}

/// P04 and P05: one header at an offset; `crc_offset_bits` or `counter_offset_bits` place it.
void parse_header(config::StrictTable& t, const dbc::MessageDef& m, e2e::E2eSpec& s,
                  std::string_view name, unsigned crc_at, unsigned counter_at, unsigned bits) {
  reject(t, "data_id_list", name);
  reject(t, "data_id_mode", name);
  s.data_id = data_id(t, name == "P04" ? 0xFFFFFFFFLL : 0xFFFF, std::string(name));
  const long long from_crc = t.integer("crc_offset_bits", crc_at) - crc_at;
  const long long from_counter = t.integer("counter_offset_bits", counter_at) - counter_at;
  if (t.has("crc_offset_bits") && t.has("counter_offset_bits") && from_crc != from_counter) {
    throw t.error("counter_offset_bits", std::string(name) + ": the counter lies " +
                                             std::to_string(counter_at) +
                                             " bits into the header, the CRC " +
                                             std::to_string(crc_at) + ": offsets disagree");
  }
  const long long header = t.has("crc_offset_bits") ? from_crc : from_counter;
  const std::string_view key = t.has("crc_offset_bits") ? "crc_offset_bits" : "counter_offset_bits";
  if (header < 0 || header % 8 != 0 || header + bits > 8LL * m.length_bytes) {
    throw t.error(key, std::string(name) + ": the " + std::to_string(bits / 8) +
                           "-byte header would start at bit " + std::to_string(header) +
                           ", not a byte inside message " + m.name + " (" +
                           std::to_string(m.length_bytes) + " bytes)");
  }
  s.offset_bits = static_cast<std::uint32_t>(header);
  s.crc_offset_bits = s.offset_bits + crc_at;
  s.counter_offset_bits = s.offset_bits + counter_at;
}

}  // namespace

e2e::E2eSpec parse_e2e(config::StrictTable t, const dbc::MessageDef& m) {
  e2e::E2eSpec s;
  s.profile = parse_profile(t);
  s.length_bytes = m.length_bytes;
  switch (s.profile) {
    case Profile::kP01:
      parse_p01(t, m, s);
      break;
    case Profile::kP02:
      parse_p02(t, m, s);
      break;
    case Profile::kP04:  // Length 0, Counter 16, Data ID 32, CRC 64 bits into the header
      parse_header(t, m, s, "P04", 64, 16, 96);
      break;
    case Profile::kP05:  // CRC 0, Counter 16 bits into the header
      parse_header(t, m, s, "P05", 0, 16, 24);
      break;
  }
  const long long modulus = e2e::counter_modulus(s.profile);
  s.max_delta_counter =
      static_cast<std::uint32_t>(t.integer_in("max_delta_counter", 1, 1, modulus - 1));
  t.finish();
  return s;
}

}  // namespace rig::io::can::mapping
