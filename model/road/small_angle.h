#pragma once
/// @file
/// cos and sin of an angle by their series up to x^9 where it is small (error below 3e-17 for
/// |x| <= 0.1; the library functions beyond): the reference line's short turns cost no call.

#include <cmath>

namespace rig::model::road {

struct CosSin {
  double cos = 1;
  double sin = 0;
};

inline CosSin cos_sin(double x) noexcept {
  if (std::abs(x) > 0.1) return {std::cos(x), std::sin(x)};
  const double x2 = x * x;
  return {1.0 - x2 / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 * (1.0 - x2 / 56.0))),
          x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0))))};
}

}  // namespace rig::model::road
