#include "io/can/e2e/e2e_profile.h"

#include "io/can/e2e/crc.h"

namespace rig::io::can::e2e {
namespace {

// Profile 1 uses the SAE J1850 polynomial with start and final XOR 0x00.
constexpr Crc kP01Crc(CrcParams{8, 0x1D, 0x00, false, false, 0x00});
constexpr Crc kP02Crc(presets::kCrc8H2F);
constexpr Crc kP04Crc(presets::kCrc32P4);
constexpr Crc kP05Crc(presets::kCrc16CcittFalse);

/// A nibble at a bit offset that is a multiple of 4.
std::uint32_t get_nibble(const std::uint8_t* data, std::uint32_t offset_bits) noexcept {
  const std::uint8_t byte = data[offset_bits / 8];
  return offset_bits % 8 == 0 ? byte & 0x0Fu : byte >> 4;
}
void set_nibble(std::uint8_t* data, std::uint32_t offset_bits, std::uint32_t value) noexcept {
  std::uint8_t& byte = data[offset_bits / 8];
  const auto v = static_cast<std::uint8_t>(value & 0x0Fu);
  byte = offset_bits % 8 == 0 ? static_cast<std::uint8_t>((byte & 0xF0u) | v)
                              : static_cast<std::uint8_t>((byte & 0x0Fu) | (v << 4));
}

std::uint32_t get_be(const std::uint8_t* p, unsigned bytes) noexcept {
  std::uint32_t v = 0;
  for (unsigned i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}
void set_be(std::uint8_t* p, unsigned bytes, std::uint32_t v) noexcept {
  for (unsigned i = 0; i < bytes; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * (bytes - 1 - i)));
}

/// CRC over every byte of the frame except `skip` bytes from `from` (the CRC field).
std::uint32_t crc_around(const Crc& crc, std::uint32_t reg, const std::uint8_t* data,
                         std::uint32_t len, std::uint32_t from, std::uint32_t skip) noexcept {
  reg = crc.update(reg, data, from);
  return crc.update(reg, data + from + skip, len - from - skip);
}

std::uint32_t p01_crc(const E2eSpec& s, const std::uint8_t* data, std::uint32_t counter) noexcept {
  const std::uint8_t id_low = s.data_id & 0xFFu;
  const std::uint8_t id_high = (s.data_id >> 8) & 0xFFu;
  const std::uint8_t zero = 0;
  std::uint32_t reg = kP01Crc.begin();
  switch (s.data_id_mode) {
    case DataIdMode::kBoth:
      reg = kP01Crc.update(reg, &id_low, 1);
      reg = kP01Crc.update(reg, &id_high, 1);
      break;
    case DataIdMode::kAlt:
      reg = kP01Crc.update(reg, counter % 2 == 0 ? &id_low : &id_high, 1);
      break;
    case DataIdMode::kLow:
      reg = kP01Crc.update(reg, &id_low, 1);
      break;
    case DataIdMode::kNibble:  // the high byte's nibble travels in the frame, a zero in the CRC
      reg = kP01Crc.update(reg, &id_low, 1);
      reg = kP01Crc.update(reg, &zero, 1);
      break;
  }
  reg = crc_around(kP01Crc, reg, data, s.length_bytes, s.crc_offset_bits / 8, 1);
  return kP01Crc.finish(reg);
}

std::uint32_t p02_crc(const E2eSpec& s, const std::uint8_t* data, std::uint32_t counter) noexcept {
  std::uint32_t reg = kP02Crc.update(kP02Crc.begin(), data + 1, s.length_bytes - 1);
  reg = kP02Crc.update(reg, &s.data_id_list[counter & 0x0Fu], 1);
  return kP02Crc.finish(reg);
}

std::uint32_t p04_crc(const E2eSpec& s, const std::uint8_t* data) noexcept {
  const std::uint32_t o = s.offset_bits / 8;
  return kP04Crc.finish(crc_around(kP04Crc, kP04Crc.begin(), data, s.length_bytes, o + 8, 4));
}

std::uint32_t p05_crc(const E2eSpec& s, const std::uint8_t* data) noexcept {
  const std::uint32_t o = s.offset_bits / 8;
  std::uint32_t reg = crc_around(kP05Crc, kP05Crc.begin(), data, s.length_bytes, o, 2);
  const std::uint8_t id[2] = {static_cast<std::uint8_t>(s.data_id & 0xFFu),
                              static_cast<std::uint8_t>((s.data_id >> 8) & 0xFFu)};
  return kP05Crc.finish(kP05Crc.update(reg, id, 2));
}

void mark(std::array<std::uint8_t, 64>& mask, std::uint32_t offset_bits, std::uint32_t bits) {
  for (std::uint32_t b = offset_bits; b < offset_bits + bits && b / 8 < mask.size(); ++b)
    mask[b / 8] = static_cast<std::uint8_t>(mask[b / 8] | (1u << (b % 8)));
}

}  // namespace

std::uint32_t counter_modulus(Profile p) noexcept {
  switch (p) {
    case Profile::kP01:
      return 15;
    case Profile::kP02:
      return 16;
    case Profile::kP04:
      return 65536;
    case Profile::kP05:
      return 256;
  }
  return 16;
}

std::array<std::uint8_t, 64> field_mask(const E2eSpec& s) noexcept {
  std::array<std::uint8_t, 64> mask{};
  switch (s.profile) {
    case Profile::kP01:
      mark(mask, s.crc_offset_bits, 8);
      mark(mask, s.counter_offset_bits, 4);
      if (s.data_id_mode == DataIdMode::kNibble) mark(mask, kP01NibbleOffsetBits, 4);
      break;
    case Profile::kP02:
      mark(mask, 0, 8);
      mark(mask, 8, 4);
      break;
    case Profile::kP04:
      mark(mask, s.offset_bits, 96);
      break;
    case Profile::kP05:
      mark(mask, s.offset_bits, 24);
      break;
  }
  return mask;
}

void protect(const E2eSpec& s, std::uint8_t* data, std::uint32_t counter) noexcept {
  const std::uint32_t o = s.offset_bits / 8;
  switch (s.profile) {
    case Profile::kP01:
      set_nibble(data, s.counter_offset_bits, counter);
      if (s.data_id_mode == DataIdMode::kNibble)
        set_nibble(data, kP01NibbleOffsetBits, s.data_id >> 8);
      data[s.crc_offset_bits / 8] = static_cast<std::uint8_t>(p01_crc(s, data, counter));
      break;
    case Profile::kP02:
      set_nibble(data, 8, counter);
      data[0] = static_cast<std::uint8_t>(p02_crc(s, data, counter));
      break;
    case Profile::kP04:
      set_be(data + o, 2, s.length_bytes);
      set_be(data + o + 2, 2, counter);
      set_be(data + o + 4, 4, s.data_id);
      set_be(data + o + 8, 4, p04_crc(s, data));
      break;
    case Profile::kP05: {
      data[o + 2] = static_cast<std::uint8_t>(counter);
      const std::uint32_t crc = p05_crc(s, data);
      data[o] = static_cast<std::uint8_t>(crc & 0xFFu);
      data[o + 1] = static_cast<std::uint8_t>(crc >> 8);
      break;
    }
  }
}

CheckResult check(const E2eSpec& s, const std::uint8_t* data) noexcept {
  const std::uint32_t o = s.offset_bits / 8;
  CheckResult r;
  switch (s.profile) {
    case Profile::kP01:
      r.counter = get_nibble(data, s.counter_offset_bits);
      r.crc_ok = data[s.crc_offset_bits / 8] == p01_crc(s, data, r.counter) &&
                 (s.data_id_mode != DataIdMode::kNibble ||
                  get_nibble(data, kP01NibbleOffsetBits) == ((s.data_id >> 8) & 0x0Fu));
      break;
    case Profile::kP02:
      r.counter = get_nibble(data, 8);
      r.crc_ok = data[0] == p02_crc(s, data, r.counter);
      break;
    case Profile::kP04:
      r.counter = get_be(data + o + 2, 2);
      r.crc_ok = get_be(data + o + 8, 4) == p04_crc(s, data) &&
                 get_be(data + o, 2) == s.length_bytes && get_be(data + o + 4, 4) == s.data_id;
      break;
    case Profile::kP05:
      r.counter = data[o + 2];
      r.crc_ok = (data[o] | (std::uint32_t{data[o + 1]} << 8)) == p05_crc(s, data);
      break;
  }
  return r;
}

}  // namespace rig::io::can::e2e
