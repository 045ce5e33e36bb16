#include "model/vehicle/tmeasy.h"

#include <algorithm>
#include <cmath>

namespace rig::model::vehicle {
namespace {

// sqrt(a^2 + b^2) without glibc hypot's overflow care (our magnitudes are far from it): the
// hot path evaluates this ~30 times per step.
inline double norm2(double a, double b) { return std::sqrt(a * a + b * b); }

// TMeasy's degressive load dependence: value(F_z) from the values at F_zN and 2 F_zN.
double degressive(double at_nominal, double at_double, double load_ratio) {
  return load_ratio *
         (2.0 * at_nominal - 0.5 * at_double - (at_nominal - 0.5 * at_double) * load_ratio);
}

double linear(double at_nominal, double at_double, double load_ratio) {
  return at_nominal + (at_double - at_nominal) * (load_ratio - 1.0);
}

TmeasyCurve at_load(const TmeasyCurve& n, const TmeasyCurve& d, double ratio, double mu) {
  TmeasyCurve c;
  c.initial_slope_n = std::max(0.0, degressive(n.initial_slope_n, d.initial_slope_n, ratio));
  c.max_force_n = mu * std::max(0.0, degressive(n.max_force_n, d.max_force_n, ratio));
  c.sliding_force_n = mu * std::max(0.0, degressive(n.sliding_force_n, d.sliding_force_n, ratio));
  c.slip_at_max = std::max(1e-3, linear(n.slip_at_max, d.slip_at_max, ratio));
  c.slip_at_sliding =
      std::max(c.slip_at_max + 1e-3, linear(n.slip_at_sliding, d.slip_at_sliding, ratio));
  return c;
}

}  // namespace

TmeasyLoadCurves tmeasy_curves(const TireParams& tire, double load_n, double mu) noexcept {
  TmeasyLoadCurves c;
  const double ratio = std::max(0.0, load_n) / tire.nominal_load_n;
  c.x = at_load(tire.longitudinal_nominal, tire.longitudinal_double, ratio, mu);
  c.y = at_load(tire.lateral_nominal, tire.lateral_double, ratio, mu);
  // Normalizing factors (TMeasy): equal weight of slip-at-maximum and initial-slope ratios.
  const double sm = c.x.slip_at_max + c.y.slip_at_max;
  const double rx = c.x.initial_slope_n > 0 ? c.x.max_force_n / c.x.initial_slope_n : 0.0;
  const double ry = c.y.initial_slope_n > 0 ? c.y.max_force_n / c.y.initial_slope_n : 0.0;
  const double rs = rx + ry;
  c.normalize_x = c.x.slip_at_max / sm + (rs > 0 ? rx / rs : 0.5);
  c.normalize_y = c.y.slip_at_max / sm + (rs > 0 ? ry / rs : 0.5);
  return c;
}

double tmeasy_f_per_slip(const TmeasyLoadCurves& c, double slip_x, double slip_y) noexcept {
  const double s = norm2(slip_x, slip_y);
  double cx = 1.0;
  double cy = 0.0;
  if (s > 1e-12) {
    cx = slip_x / s;
    cy = slip_y / s;
  }
  const double ax = c.normalize_x * cx;
  const double ay = c.normalize_y * cy;
  const double df0 = norm2(c.x.initial_slope_n * ax, c.y.initial_slope_n * ay);
  const double fm = norm2(c.x.max_force_n * cx, c.y.max_force_n * cy);
  const double fs = norm2(c.x.sliding_force_n * cx, c.y.sliding_force_n * cy);
  const double sm =
      norm2(c.x.slip_at_max / c.normalize_x * cx, c.y.slip_at_max / c.normalize_y * cy);
  const double ss =
      norm2(c.x.slip_at_sliding / c.normalize_x * cx, c.y.slip_at_sliding / c.normalize_y * cy);
  if (fm <= 0.0 || df0 <= 0.0) return 0.0;
  if (s <= sm) {
    const double sigma = s / sm;
    return df0 / (1.0 + sigma * (sigma + df0 * sm / fm - 2.0));
  }
  if (s < ss) {
    const double sigma = (s - sm) / (ss - sm);
    return (fm - (fm - fs) * sigma * sigma * (3.0 - 2.0 * sigma)) / s;
  }
  return fs / s;
}

TmeasySlip tmeasy_slip(const TmeasyLoadCurves& c, double vx_mps, double vy_mps, double spin_radps,
                       double radius_dynamic_m, double velocity_floor_mps) noexcept {
  const double rw = radius_dynamic_m * std::abs(spin_radps);
  TmeasySlip out;
  // eqs. (14-15)
  out.slip_x =
      -(vx_mps - radius_dynamic_m * spin_radps) / (rw * c.normalize_x + velocity_floor_mps);
  out.slip_y = -vy_mps / (rw * c.normalize_y + velocity_floor_mps);
  out.f_per_slip = tmeasy_f_per_slip(c, out.slip_x, out.slip_y);
  return out;
}

}  // namespace rig::model::vehicle
