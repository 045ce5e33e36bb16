#include "model/tire/tmeasy_tire.h"

#include <algorithm>
#include <cmath>

#include "model/tire/tmeasy_characteristic.h"

namespace rig::model::tire {
namespace {

/// The degressive load law turns negative far beyond 2 F_zN (and the slips could at F_z -> 0):
/// keep the curve physical there (no force of the wrong sign, s_S > s_M > 0).
TmeasyCurve guarded(TmeasyCurve c) noexcept {
  c.initial_slope_n = std::max(0.0, c.initial_slope_n);
  c.max_force_n = std::max(0.0, c.max_force_n);
  c.slide_force_n = std::max(0.0, c.slide_force_n);
  c.max_slip = std::max(1e-3, c.max_slip);
  c.slide_slip = std::max(c.max_slip + 1e-3, c.slide_slip);
  return c;
}

}  // namespace

TireCharacteristic characteristic_at(const TmeasyParams& p, double load_n,
                                     double friction) noexcept {
  TireCharacteristic c;
  if (!(load_n > 0.0)) return c;  // lift-off: zero curves, f = 0
  const double q = load_n / p.nominal_load_n;
  const double mu_ratio = friction / p.reference_friction;
  c.x = guarded(curve_at_load(p.longitudinal, q, mu_ratio));
  c.y = guarded(curve_at_load(p.lateral, q, mu_ratio));
  if (c.x.initial_slope_n > 0.0 && c.y.initial_slope_n > 0.0) {
    const SlipNormalization n = slip_normalization(c.x, c.y);  // Rill 2011, eq. 3.83
    c.normalize_x = n.x;
    c.normalize_y = n.y;
  }
  return c;
}

double f_per_slip_of(const TireCharacteristic& c, double slip_x, double slip_y) noexcept {
  // sqrt without glibc hypot's overflow care (our magnitudes are far from it)
  const double s = std::sqrt(slip_x * slip_x + slip_y * slip_y);
  double cos_phi = 1.0, sin_phi = 0.0;  // s = 0: phi = 0, f(0) = dFx0 s^x
  if (s > 1e-12) {
    cos_phi = slip_x / s;
    sin_phi = slip_y / s;
  }
  const TmeasyCurve k = generalized_curve(c.x, c.y, SlipNormalization{c.normalize_x, c.normalize_y},
                                          cos_phi, sin_phi);
  if (k.max_force_n <= 0.0 || k.initial_slope_n <= 0.0) return 0.0;
  return evaluate_characteristic(k, s).f_n;
}

TireSlip slip_of(const TireCharacteristic& c, const TireKinematics& k,
                 double velocity_floor_mps) noexcept {
  const double r = k.rolling_radius_m;
  const double rw = r * std::abs(k.spin_radps);
  TireSlip out;
  // eqs. (14-15)
  out.slip_x = -(k.long_speed_mps - r * k.spin_radps) / (rw * c.normalize_x + velocity_floor_mps);
  out.slip_y = -k.lat_speed_mps / (rw * c.normalize_y + velocity_floor_mps);
  out.f_per_slip = f_per_slip_of(c, out.slip_x, out.slip_y);
  return out;
}

SteadyStateForces steady_state_forces(const TmeasyParams& params, const TireKinematics& k,
                                      double load_n, double friction) noexcept {
  SteadyStateForces r;
  if (!(load_n > 0.0) || !(friction > 0.0)) return r;
  r.slip = slip_of(characteristic_at(params, load_n, friction), k, params.velocity_floor_mps);
  r.long_force_n = r.slip.f_per_slip * r.slip.slip_x;  // eq. (16)
  r.lat_force_n = r.slip.f_per_slip * r.slip.slip_y;   // eq. (17)
  return r;
}

}  // namespace rig::model::tire
