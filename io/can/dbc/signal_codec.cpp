#include "io/can/dbc/signal_codec.h"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <limits>

namespace rig::io::can::dbc {

SignalCodec::SignalCodec(const SignalDef& signal)
    : length_bits_(std::clamp<std::uint32_t>(signal.length_bits, 1, 64)),
      is_signed_(signal.is_signed),
      value_type_(signal.value_type),
      factor_(signal.factor),
      offset_(signal.offset),
      raw_limit_(std::ldexp(1.0, static_cast<int>(length_bits_) - (is_signed_ ? 1 : 0))) {
  // Split the signal into byte segments, LSB of the raw value first for Intel and MSB first for
  // Motorola; either way each segment records where its bits go in the raw value.
  std::uint32_t remaining = length_bits_;
  if (signal.byte_order == ByteOrder::kIntel) {
    std::uint32_t bit = signal.start_bit;  // LSB of the signal
    std::uint32_t done = 0;
    while (remaining > 0 && segment_count_ < segments_.size()) {
      const std::uint32_t byte = bit / 8;
      const std::uint32_t lsb = bit % 8;
      const std::uint32_t width = std::min(8 - lsb, remaining);
      segments_[segment_count_++] = {
          static_cast<std::uint8_t>(byte), static_cast<std::uint8_t>(lsb),
          static_cast<std::uint8_t>((1u << width) - 1u), static_cast<std::uint8_t>(done)};
      required_bytes_ = byte + 1;
      done += width;
      bit += width;
      remaining -= width;
    }
  } else {
    // Sawtooth numbering: start bit = MSB at (byte, bit k); lower bits continue down to bit 0 of
    // the same byte, then from bit 7 of the next byte.
    std::uint32_t byte = signal.start_bit / 8;
    std::uint32_t msb = signal.start_bit % 8;
    while (remaining > 0 && segment_count_ < segments_.size()) {
      const std::uint32_t width = std::min(msb + 1, remaining);
      const std::uint32_t lsb = msb + 1 - width;
      remaining -= width;
      segments_[segment_count_++] = {
          static_cast<std::uint8_t>(byte), static_cast<std::uint8_t>(lsb),
          static_cast<std::uint8_t>((1u << width) - 1u), static_cast<std::uint8_t>(remaining)};
      required_bytes_ = byte + 1;
      ++byte;
      msb = 7;
    }
  }
}

std::uint64_t SignalCodec::extract_raw(const std::uint8_t* data) const noexcept {
  std::uint64_t raw = 0;
  for (std::uint8_t i = 0; i < segment_count_; ++i) {
    const Segment& s = segments_[i];
    const auto bits = static_cast<std::uint64_t>((data[s.byte_index] >> s.bit_shift) & s.mask);
    raw |= bits << s.value_shift;
  }
  return raw;
}

void SignalCodec::insert_raw(std::uint64_t raw, std::uint8_t* data) const noexcept {
  for (std::uint8_t i = 0; i < segment_count_; ++i) {
    const Segment& s = segments_[i];
    const auto bits = static_cast<unsigned>((raw >> s.value_shift) & s.mask);
    const auto keep = static_cast<unsigned>(~(static_cast<unsigned>(s.mask) << s.bit_shift));
    data[s.byte_index] =
        static_cast<std::uint8_t>((data[s.byte_index] & keep) | (bits << s.bit_shift));
  }
}

double SignalCodec::raw_to_physical(std::uint64_t raw) const noexcept {
  double value = 0.0;
  switch (value_type_) {
    case ValueType::kFloat32:
      value = static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(raw)));
      break;
    case ValueType::kFloat64:
      value = std::bit_cast<double>(raw);
      break;
    case ValueType::kInteger:
      if (is_signed_) {
        if (length_bits_ < 64 && ((raw >> (length_bits_ - 1)) & 1u) != 0) {
          raw |= ~((std::uint64_t{1} << length_bits_) - 1);  // sign extension
        }
        value = static_cast<double>(static_cast<std::int64_t>(raw));
      } else {
        value = static_cast<double>(raw);
      }
      break;
  }
  return value * factor_ + offset_;
}

