#pragma once
/// @file
/// A table-driven CRC of width 8, 16 or 32 bits in the Rocksoft/Williams parameter model
/// (width, poly, init, refin, refout, xorout: the parameters of the published catalogues, which
/// give each CRC's check value over ASCII "123456789"). The table is built when the Crc is made
/// (load time, or at compile time for the presets); compute() and the begin/update/finish steps
/// are pure, allocation-free and noexcept (RT-safe).

#include <array>
#include <cstddef>
#include <cstdint>

namespace rig::io::can::e2e {

struct CrcParams {
  std::uint8_t width = 8;  ///< 8, 16 or 32
  std::uint32_t poly = 0;  ///< normal (MSB-first) form, without the x^width term
  std::uint32_t init = 0;  ///< register before the first byte (unreflected)
  bool refin = false;      ///< bytes enter LSB first
  bool refout = false;     ///< the register is reflected before xorout
  std::uint32_t xorout = 0;
};

/// The CRCs with names (check values over "123456789" in the comments).
namespace presets {
inline constexpr CrcParams kCrc8SaeJ1850{8, 0x1D, 0xFF, false, false, 0xFF};       // 0x4B
inline constexpr CrcParams kCrc8H2F{8, 0x2F, 0xFF, false, false, 0xFF};            // 0xDF (AUTOSAR)
inline constexpr CrcParams kCrc16CcittFalse{16, 0x1021, 0xFFFF, false, false, 0};  // 0x29B1
inline constexpr CrcParams kCrc32{32, 0x04C11DB7, 0xFFFFFFFF, true, true, 0xFFFFFFFF};  // CBF43926
inline constexpr CrcParams kCrc32P4{32,   0xF4ACFB13, 0xFFFFFFFF,
                                    true, true,       0xFFFFFFFF};  // 0x1697D06A
}  // namespace presets

constexpr std::uint32_t width_mask(unsigned width) noexcept {
  return width >= 32 ? 0xFFFFFFFFu : (1u << width) - 1u;
}

constexpr std::uint32_t reflect(std::uint32_t value, unsigned width) noexcept {
  std::uint32_t r = 0;
  for (unsigned i = 0; i < width; ++i) r |= ((value >> i) & 1u) << (width - 1 - i);
  return r;
}

class Crc {
 public:
  constexpr Crc() : Crc(presets::kCrc8SaeJ1850) {}
  /// `p.width` must be 8, 16 or 32 (the mapping checks it; other widths are treated as 32).
  constexpr explicit Crc(const CrcParams& p) : params_(p) {
    if (params_.width != 8 && params_.width != 16) params_.width = 32;
    const unsigned w = params_.width;
    const std::uint32_t mask = width_mask(w);
    const std::uint32_t top = 1u << (w - 1);
    const std::uint32_t rpoly = reflect(p.poly & mask, w);
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t reg = p.refin ? i : i << (w - 8);
      for (int bit = 0; bit < 8; ++bit) {
        if (p.refin) {
          reg = (reg & 1u) != 0 ? (reg >> 1) ^ rpoly : reg >> 1;
        } else {
          reg = (reg & top) != 0 ? ((reg << 1) ^ p.poly) & mask : (reg << 1) & mask;
        }
      }
      table_[i] = reg;
    }
  }

  /// The register before the first byte.
  [[nodiscard]] constexpr std::uint32_t begin() const noexcept {
    const std::uint32_t init = params_.init & width_mask(params_.width);
    return params_.refin ? reflect(init, params_.width) : init;
  }
  /// Feeds `len` bytes into the register `reg` (chain several calls for gathered data).
  [[nodiscard]] constexpr std::uint32_t update(std::uint32_t reg, const std::uint8_t* data,
                                               std::size_t len) const noexcept {
    const unsigned w = params_.width;
    const std::uint32_t mask = width_mask(w);
    for (std::size_t i = 0; i < len; ++i) {
      if (params_.refin) {
        reg = (w > 8 ? reg >> 8 : 0u) ^ table_[(reg ^ data[i]) & 0xFFu];
      } else {
        reg = ((w > 8 ? reg << 8 : 0u) ^ table_[((reg >> (w - 8)) ^ data[i]) & 0xFFu]) & mask;
      }
    }
    return reg;
  }
  /// The CRC of the register after the last byte.
  [[nodiscard]] constexpr std::uint32_t finish(std::uint32_t reg) const noexcept {
    const unsigned w = params_.width;
    if (params_.refin != params_.refout) reg = reflect(reg, w);
    return (reg ^ params_.xorout) & width_mask(w);
  }
  [[nodiscard]] constexpr std::uint32_t compute(const std::uint8_t* data,
                                                std::size_t len) const noexcept {
    return finish(update(begin(), data, len));
  }
  [[nodiscard]] constexpr const CrcParams& params() const noexcept { return params_; }

 private:
  CrcParams params_;
  std::array<std::uint32_t, 256> table_{};
};

}  // namespace rig::io::can::e2e
