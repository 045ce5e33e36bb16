#include "model/vehicle/tmeasy.h"

#include <algorithm>
#include <cmath>

namespace rig::model::vehicle {
namespace {

/// The degressive load law turns negative far beyond 2 F_zN (and the slips could at F_z -> 0):
/// keep the curve physical there (no force of the wrong sign, s_S > s_M > 0).
tire::TmeasyCurve guarded(tire::TmeasyCurve c) noexcept {
  c.initial_slope_n = std::max(0.0, c.initial_slope_n);
  c.max_force_n = std::max(0.0, c.max_force_n);
  c.slide_force_n = std::max(0.0, c.slide_force_n);
  c.max_slip = std::max(1e-3, c.max_slip);
  c.slide_slip = std::max(c.max_slip + 1e-3, c.slide_slip);
  return c;
}

}  // namespace

TmeasyLoadCurves tmeasy_curves(const TireParams& t, double load_n, double mu) noexcept {
  TmeasyLoadCurves c;
  if (!(load_n > 0.0)) return c;  // lift-off: zero curves, f = 0
  const double q = load_n / t.nominal_load_n;
  c.x = guarded(tire::curve_at_load(t.longitudinal, q, mu));
  c.y = guarded(tire::curve_at_load(t.lateral, q, mu));
  if (c.x.initial_slope_n > 0.0 && c.y.initial_slope_n > 0.0) {
    const tire::SlipNormalization n = tire::slip_normalization(c.x, c.y);  // Rill 2011, eq. 3.83
    c.normalize_x = n.x;
    c.normalize_y = n.y;
  }
  return c;
}

double tmeasy_f_per_slip(const TmeasyLoadCurves& c, double slip_x, double slip_y) noexcept {
  // sqrt without glibc hypot's overflow care (our magnitudes are far from it)
  const double s = std::sqrt(slip_x * slip_x + slip_y * slip_y);
  double cos_phi = 1.0, sin_phi = 0.0;  // s = 0: phi = 0, f(0) = dFx0 s^x
  if (s > 1e-12) {
    cos_phi = slip_x / s;
    sin_phi = slip_y / s;
  }
  const tire::TmeasyCurve k = tire::generalized_curve(
      c.x, c.y, tire::SlipNormalization{c.normalize_x, c.normalize_y}, cos_phi, sin_phi);
  if (k.max_force_n <= 0.0 || k.initial_slope_n <= 0.0) return 0.0;
  return tire::evaluate_characteristic(k, s).f_n;
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
