#pragma once
/// @file
/// Templated bodies of the TMeasy characteristic (tmeasy_characteristic.h), instantiated with
/// double and with internal::Dual for exact partial derivatives. Internal to model/tire.

#include <cmath>

#include "model/tire/dual.h"
#include "model/tire/tmeasy_characteristic.h"

namespace rig::model::tire::internal {

using std::abs;
using std::sqrt;

template <class T>
struct CurveT {
  T initial_slope_n, max_force_n, max_slip, slide_force_n, slide_slip;
};

template <class T>
CurveT<T> curve_at_load_t(const TmeasyCurvePair& p, const T& q, double mu_ratio) {
  const TmeasyCurve& a = p.at_nominal;
  const TmeasyCurve& b = p.at_double;
  auto deg = [&q](double w1, double w2) { return q * (2.0 * w1 - 0.5 * w2 - (w1 - 0.5 * w2) * q); };
  auto lin = [&q](double w1, double w2) { return w1 + (w2 - w1) * (q - 1.0); };
  // forces and the initial slope: degressive parabola; slips: linear in q; mu/mu0 scales the
  // force and slip levels, not the initial slope (Rill 2011, sec. 3.4.2)
  return {deg(a.initial_slope_n, b.initial_slope_n), mu_ratio * deg(a.max_force_n, b.max_force_n),
          mu_ratio * lin(a.max_slip, b.max_slip), mu_ratio * deg(a.slide_force_n, b.slide_force_n),
          mu_ratio * lin(a.slide_slip, b.slide_slip)};
}

template <class T>
struct NormT {
  T x, y;
};

template <class T>
NormT<T> slip_normalization_t(const CurveT<T>& lo, const CurveT<T>& la) {
  // Rill 2011, eq. 3.83: both directions contribute about equally to the generalized slip
  const T sum_slip = lo.max_slip + la.max_slip;
  const T rx = lo.max_force_n / lo.initial_slope_n;
  const T ry = la.max_force_n / la.initial_slope_n;
  const T sum_r = rx + ry;
  return {lo.max_slip / sum_slip + rx / sum_r, la.max_slip / sum_slip + ry / sum_r};
}

template <class T>
CurveT<T> generalized_curve_t(const CurveT<T>& lo, const CurveT<T>& la, const NormT<T>& n,
                              const T& c, const T& s) {
  auto comb = [&c, &s](const T& x, const T& y) { return sqrt(x * x * c * c + y * y * s * s); };
  return {comb(lo.initial_slope_n * n.x, la.initial_slope_n * n.y),
          comb(lo.max_force_n, la.max_force_n), comb(lo.max_slip / n.x, la.max_slip / n.y),
          comb(lo.slide_force_n, la.slide_force_n), comb(lo.slide_slip / n.x, la.slide_slip / n.y)};
}

/// f(s) = F(s)/s of Rill's characteristic (f(0) = dF0) for s >= 0.
template <class T>
T f_of_s_t(const CurveT<T>& k, const T& s) {
  if (value_of(s) <= value_of(k.max_slip)) {
    const T sig = s / k.max_slip;
    const T a = k.initial_slope_n * k.max_slip / k.max_force_n;
    return k.initial_slope_n / (1.0 + sig * (sig + a - 2.0));
  }
  if (value_of(s) < value_of(k.slide_slip)) {
    const T sig = (s - k.max_slip) / (k.slide_slip - k.max_slip);
    return (k.max_force_n - (k.max_force_n - k.slide_force_n) * sig * sig * (3.0 - 2.0 * sig)) / s;
  }
  return k.slide_force_n / s;
}

/// The sliding ratio F(s)/F_M of the characteristic, from f = f(s): 1 up to s_M, falling to
/// F_S/F_M at s_S and beyond. Eq. (26)'s limit is F_M times it, so that a sliding tire transmits
/// F(s) -> F_S.
template <class T, class Slip>
T sliding_ratio_t(const T& max_slip, const T& max_force_n, const Slip& s, const Slip& f) {
  if (value_of(s) <= value_of(max_slip)) return T(1.0);
  return f * s / max_force_n;
}

inline CurveT<double> to_t(const TmeasyCurve& c) {
  return {c.initial_slope_n, c.max_force_n, c.max_slip, c.slide_force_n, c.slide_slip};
}
inline TmeasyCurve from_t(const CurveT<double>& c) {
  return {c.initial_slope_n, c.max_force_n, c.max_slip, c.slide_force_n, c.slide_slip};
}

}  // namespace rig::model::tire::internal