std::uint64_t SignalCodec::physical_to_raw(double physical) const noexcept {
  const double scaled = (physical - offset_) / factor_;
  const std::uint64_t mask =
      length_bits_ >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << length_bits_) - 1;
  switch (value_type_) {
    case ValueType::kFloat32: {
      double v = scaled;
      if (std::isfinite(v)) v = std::clamp(v, -static_cast<double>(FLT_MAX), double{FLT_MAX});
      return std::bit_cast<std::uint32_t>(static_cast<float>(v));
    }
    case ValueType::kFloat64:
      return std::bit_cast<std::uint64_t>(scaled);
    case ValueType::kInteger:
      break;
  }
  if (std::isnan(scaled)) return 0;
  if (is_signed_) {
    // Saturate to [-2^(n-1), 2^(n-1) - 1] before converting (no UB on huge values).
    const double lo = -raw_limit_;
    const double hi_exclusive = raw_limit_;
    std::int64_t v = 0;
    if (scaled <= lo) {
      v = length_bits_ >= 64 ? std::numeric_limits<std::int64_t>::min()
                             : -(std::int64_t{1} << (length_bits_ - 1));
    } else if (std::round(scaled) >= hi_exclusive) {
      v = length_bits_ >= 64 ? std::numeric_limits<std::int64_t>::max()
                             : (std::int64_t{1} << (length_bits_ - 1)) - 1;
    } else {
      v = static_cast<std::int64_t>(std::round(scaled));
    }
    return static_cast<std::uint64_t>(v) & mask;
  }
  const double hi_exclusive = raw_limit_;
  if (scaled <= 0.0) return 0;
  const double rounded = std::round(scaled);
  if (rounded >= hi_exclusive) return mask;
  return static_cast<std::uint64_t>(rounded) & mask;
}

MessageCodec::MessageCodec(const MessageDef& message) : length_bytes_(message.length_bytes) {
  signals_.reserve(message.signals.size());
  for (std::size_t i = 0; i < message.signals.size(); ++i) {
    const SignalDef& s = message.signals[i];
    signals_.emplace_back(s);
    roles_.push_back(s.mux_role);
    mux_values_.push_back(s.mux_value);
    if (s.mux_role == MuxRole::kMultiplexor && multiplexor_ < 0) multiplexor_ = static_cast<int>(i);
  }
}

bool MessageCodec::present(std::size_t i, std::uint64_t mux_raw) const noexcept {
  return roles_[i] != MuxRole::kMultiplexed || (multiplexor_ >= 0 && mux_values_[i] == mux_raw);
}

bool MessageCodec::decode(const std::uint8_t* data, std::size_t len, std::span<double> physical,
                          std::span<bool> present_out) const noexcept {
  if (len < length_bytes_ || physical.size() < signals_.size() ||
      present_out.size() < signals_.size()) {
    return false;
  }
  const std::uint64_t mux_raw =
      multiplexor_ >= 0 ? signals_[static_cast<std::size_t>(multiplexor_)].extract_raw(data) : 0;
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    const bool here = present(i, mux_raw);
    present_out[i] = here;
    if (here) physical[i] = signals_[i].decode(data);
  }
  return true;
}

void MessageCodec::encode(std::span<const double> physical, std::uint8_t* data) const noexcept {
  for (std::uint32_t b = 0; b < length_bytes_; ++b) data[b] = 0;
  if (physical.size() < signals_.size()) return;
  std::uint64_t mux_raw = 0;
  if (multiplexor_ >= 0) {
    const auto m = static_cast<std::size_t>(multiplexor_);
    mux_raw = signals_[m].physical_to_raw(physical[m]);
  }
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    if (present(i, mux_raw)) signals_[i].encode(physical[i], data);
  }
}

}  // namespace rig::io::can::dbc
