#pragma once
/// @file
/// A mapped message's checksum on the wire: computed over its covered bytes, written on send,
/// compared on receive; the one place RxProcessor and TxScheduler share for it (E2E profiles:
/// io/can/e2e/e2e_profile.h). RT-safe: no allocation, no throw.

#include <cstdint>

#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/can_mapping.h"

namespace rig::io::can::mapping {

/// The checksum of `data` (the whole frame) over c.bytes, in their order.
std::uint32_t compute_checksum(const ChecksumSpec& c, const std::uint8_t* data) noexcept;

/// Writes the checksum into its signal (or at its position).
void write_checksum(const ChecksumSpec& c, const dbc::MessageCodec& codec,
                    std::uint8_t* data) noexcept;

/// True if the received checksum equals the computed one.
bool checksum_ok(const ChecksumSpec& c, const dbc::MessageCodec& codec,
                 const std::uint8_t* data) noexcept;

}  // namespace rig::io::can::mapping
