#include "model/examples/quarter_car/quarter_car_tire.h"

#include <algorithm>
#include <cmath>

namespace rig::model::examples {
namespace {

// 215/55 R18 longitudinal data at F_zN = 3500 N and 2 F_zN (issue 3).
constexpr double kLoadNominal_n = 3500.0;
constexpr double kDf0[2] = {100e3, 190e3};
constexpr double kFm[2] = {3.9e3, 7.4e3};
constexpr double kSm[2] = {0.11, 0.15};
constexpr double kStiffness_npm = 250e3;  // c_x
constexpr double kDamping_nspm = 2000.0;  // d_x
constexpr double kVn_mps = 0.5;           // v_N

// Degressive load dependence of forces and slopes: q (2 w1 - w2/2 - (w1 - w2/2) q).
double degressive(const double w[2], double q) {
  return q * (2 * w[0] - 0.5 * w[1] - (w[0] - 0.5 * w[1]) * q);
}
double linear(const double w[2], double q) { return w[0] + (w[1] - w[0]) * (q - 1.0); }

struct Curve {
  double df0, fm, sm, fs, ss;
};

Curve curve_at(double fz) {
  const double q = fz / kLoadNominal_n;
  Curve c{};
  c.df0 = degressive(kDf0, q);
  c.fm = degressive(kFm, q);
  c.sm = linear(kSm, q);
  c.fs = 0.9 * c.fm;
  c.ss = 3.0 * c.sm;
  return c;
}

// f(s) = F(s)/s of the TMeasy characteristic (f(0) = dF0) and its derivative df/ds.
struct FOfS {
  double f, df_ds;
};

FOfS f_of_s(const Curve& c, double s) {
  if (s <= c.sm) {
    // F = dF0 s / (1 + sig (sig + A - 2)), sig = s / s_M, A = dF0 s_M / F_M
    const double sig = s / c.sm;
    const double a = c.df0 * c.sm / c.fm;
    const double den = 1.0 + sig * (sig + a - 2.0);
    return {c.df0 / den, -c.df0 * (2.0 * sig + a - 2.0) / (c.sm * den * den)};
  }
  if (s < c.ss) {
    const double sig = (s - c.sm) / (c.ss - c.sm);
    const double force = c.fm - (c.fm - c.fs) * sig * sig * (3.0 - 2.0 * sig);
    const double dforce = -(c.fm - c.fs) * 6.0 * sig * (1.0 - sig) / (c.ss - c.sm);
    return {force / s, (dforce * s - force) / (s * s)};
  }
  return {c.fs / s, -c.fs / (s * s)};
}

double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

}  // namespace

QuarterCarTire::QuarterCarTire(double wheel_load_n, double radius_m)
    : wheel_load_n_(wheel_load_n), radius_m_(radius_m) {}

double QuarterCarTire::max_force_n() const noexcept { return curve_at(wheel_load_n_).fm; }
double QuarterCarTire::stiffness_npm() const noexcept { return kStiffness_npm; }

TireLongitudinalState QuarterCarTire::evaluate(double x_e, double v, double w) const noexcept {
  const Curve c = curve_at(wheel_load_n_);
  const double r = radius_m_;
  const double u = v - r * w;                               // contact point sliding speed
  const double transport = r * std::abs(w);                 // r_D |omega|
  const double slip = std::abs(u) / (transport + kVn_mps);  // eqs. (14-15)
  const FOfS fs = f_of_s(c, slip);
  // eq. (24): (d_x r|w| + f) x_e' = -f (v_x - r w) - c_x x_e r|w|
  const double num = -fs.f * u - kStiffness_npm * x_e * transport;
  const double den = kDamping_nspm * transport + fs.f;
  TireLongitudinalState st;
  st.deflection_rate_mps = num / den;
  st.force_n = kStiffness_npm * x_e + kDamping_nspm * st.deflection_rate_mps;  // eq. (22)
  const double fm = c.fm;
  if (std::abs(st.force_n) > fm) {  // eq. (26)
    st.limited = true;
    st.force_n = std::copysign(fm, x_e);
    st.deflection_rate_mps = 0.0;
    return st;
  }
  // Partial derivatives of x_e' = num / den (through f(s(v, w)) as well).
  const double ds_dv = sign(u) / (transport + kVn_mps);
  const double ds_dw = (-r * sign(u) - slip * r * sign(w)) / (transport + kVn_mps);
  const double dnum_dv = -fs.df_ds * ds_dv * u - fs.f;
  const double dden_dv = fs.df_ds * ds_dv;
  const double dnum_dw = -fs.df_ds * ds_dw * u + fs.f * r - kStiffness_npm * x_e * r * sign(w);
  const double dden_dw = kDamping_nspm * r * sign(w) + fs.df_ds * ds_dw;
  st.d_rate_d_deflection = -kStiffness_npm * transport / den;
  st.d_rate_d_speed = (dnum_dv - st.deflection_rate_mps * dden_dv) / den;
  st.d_rate_d_spin = (dnum_dw - st.deflection_rate_mps * dden_dw) / den;
  return st;
}

double QuarterCarTire::limit_deflection(double x_e) const noexcept {
  const double x_max = max_force_n() / kStiffness_npm;
  return std::clamp(x_e, -x_max, x_max);
}

}  // namespace rig::model::examples
