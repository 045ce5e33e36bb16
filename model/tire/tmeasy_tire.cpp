#include "model/tire/tmeasy_tire.h"

#include <algorithm>
#include <cmath>

#include "model/tire/dual.h"
#include "model/tire/tmeasy_characteristic.h"
#include "model/tire/tmeasy_characteristic_impl.h"

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

/// Pneumatic trail over contact length, (n/L)(s_y), Rill 2011 eq. 3.92 form: falls from
/// (n/L)_0 through zero at s_y0 to a negative dip and back to zero at s_yE.
double trail_over_length(double n0, double sy0, double syE, double sy) noexcept {
  const double a = std::abs(sy);
  if (a <= sy0) {
    const double w = sy0 / syE;
    const double x = a / sy0;
    return n0 * ((1.0 - w) * (1.0 - x) + w * (1.0 - (3.0 - 2.0 * x) * x * x));
  }
  if (a <= syE) {
    const double w = sy0 / syE;
    const double e = (syE - a) / (syE - sy0);
    return -n0 * (1.0 - w) * (a - sy0) / sy0 * e * e;
  }
  return 0.0;
}

using D3 = internal::Dual<3>;  // derivative slots: v_x, v_y, omega

/// f(s) of eq. (16) and the sliding ratio kappa in dual numbers (slip_curve_value's formula).
struct SlipCurveDual {
  D3 f, sliding_ratio;
};
SlipCurveDual slip_curve_dual(const TireCharacteristic& c, const D3& slip_x,
                              const D3& slip_y) noexcept {
  const D3 s = internal::sqrt(slip_x * slip_x + slip_y * slip_y);
  D3 cos_phi(1.0), sin_phi(0.0);
  if (s.v > 1e-12) {
    cos_phi = slip_x / s;
    sin_phi = slip_y / s;
  }
  const auto constant = [](const TmeasyCurve& k) {
    return internal::CurveT<D3>{k.initial_slope_n, k.max_force_n, k.max_slip, k.slide_force_n,
                                k.slide_slip};
  };
  const internal::CurveT<D3> k = internal::generalized_curve_t(
      constant(c.x), constant(c.y), internal::NormT<D3>{c.normalize_x, c.normalize_y}, cos_phi,
      sin_phi);
  if (k.max_force_n.v <= 0.0 || k.initial_slope_n.v <= 0.0) return {D3(0.0), D3(1.0)};
  const D3 f = internal::f_of_s_t(k, s);
  return {f, internal::sliding_ratio_t(k.max_slip, k.max_force_n, s, f)};
}

}  // namespace

TireForcePartials tire_force_partials(const TmeasyParams& p, const TireCharacteristic& c,
                                      const TireKinematics& k, const Eigen::Vector2d& s) noexcept {
  const D3 vx = D3::variable(k.long_speed_mps, 0);
  const D3 vy = D3::variable(k.lat_speed_mps, 1);
  const D3 w = D3::variable(k.spin_radps, 2);
  const double r = k.rolling_radius_m;
  const D3 rolling = r * internal::abs(w);
  const D3 slip_speed_x = vx - r * w;
  // eqs. (14-17), (24), (22) as in slip_of, directional_dynamics and limited_forces
  const SlipCurveDual curve =
      slip_curve_dual(c, -slip_speed_x / (rolling * c.normalize_x + p.velocity_floor_mps),
                      -vy / (rolling * c.normalize_y + p.velocity_floor_mps));
  const D3& f = curve.f;
  // the low-speed damping's weight (deflection_damping), moving with v_x
  const D3 weight = low_speed_weight(p, vx);
  const auto force = [&](const D3& slip_speed, double normalize, double deflection,
                         double stiffness, const D3& damping) {
    const D3 rs = rolling * normalize;
    const D3 rate = (-f * slip_speed - stiffness * deflection * rs) / (damping * rs + f + 1e-9);
    return stiffness * deflection + damping * rate;
  };
  D3 fx = force(slip_speed_x, c.normalize_x, s(0), p.longitudinal_stiffness_npm,
                p.longitudinal_damping_nspm + weight * c.low_speed_damping_x_nspm);
  D3 fy = force(vy, c.normalize_y, s(1), p.lateral_stiffness_npm,
                p.lateral_damping_nspm + weight * c.low_speed_damping_y_nspm);
  TireForcePartials out;
  const double rho = ellipse_ratio(c, fx.v, fy.v) / curve.sliding_ratio.v;
  if (rho == std::numeric_limits<double>::infinity()) return out;  // no force, no partials
  if (rho > 1.0) {  // eq. (26): F^D kappa / |F^D/F_M|, of the duals
    const D3 ux = fx / c.x.max_force_n, uy = fy / c.y.max_force_n;
    const D3 rho_d = internal::sqrt(ux * ux + uy * uy) / curve.sliding_ratio;
    fx = fx / rho_d;
    fy = fy / rho_d;
  }
  for (int j = 0; j < 3; ++j) {
    out.d_force(0, j) = fx.d[j];
    out.d_force(1, j) = fy.d[j];
  }
  return out;
}

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
  // the low-speed damping at this load: zeta_low of the mass F_z / g on each tire spring
  const double mass_kg = load_n / 9.80665;
  c.low_speed_damping_x_nspm =
      2.0 * p.low_speed_damping_ratio * std::sqrt(p.longitudinal_stiffness_npm * mass_kg);
  c.low_speed_damping_y_nspm =
      2.0 * p.low_speed_damping_ratio * std::sqrt(p.lateral_stiffness_npm * mass_kg);
  return c;
}

