#include "io/can/mapping/protection.h"

namespace rig::io::can::mapping {

std::uint32_t compute_checksum(const ChecksumSpec& c, const std::uint8_t* data) noexcept {
  // Gather the covered bytes in their configured order (at most 64, on the stack).
  std::uint8_t covered[64];
  std::size_t n = 0;
  for (std::uint8_t b : c.bytes) {
    if (n < sizeof covered) covered[n++] = data[b];
  }
  return c.type == ChecksumType::kXor ? xor8(covered, n) : c.crc.compute(covered, n);
}

void write_checksum(const ChecksumSpec& c, const dbc::MessageCodec& codec,
                    std::uint8_t* data) noexcept {
  const std::uint32_t sum = compute_checksum(c, data);
  if (!c.position_byte) {
    codec.signal(c.dbc_signal).insert_raw(sum, data);
    return;
  }
  const unsigned bytes = c.crc.params().width / 8u;
  for (unsigned i = 0; i < bytes; ++i)
    data[*c.position_byte + i] = static_cast<std::uint8_t>(sum >> (8 * (bytes - 1 - i)));
}

bool checksum_ok(const ChecksumSpec& c, const dbc::MessageCodec& codec,
                 const std::uint8_t* data) noexcept {
  std::uint64_t received = 0;
  if (!c.position_byte) {
    received = codec.signal(c.dbc_signal).extract_raw(data);
  } else {
    const unsigned bytes = c.crc.params().width / 8u;
    for (unsigned i = 0; i < bytes; ++i) received = (received << 8) | data[*c.position_byte + i];
  }
  return received == compute_checksum(c, data);
}

}  // namespace rig::io::can::mapping
