#pragma once
/// @file
/// AUTOSAR E2E protection of one frame (E2E Protocol Specification, profiles 1, 2, 4 and 5),
/// written for the rig from the specification: protect() fills counter, CRC (and the explicit
/// header fields) of a frame about to be sent; check() verifies a received frame's CRC with the
/// configured Data ID and returns its counter, which the caller hands to the one sequence
/// checker (io/can/mapping/sequence_checker.h). Offsets are in bits, bit n = bit n % 8 (LSB 0)
/// of byte n / 8, as in the specification.
///
///   P01  CRC-8 SAE J1850 poly, init 0x00, xorout 0x00, over the Data ID (per data_id_mode)
///        then every byte but the CRC byte; 4-bit counter 0..14; NIBBLE mode sends the low
///        nibble of the Data ID's high byte at bit 12.
///   P02  CRC-8H2F over bytes 1..n-1 then DataIDList[counter]; CRC in byte 0, 4-bit counter
///        0..15 in the low nibble of byte 1.
///   P04  12-byte header at `offset`: Length (16, big-endian), Counter (16), Data ID (32), CRC
///        (32, CRC-32P4 over every byte but the CRC).
///   P05  CRC-16/CCITT-FALSE at `offset` (little-endian), 8-bit counter at offset + 16; CRC over
///        every byte but the CRC, then the Data ID, low byte first.
///
/// Plain data and pure functions: allocation-free, noexcept (RT-safe).

#include <array>
#include <cstddef>
#include <cstdint>

namespace rig::io::can::e2e {

enum class Profile : std::uint8_t { kP01, kP02, kP04, kP05 };
enum class DataIdMode : std::uint8_t { kBoth, kAlt, kLow, kNibble };  ///< Profile 1 only

/// Bit offset of the explicit Data ID nibble of P01 NIBBLE mode (the specification's default).
inline constexpr std::uint32_t kP01NibbleOffsetBits = 12;

struct E2eSpec {
  Profile profile = Profile::kP01;
  std::uint32_t data_id = 0;                    ///< P01 (16 bit), P04 (32 bit), P05 (16 bit)
  DataIdMode data_id_mode = DataIdMode::kBoth;  ///< P01
  std::array<std::uint8_t, 16> data_id_list{};  ///< P02: Data ID per counter value
  std::uint32_t crc_offset_bits = 0;            ///< P01, P02 (0): the CRC byte
  std::uint32_t counter_offset_bits = 8;        ///< P01, P02 (8): the counter nibble
  std::uint32_t offset_bits = 0;                ///< P04, P05: start of the header
  std::uint32_t max_delta_counter = 1;          ///< accepted counter step 1..max_delta_counter
  std::uint32_t length_bytes = 8;               ///< the frame's (DBC) length
};

/// Counter values 0 .. modulus - 1 (P01 15: 0x0F is not a counter value).
std::uint32_t counter_modulus(Profile p) noexcept;

/// The bytes/bits the profile writes, as a 64-byte mask (load time: overlap checks).
std::array<std::uint8_t, 64> field_mask(const E2eSpec& spec) noexcept;

/// Writes counter (and the explicit header fields) and then the CRC into `data`
/// (spec.length_bytes bytes).
void protect(const E2eSpec& spec, std::uint8_t* data, std::uint32_t counter) noexcept;

struct CheckResult {
  bool crc_ok = false;        ///< CRC, Data ID (explicit ones too) and P04 length all match
  std::uint32_t counter = 0;  ///< the received counter
};

/// Checks a received frame of spec.length_bytes bytes.
CheckResult check(const E2eSpec& spec, const std::uint8_t* data) noexcept;

}  // namespace rig::io::can::e2e
