#pragma once
/// @file
/// The sine and cosine of the last angle asked for, kept until another comes. The angle is
/// compared bit for bit, so a hit gives the bits a new evaluation would. A rigid axle's roll and
/// the frame's twist are asked for by each of their wheels in every evaluation (mass matrix,
/// forces, partials, contacts: on the 40 t tractor 70 times a step for a few distinct values).

#include <bit>
#include <cmath>
#include <cstdint>

namespace rig::model::vehicle {

struct SinCos {
  double sin = 0.0;
  double cos = 1.0;
};

[[nodiscard]] inline SinCos sin_cos(double angle_rad) noexcept {
  return {std::sin(angle_rad), std::cos(angle_rad)};
}

class SinCosMemo {
 public:
  [[nodiscard]] SinCos operator()(double angle_rad) noexcept {
    const auto key = std::bit_cast<std::uint64_t>(angle_rad);
    if (key != key_) {
      key_ = key;
      value_ = sin_cos(angle_rad);
    }
    return value_;
  }

 private:
  std::uint64_t key_ = 0;  ///< the bits of +0.0, whose value value_ holds at the start
  SinCos value_{};
};

}  // namespace rig::model::vehicle
