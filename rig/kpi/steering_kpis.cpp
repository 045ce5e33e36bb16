#include "rig/kpi/steering_kpis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rig::kpi {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::size_t nearest(std::span<const double> t_s, double t) {
  const auto it = std::lower_bound(t_s.begin(), t_s.end(), t);
  if (it == t_s.end()) return t_s.size() - 1;
  const auto i = static_cast<std::size_t>(it - t_s.begin());
  return i > 0 && t - t_s[i - 1] < *it - t ? i - 1 : i;
}

}  // namespace

double peak_abs(std::span<const double> y) {
  if (y.empty()) return kNaN;
  double m = 0.0;
  for (const double v : y) m = std::max(m, std::abs(v));
  return m;
}

double loop_width(std::span<const double> x, std::span<const double> y, double x0) {
  double rising = 0.0, falling = 0.0;
  int n_rising = 0, n_falling = 0;
  for (std::size_t i = 1; i < x.size() && i < y.size(); ++i) {
    const double a = x[i - 1] - x0, b = x[i] - x0;
    if ((a < 0.0) == (b < 0.0) || a == b) continue;  // no crossing between the samples
    const double w = a / (a - b);
    const double yc = y[i - 1] + w * (y[i] - y[i - 1]);
    if (b > a) {
      rising += yc;
      ++n_rising;
    } else {
      falling += yc;
      ++n_falling;
    }
  }
  if (n_rising == 0 || n_falling == 0) return kNaN;
  return std::abs(rising / n_rising - falling / n_falling);
}

double gradient(std::span<const double> x, std::span<const double> y, double x0, double band) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  double n = 0.0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    const double dx = x[i] - x0;  // centred: better conditioned sums
    if (std::abs(dx) > band) continue;
    sx += dx;
    sy += y[i];
    sxx += dx * dx;
    sxy += dx * y[i];
    n += 1.0;
  }
  const double det = n * sxx - sx * sx;
  if (n < 2.0 || !(det > 0.0)) return kNaN;
  return (n * sxy - sx * sy) / det;
}

double residual_fraction(std::span<const double> t_s, std::span<const double> y, double t0_s,
                         double t1_s) {
  if (t_s.empty() || y.size() != t_s.size()) return kNaN;
  const double y0 = y[nearest(t_s, t0_s)];
  if (y0 == 0.0) return kNaN;
  return std::abs(y[nearest(t_s, t1_s)]) / std::abs(y0);
}

}  // namespace rig::kpi
