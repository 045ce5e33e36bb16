#pragma once
/// @file
/// The key of a per-step cache: the exact bits of what a result was computed from. Within one
/// step the stepper asks a block for its partials and then for q at the same (y, z), and the
/// framework asks for the mounts' load and then their partials at the same chassis state; a
/// cache hit hands back what the same inputs gave, bit for bit, so results do not change.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace rig::model::vehicle {

template <std::size_t N>
class InputKey {
 public:
  using Values = std::array<double, N>;

  /// True if `now` equals the stored inputs bit for bit; otherwise stores them (the caller
  /// then recomputes) and returns false.
  [[nodiscard]] bool hit(const Values& now) noexcept {
    bool same = valid_;
    for (std::size_t i = 0; same && i < N; ++i)
      same = std::bit_cast<std::uint64_t>(values_[i]) == std::bit_cast<std::uint64_t>(now[i]);
    if (same) return true;
    values_ = now;
    valid_ = true;
    return false;
  }

 private:
  Values values_{};
  bool valid_ = false;
};

/// Copies n doubles from `p` into `out` from position `at`; returns the position after them.
template <std::size_t N>
std::size_t put(std::array<double, N>& out, std::size_t at, const double* p,
                std::size_t n) noexcept {
  std::memcpy(out.data() + at, p, sizeof(double) * n);
  return at + n;
}

}  // namespace rig::model::vehicle
