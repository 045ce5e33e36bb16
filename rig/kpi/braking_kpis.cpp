#include "rig/kpi/braking_kpis.h"

#include <cmath>
#include <limits>

namespace rig::kpi {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The distance from sample `from` at which |v| first falls to `level` (trapezoidal |v|,
/// the crossing interpolated linearly), NaN if it never does.
double distance_to(std::span<const double> t_s, std::span<const double> v, std::size_t from,
                   double level) {
  double s = 0.0;
  for (std::size_t i = from + 1; i < v.size() && i < t_s.size(); ++i) {
    const double a = std::abs(v[i - 1]), b = std::abs(v[i]), dt = t_s[i] - t_s[i - 1];
    if (b > level) {
      s += 0.5 * (a + b) * dt;
      continue;
    }
    const double f = a > b ? (a - level) / (a - b) : 0.0;  // of the interval, to the crossing
    return s + 0.5 * (a + level) * f * dt;
  }
  return kNaN;
}

}  // namespace

std::optional<std::size_t> brake_point(std::span<const double> trigger, double threshold,
                                       std::size_t samples) {
  if (samples == 0) return std::nullopt;
  if (trigger.empty()) return 0;
  for (std::size_t i = 0; i < trigger.size(); ++i) {
    if (trigger[i] >= threshold) return i;
  }
  return std::nullopt;
}

double braking_distance(std::span<const double> t_s, std::span<const double> v, std::size_t from,
                        double stop_mps) {
  if (from >= v.size() || std::abs(v[from]) <= stop_mps) return kNaN;
  return distance_to(t_s, v, from, stop_mps);
}

double mean_deceleration(std::span<const double> t_s, std::span<const double> v, std::size_t from) {
  if (from >= v.size()) return kNaN;
  const double v0 = std::abs(v[from]);
  const double vb = 0.8 * v0, ve = 0.1 * v0;
  const double sb = distance_to(t_s, v, from, vb), se = distance_to(t_s, v, from, ve);
  if (!(v0 > 0.0) || !(se > sb)) return kNaN;
  return (vb * vb - ve * ve) / (2.0 * (se - sb));
}

}  // namespace rig::kpi
