#include "model/tire/tmeasy_dual_law.h"

#include <algorithm>
#include <cmath>

#include "model/tire/tmeasy_characteristic_impl.h"

namespace rig::model::tire::legacy {
namespace {

using D = internal::Dual<4>;  // derivative slots: v_x, v_y, omega, F_z (TirePartial order)

/// Slip kinematics and f(s) of eqs. (14-17), in dual numbers.
struct SlipState {
  D long_slip_n, lat_slip_n;  // s_x^N, s_y^N
  D s;                        // generalized slip
  D f;                        // f(s)
  D roll_x, roll_y;           // r_D |omega| s^x, r_D |omega| s^y (eq. 24 without v_N)
  D max_long, max_lat;        // F_xM, F_yM at the load and friction
};

using D1 = internal::Dual<1>;  // load-only quantities: derivative by q = F_z / F_zN

/// A load-only dual lifted into the four slots (d/dF_z = d/dq / F_zN).
D lift(const D1& a, double inv_nominal_load) {
  D r(a.v);
  r.d[kByLoad] = a.d[0] * inv_nominal_load;
  return r;
}

SlipState slip_state(const TmeasyParams& p, const TireInput& in) {
  const D vx = D::variable(in.long_speed_mps, kByLongSpeed);
  const D vy = D::variable(in.lat_speed_mps, kByLatSpeed);
  const D w = D::variable(in.spin_radps, kBySpin);
  const double inv_fzn = 1.0 / p.nominal_load_n;
  const D1 q = D1::variable(in.load_n * inv_fzn, 0);
  const double mu_ratio = in.friction / p.reference_friction;
  const double r = in.rolling_radius_m;

  // the load-dependent curves and normalizing factors depend on F_z only: cheap 1-slot duals
  const auto lo = internal::curve_at_load_t(p.longitudinal, q, mu_ratio);
  const auto la = internal::curve_at_load_t(p.lateral, q, mu_ratio);
  const auto norm = internal::slip_normalization_t(lo, la);

  SlipState st;
  const D rw = r * internal::abs(w);
  st.roll_x = rw * lift(norm.x, inv_fzn);
  st.roll_y = rw * lift(norm.y, inv_fzn);
  // eqs. (14-15): normalized slips with the artificial velocity v_N
  st.long_slip_n = -(vx - r * w) / (st.roll_x + p.velocity_floor_mps);
  st.lat_slip_n = -vy / (st.roll_y + p.velocity_floor_mps);
  const D s2 = st.long_slip_n * st.long_slip_n + st.lat_slip_n * st.lat_slip_n;
  D cos2(1.0), sin2(0.0);
  if (s2.v > 1e-24) {
    st.s = internal::sqrt(s2);
    cos2 = st.long_slip_n * st.long_slip_n / s2;
    sin2 = st.lat_slip_n * st.lat_slip_n / s2;
  } else {
    st.s = D(0.0);  // direction undefined at s = 0: phi = 0 (f(0) = dF0 of the x curve)
  }
  // generalized curve (Rill 2011, eqs. 3.84-3.86): P = sqrt(P_x^2 cos^2 + P_y^2 sin^2)
  auto comb = [&](const D1& x, const D1& y) {
    return internal::sqrt(lift(x * x, inv_fzn) * cos2 + lift(y * y, inv_fzn) * sin2);
  };
  internal::CurveT<D> k{comb(lo.initial_slope_n * norm.x, la.initial_slope_n * norm.y),
                        comb(lo.max_force_n, la.max_force_n),
                        comb(lo.max_slip / norm.x, la.max_slip / norm.y), D(0.0), D(0.0)};
  if (st.s.v > k.max_slip.v) {  // the sliding values are needed beyond s_M only
    k.slide_force_n = comb(lo.slide_force_n, la.slide_force_n);
    k.slide_slip = comb(lo.slide_slip / norm.x, la.slide_slip / norm.y);
  }
  st.f = internal::f_of_s_t(k, st.s);
  st.max_long = lift(lo.max_force_n, inv_fzn);
  st.max_lat = lift(la.max_force_n, inv_fzn);
  return st;
}

void copy_partials(const D& x, Eigen::Matrix<double, 2, kTirePartialCount>& m, int row) {
  for (int i = 0; i < 4; ++i) m(row, i) = x.d[i];
}

/// Pneumatic trail over contact length, (n/L)(s_y), Rill 2011 eq. 3.92 form: falls from
/// (n/L)_0 through zero at s_y0 to a negative dip and back to zero at s_yE.
double trail_over_length(double n0, double sy0, double syE, double sy) {
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

}  // namespace

TmeasyTire::TmeasyTire(const TmeasyParams& params) noexcept : params_(params) {}

double TmeasyTire::max_long_force_n(double load_n, double friction) const noexcept {
  if (load_n <= 0.0) return 0.0;
  return curve_at_load(params_.longitudinal, load_n / params_.nominal_load_n,
                       friction / params_.reference_friction)
      .max_force_n;
}

double TmeasyTire::max_lat_force_n(double load_n, double friction) const noexcept {
  if (load_n <= 0.0) return 0.0;
  return curve_at_load(params_.lateral, load_n / params_.nominal_load_n,
                       friction / params_.reference_friction)
      .max_force_n;
}

SteadyStateForces TmeasyTire::steady_state(const TireInput& in) const noexcept {
  SteadyStateForces r;
  if (in.load_n <= 0.0 || in.friction <= 0.0) return r;
  const SlipState st = slip_state(params_, in);
  r.long_slip_normalized = st.long_slip_n.v;
  r.lat_slip_normalized = st.lat_slip_n.v;
  r.generalized_slip = st.s.v;
  r.f_n = st.f.v;
  r.long_force_n = st.f.v * st.long_slip_n.v;  // eq. (16)
  r.lat_force_n = st.f.v * st.lat_slip_n.v;    // eq. (17)
  return r;
}

void TmeasyTire::evaluate(const TireInput& in, const TireDeflection& deflection,
                          TireOutput& out) const noexcept {
  const TmeasyParams& p = params_;
  out = TireOutput{};
  const double cx = p.longitudinal_stiffness_npm, dx = p.longitudinal_damping_nspm;
  const double cy = p.lateral_stiffness_npm, dy = p.lateral_damping_nspm;

  if (in.load_n <= 0.0 || in.friction <= 0.0) {
    // lift-off (or no friction): zero force, the free spring-damper relaxes: c x_e + d x_e' = 0
    out.lifted_off = true;
    out.deflection_rate = {-cx / dx * deflection.long_m, -cy / dy * deflection.lat_m};
    out.d_rate_d_deflection = {-cx / dx, -cy / dy};
    out.d_rate(0, kByLongDeflection) = -cx / dx;
    out.d_rate(1, kByLatDeflection) = -cy / dy;
    return;
  }

  const SlipState st = slip_state(p, in);
  const double r = in.rolling_radius_m;
  const D vx = D::variable(in.long_speed_mps, kByLongSpeed);
  const D vy = D::variable(in.lat_speed_mps, kByLatSpeed);
  const D w = D::variable(in.spin_radps, kBySpin);

  // eq. (24): (d_x r_D |w| s^x + f) x_e' = -f (v_x - r_D w) - c_x x_e r_D |w| s^x.
  // At stand-still (v_x = 0, w = 0) this gives x_e' = 0; locked (w = 0): x_e' = -v_x (eq. 25).
  const D den_x = dx * st.roll_x + st.f;
  const D xe_rate = (-st.f * (vx - r * w) - cx * deflection.long_m * st.roll_x) / den_x;
  const D fx = cx * deflection.long_m + dx * xe_rate;  // eq. (22)
  // lateral twin: (d_y r_D |w| s^y + f) y_e' = -f v_y - c_y y_e r_D |w| s^y
  const D den_y = dy * st.roll_y + st.f;
  const D ye_rate = (-st.f * vy - cy * deflection.lat_m * st.roll_y) / den_y;
  const D fy = cy * deflection.lat_m + dy * ye_rate;

  // longitudinal: eq. (26) limiter, else the dynamic force
  if (std::abs(fx.v) > st.max_long.v) {
    // eq. (26) writes sign(x_e); we take the sign of the dynamic force, which is the same
    // whenever the spring part dominates, and does not reverse the force when the damping
    // part d_x x_e' dominates (e.g. a wheel locking at speed with a small opposite x_e)
    const double sign = std::copysign(1.0, fx.v);
    out.long_limited = true;
    out.long_force_n = sign * st.max_long.v;
    out.d_force(0, kByLoad) = sign * st.max_long.d[kByLoad];
  } else {
    out.deflection_rate(0) = xe_rate.v;
    out.long_force_n = fx.v;
    copy_partials(xe_rate, out.d_rate, 0);
    copy_partials(fx, out.d_force, 0);
    out.d_rate_d_deflection(0) = -cx * st.roll_x.v / den_x.v;
    out.d_rate(0, kByLongDeflection) = out.d_rate_d_deflection(0);
    out.d_force(0, kByLongDeflection) = cx + dx * out.d_rate_d_deflection(0);
  }
  if (std::abs(fy.v) > st.max_lat.v) {
    const double sign = std::copysign(1.0, fy.v);
    out.lat_limited = true;
    out.lat_force_n = sign * st.max_lat.v;
    out.d_force(1, kByLoad) = sign * st.max_lat.d[kByLoad];
  } else {
    out.deflection_rate(1) = ye_rate.v;
    out.lat_force_n = fy.v;
    copy_partials(ye_rate, out.d_rate, 1);
    copy_partials(fy, out.d_force, 1);
    out.d_rate_d_deflection(1) = -cy * st.roll_y.v / den_y.v;
    out.d_rate(1, kByLatDeflection) = out.d_rate_d_deflection(1);
    out.d_force(1, kByLatDeflection) = cy + dy * out.d_rate_d_deflection(1);
  }

  // self-aligning torque M_z = -n F_y, n = (n/L) L, contact length L = sqrt(8 r_0 dz)
  const double q = in.load_n / p.nominal_load_n;
  const TmeasyTrail& t = p.trail;
  const double n0 = internal::curve_at_load_t(  // (n/L)_0 linear in q like the slips
                        TmeasyCurvePair{{0, 0, t.trail_over_length_nominal, 0, 0},
                                        {0, 0, t.trail_over_length_double, 0, 0}},
                        q, 1.0)
                        .max_slip;
  const double sy0 = internal::curve_at_load_t(TmeasyCurvePair{{0, 0, t.zero_slip_nominal, 0, 0},
                                                               {0, 0, t.zero_slip_double, 0, 0}},
                                               q, 1.0)
                         .max_slip;
  const double syE = internal::curve_at_load_t(TmeasyCurvePair{{0, 0, t.end_slip_nominal, 0, 0},
                                                               {0, 0, t.end_slip_double, 0, 0}},
                                               q, 1.0)
                         .max_slip;
  const double lat_slip = -in.lat_speed_mps / (r * std::abs(in.spin_radps) + p.velocity_floor_mps);
  const double contact_length =
      std::sqrt(8.0 * p.radius_unloaded_m * in.load_n / p.vertical_stiffness_npm);
  out.aligning_torque_nm =
      -trail_over_length(n0, sy0, syE, lat_slip) * contact_length * out.lat_force_n;

  // rolling resistance T_R = -f_r F_z r_D tanh-like(r_D w / v_N), smooth through w = 0
  const double vr = r * in.spin_radps;
  const double den = std::abs(vr) + p.velocity_floor_mps;
  out.rolling_torque_nm = -p.rolling_resistance * in.load_n * r * vr / den;
  out.d_rolling_torque_d_spin =
      -p.rolling_resistance * in.load_n * r * r * p.velocity_floor_mps / (den * den);
}

void TmeasyTire::clamp_deflection(double load_n, double friction,
                                  TireDeflection& deflection) const noexcept {
  const double fxm = max_long_force_n(load_n, friction);
  const double fym = max_lat_force_n(load_n, friction);
  const double xm = fxm / params_.longitudinal_stiffness_npm;
  const double ym = fym / params_.lateral_stiffness_npm;
  deflection.long_m = std::clamp(deflection.long_m, -xm, xm);
  deflection.lat_m = std::clamp(deflection.lat_m, -ym, ym);
}

}  // namespace rig::model::tire::legacy
