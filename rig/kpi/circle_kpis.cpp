#include "rig/kpi/circle_kpis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rig::kpi {
namespace {

/// Sums of one plateau's steady part.
struct Plateau {
  double angle = 0.0, v = 0.0, r = 0.0, v_min = 1e300, v_max = -1e300;
  int n = 0;
  void add(double a, double speed, double rate) {
    angle += a, v += speed, r += rate, ++n;
    v_min = std::min(v_min, speed), v_max = std::max(v_max, speed);
  }
};

/// Least-squares sums of y over x.
struct Fit {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, n = 0.0;
  void add(double x, double y) { sx += x, sy += y, sxx += x * x, sxy += x * y, n += 1.0; }
  [[nodiscard]] double slope() const {
    const double det = n * sxx - sx * sx;
    return n >= 2.0 && det > 0.0 ? (n * sxy - sx * sy) / det
                                 : std::numeric_limits<double>::quiet_NaN();
  }
};

/// One steady point into the fit, if it is steady and within the a_y range.
void add_point(const Plateau& pl, const CircleParams& p, Fit& fit) {
  if (pl.n == 0 || pl.v_max - pl.v_min >= p.speed_band_mps) return;
  const double v = pl.v / pl.n, r = pl.r / pl.n, angle = pl.angle / pl.n;
  if (v == 0.0 || r == 0.0) return;
  const double turn = r > 0.0 ? 1.0 : -1.0;  // a right turn counts as a left one
  const double ay = turn * v * r;
  if (!(ay >= p.ay_min_mps2 && ay <= p.ay_max_mps2)) return;
  fit.add(ay, turn * (angle / p.steering_ratio - p.wheelbase_m * r / v));
}

}  // namespace

double understeer_gradient(std::span<const double> t_s, std::span<const double> wheel_angle_rad,
                           std::span<const double> speed_mps,
                           std::span<const double> yaw_rate_radps, const CircleParams& p) {
  Fit fit;
  Plateau pl;
  long current = -1;
  for (std::size_t i = 0; i < t_s.size(); ++i) {
    const double since = t_s[i] - p.from_s;
    const auto k = static_cast<long>(std::floor(since / p.plateau_s));
    if (k != current) {  // a new plateau: the last one is complete
      add_point(pl, p, fit);
      pl = Plateau{};
      current = k;
    }
    if (since - static_cast<double>(k) * p.plateau_s >= p.plateau_s - p.steady_s)
      pl.add(wheel_angle_rad[i], speed_mps[i], yaw_rate_radps[i]);
  }
  // the last plateau counts only if the run reached its end
  if (!t_s.empty() &&
      t_s.back() - p.from_s >= static_cast<double>(current + 1) * p.plateau_s - 2e-3)
    add_point(pl, p, fit);
  return fit.slope();
}

}  // namespace rig::kpi