double f_per_slip_of(const TireCharacteristic& c, double slip_x, double slip_y) noexcept {
  return slip_curve_value(c, slip_x, slip_y).f_per_slip;
}

SlipCurveValue slip_curve_value(const TireCharacteristic& c, double slip_x,
                                double slip_y) noexcept {
  // sqrt without glibc hypot's overflow care (our magnitudes are far from it)
  const double s = std::sqrt(slip_x * slip_x + slip_y * slip_y);
  double cos_phi = 1.0, sin_phi = 0.0;  // s = 0: phi = 0, f(0) = dFx0 s^x
  if (s > 1e-12) {
    cos_phi = slip_x / s;
    sin_phi = slip_y / s;
  }
  const TmeasyCurve k = generalized_curve(c.x, c.y, SlipNormalization{c.normalize_x, c.normalize_y},
                                          cos_phi, sin_phi);
  if (k.max_force_n <= 0.0 || k.initial_slope_n <= 0.0) return {};
  const double f = evaluate_characteristic(k, s).f_n;
  return {f, internal::sliding_ratio_t(k.max_slip, k.max_force_n, s, f)};
}

TireSlip slip_of(const TireCharacteristic& c, const TireKinematics& k,
                 double velocity_floor_mps) noexcept {
  const double r = k.rolling_radius_m;
  const double rw = r * std::abs(k.spin_radps);
  TireSlip out;
  // eqs. (14-15)
  out.slip_x = -(k.long_speed_mps - r * k.spin_radps) / (rw * c.normalize_x + velocity_floor_mps);
  out.slip_y = -k.lat_speed_mps / (rw * c.normalize_y + velocity_floor_mps);
  const SlipCurveValue v = slip_curve_value(c, out.slip_x, out.slip_y);
  out.f_per_slip = v.f_per_slip;
  out.sliding_ratio = v.sliding_ratio;
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

double aligning_torque_nm(const TmeasyParams& p, const TireKinematics& k, double load_n,
                          double lat_force_n) noexcept {
  if (!(load_n > 0.0)) return 0.0;
  const double q = load_n / p.nominal_load_n;
  const TmeasyTrail& t = p.trail;
  // (n/L)_0, s_y0 and s_yE are linear in the load, like TMeasy's slips
  const double n0 = linear_in_load(t.trail_over_length_nominal, t.trail_over_length_double, q);
  const double sy0 = linear_in_load(t.zero_slip_nominal, t.zero_slip_double, q);
  const double sy_end = linear_in_load(t.end_slip_nominal, t.end_slip_double, q);
  const double lat_slip =
      -k.lat_speed_mps / (k.rolling_radius_m * std::abs(k.spin_radps) + p.velocity_floor_mps);
  const double contact_length =
      std::sqrt(8.0 * p.radius_unloaded_m * load_n / p.vertical_stiffness_npm);
  return -trail_over_length(n0, sy0, sy_end, lat_slip) * contact_length * lat_force_n;
}

}  // namespace rig::model::tire
