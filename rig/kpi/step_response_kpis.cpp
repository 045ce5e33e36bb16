#include "rig/kpi/step_response_kpis.h"

#include <cmath>
#include <cstddef>
#include <limits>

namespace rig::kpi {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The time at which the normalised series (v - v0) / dv first reaches `level` at or after
/// sample `from` (linear between samples), NaN if it never does; `at` gets the sample index.
double first_crossing(std::span<const double> t_s, std::span<const double> v, double v0, double dv,
                      double level, std::size_t from, std::size_t* at = nullptr) {
  for (std::size_t i = from; i < v.size(); ++i) {
    const double b = (v[i] - v0) / dv;
    if (b < level) continue;
    if (at != nullptr) *at = i;
    if (i == from) return t_s[i];
    const double a = (v[i - 1] - v0) / dv;
    return t_s[i - 1] + (level - a) / (b - a) * (t_s[i] - t_s[i - 1]);
  }
  return kNaN;
}

/// Mean of v over the samples with t >= t_from.
double mean_from(std::span<const double> t_s, std::span<const double> v, double t_from) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (t_s[i] < t_from) continue;
    sum += v[i];
    ++n;
  }
  return n > 0 ? sum / n : kNaN;
}

}  // namespace

StepResponse step_response(std::span<const double> t_s, std::span<const double> y,
                           std::span<const double> x, double steady_s, double fraction) {
  StepResponse r{kNaN, kNaN, kNaN, kNaN};
  if (t_s.size() < 3 || y.size() != t_s.size() || x.size() != t_s.size()) return r;
  const double t_steady = t_s.back() - steady_s;
  const double x0 = x.front(), y0 = y.front();
  const double dx = mean_from(t_s, x, t_steady) - x0;
  const double dy = mean_from(t_s, y, t_steady) - y0;
  if (!(std::abs(dx) > 0.0) || !(std::abs(dy) > 0.0)) return r;
  r.steady_gain = dy / dx;
  std::size_t i_ref = 0;
  const double t_ref = first_crossing(t_s, x, x0, dx, 0.5, 0, &i_ref);
  if (std::isnan(t_ref)) return r;
  r.response_time_s = first_crossing(t_s, y, y0, dy, fraction, i_ref) - t_ref;
  std::size_t i_peak = i_ref;
  for (std::size_t i = i_ref; i < y.size(); ++i) {
    if ((y[i] - y0) / dy > (y[i_peak] - y0) / dy) i_peak = i;
  }
  r.peak_response_time_s = t_s[i_peak] - t_ref;
  r.overshoot = (y[i_peak] - y0) / dy - 1.0;
  return r;
}

}  // namespace rig::kpi
