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

// f(s) = F(s)/s of the TMeasy characteristic; f(0) = dF0.
double f_of_s(const Curve& c, double s) {
  if (s <= c.sm) {
    const double sig = s / c.sm;
    return c.df0 / (1.0 + sig * (sig + c.df0 * c.sm / c.fm - 2.0));
  }
  if (s < c.ss) {
    const double sig = (s - c.sm) / (c.ss - c.sm);
    return (c.fm - (c.fm - c.fs) * sig * sig * (3.0 - 2.0 * sig)) / s;
  }
  return c.fs / s;
}

}  // namespace

QuarterCarTire::QuarterCarTire(double wheel_load_n, double radius_m)
    : wheel_load_n_(wheel_load_n), radius_m_(radius_m) {}

double QuarterCarTire::max_force_n() const noexcept { return curve_at(wheel_load_n_).fm; }
double QuarterCarTire::stiffness_npm() const noexcept { return kStiffness_npm; }

double QuarterCarTire::deflection_rate(double x_e, double v, double w) const noexcept {
  const Curve c = curve_at(wheel_load_n_);
  const double transport = radius_m_ * std::abs(w);
  const double slip = std::abs(-(v - radius_m_ * w) / (transport + kVn_mps));  // eqs. (14-15)
  const double f = f_of_s(c, slip);
  // eq. (24): (d_x r|w| + f) x_e' = -f (v_x - r w) - c_x x_e r|w|
  return (-f * (v - radius_m_ * w) - kStiffness_npm * x_e * transport) /
         (kDamping_nspm * transport + f);
}

TireLongitudinalState QuarterCarTire::evaluate(double x_e, double v, double w) const noexcept {
  TireLongitudinalState st;
  st.deflection_rate_mps = deflection_rate(x_e, v, w);
  st.force_n = kStiffness_npm * x_e + kDamping_nspm * st.deflection_rate_mps;  // eq. (22)
  const double fm = max_force_n();
  if (std::abs(st.force_n) > fm) {  // eq. (26)
    st.limited = true;
    st.force_n = std::copysign(fm, x_e);
    st.deflection_rate_mps = 0.0;
    return st;
  }
  // Central differences of the scalar law (temporary until the tire module's analytic partials).
  const double dx = 1e-7, dv = 1e-6, dw = 1e-6;
  st.d_rate_d_deflection =
      (deflection_rate(x_e + dx, v, w) - deflection_rate(x_e - dx, v, w)) / (2 * dx);
  st.d_rate_d_speed =
      (deflection_rate(x_e, v + dv, w) - deflection_rate(x_e, v - dv, w)) / (2 * dv);
  st.d_rate_d_spin = (deflection_rate(x_e, v, w + dw) - deflection_rate(x_e, v, w - dw)) / (2 * dw);
  return st;
}

double QuarterCarTire::limit_deflection(double x_e) const noexcept {
  const double x_max = max_force_n() / kStiffness_npm;
  return std::clamp(x_e, -x_max, x_max);
}

}  // namespace rig::model::examples
