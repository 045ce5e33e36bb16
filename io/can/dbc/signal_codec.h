#pragma once
/// @file
/// Precompiled bit plans for DBC signals and messages: decode/encode without allocation, without
/// strings and without branches on byte order in the per-frame path.
///
/// A signal's bits are split at load time into at most 9 byte segments (byte index, shift in
/// the byte, mask, shift in the raw value). Intel and Motorola differ only in how these segments
/// are computed; extraction is the same loop for both.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "io/can/dbc/dbc_database.h"

namespace rig::io::can::dbc {

/// Decode/encode plan of one signal. Cheap to copy, no heap.
class SignalCodec {
 public:
  /// Compiles `signal` (already validated by the parser: length 1..64, fits in 64 bytes).
  explicit SignalCodec(const SignalDef& signal);
  SignalCodec() = default;

  /// Raw bits of the signal, right-aligned, not sign-extended. `data` must hold
  /// required_bytes() bytes.
  [[nodiscard]] std::uint64_t extract_raw(const std::uint8_t* data) const noexcept;
  /// Writes the low length_bits() bits of `raw` into the signal's place; other bits untouched.
  void insert_raw(std::uint64_t raw, std::uint8_t* data) const noexcept;

  /// Physical value from raw bits: sign extension or float/double reinterpretation, then
  /// raw * factor + offset.
  [[nodiscard]] double raw_to_physical(std::uint64_t raw) const noexcept;
  /// Raw bits from a physical value: (physical - offset) / factor rounded to nearest, saturated
  /// to the raw integer range (NaN -> 0); float types reinterpret after the conversion.
  [[nodiscard]] std::uint64_t physical_to_raw(double physical) const noexcept;

  /// extract_raw + raw_to_physical.
  [[nodiscard]] double decode(const std::uint8_t* data) const noexcept {
    return raw_to_physical(extract_raw(data));
  }
  /// physical_to_raw + insert_raw.
  void encode(double physical, std::uint8_t* data) const noexcept {
    insert_raw(physical_to_raw(physical), data);
  }

  /// Bytes a frame must have for this signal (highest byte touched + 1).
  [[nodiscard]] std::uint32_t required_bytes() const noexcept { return required_bytes_; }
  [[nodiscard]] std::uint32_t length_bits() const noexcept { return length_bits_; }
  [[nodiscard]] bool is_signed() const noexcept { return is_signed_; }
  [[nodiscard]] ValueType value_type() const noexcept { return value_type_; }
  [[nodiscard]] double factor() const noexcept { return factor_; }
  [[nodiscard]] double offset() const noexcept { return offset_; }

 private:
  struct Segment {
    std::uint8_t byte_index = 0;   ///< byte of the frame
    std::uint8_t bit_shift = 0;    ///< position of the segment's LSB in that byte
    std::uint8_t mask = 0;         ///< right-aligned mask of the segment's width
    std::uint8_t value_shift = 0;  ///< position of the segment's LSB in the raw value
  };
  std::array<Segment, 9> segments_{};
  std::uint8_t segment_count_ = 0;
  std::uint32_t length_bits_ = 0;
  std::uint32_t required_bytes_ = 0;
  bool is_signed_ = false;
  ValueType value_type_ = ValueType::kInteger;
  double factor_ = 1.0;
  double offset_ = 0.0;
  double raw_limit_ = 2.0;  ///< 2^length (unsigned) or 2^(length-1) (signed): exclusive bound
};

/// Plans for every signal of one message, in the order of MessageDef::signals. Built at load
/// time (allocates once); decode/encode never allocate.
class MessageCodec {
 public:
  explicit MessageCodec(const MessageDef& message);

  [[nodiscard]] std::size_t signal_count() const noexcept { return signals_.size(); }
  [[nodiscard]] const SignalCodec& signal(std::size_t i) const { return signals_[i]; }
  /// Index of the multiplexor signal, or -1 if the message is not multiplexed.
  [[nodiscard]] int multiplexor_index() const noexcept { return multiplexor_; }
  /// True if signal i is carried by a frame whose multiplexor raw value is `mux_raw` (always
  /// true for plain signals and the multiplexor itself).
  [[nodiscard]] bool present(std::size_t i, std::uint64_t mux_raw) const noexcept;
  [[nodiscard]] std::uint32_t length_bytes() const noexcept { return length_bytes_; }

  /// Decodes every signal present in `data` (len must be >= length_bytes(), else returns false
  /// and writes nothing). `physical` and `present` must have signal_count() entries; absent
  /// multiplexed signals get present = false and their physical entry is left untouched.
  bool decode(const std::uint8_t* data, std::size_t len, std::span<double> physical,
              std::span<bool> present) const noexcept;
  /// Encodes all signals from `physical` (signal_count() entries) into `data` (length_bytes()
  /// bytes, zeroed first). For a multiplexed message the multiplexor is encoded first and only
  /// the page it selects is written.
  void encode(std::span<const double> physical, std::uint8_t* data) const noexcept;

 private:
  std::vector<SignalCodec> signals_;
  std::vector<MuxRole> roles_;
  std::vector<std::uint32_t> mux_values_;
  int multiplexor_ = -1;
  std::uint32_t length_bytes_ = 0;
};

}  // namespace rig::io::can::dbc
