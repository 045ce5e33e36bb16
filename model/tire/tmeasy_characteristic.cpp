#include "model/tire/tmeasy_characteristic.h"

#include <cmath>

#include "model/tire/tmeasy_characteristic_impl.h"

namespace rig::model::tire {

TmeasyCurve curve_at_load(const TmeasyCurvePair& pair, double load_ratio,
                          double friction_ratio) noexcept {
  return internal::from_t(internal::curve_at_load_t<double>(pair, load_ratio, friction_ratio));
}

TmeasyCurve curve_at_load_dq(const TmeasyCurvePair& pair, double load_ratio,
                             double friction_ratio) noexcept {
  const auto q = internal::Dual<1>::variable(load_ratio, 0);
  const auto c = internal::curve_at_load_t(pair, q, friction_ratio);
  return {c.initial_slope_n.d[0], c.max_force_n.d[0], c.max_slip.d[0], c.slide_force_n.d[0],
          c.slide_slip.d[0]};
}

SlipNormalization slip_normalization(const TmeasyCurve& longitudinal,
                                     const TmeasyCurve& lateral) noexcept {
  const auto n =
      internal::slip_normalization_t(internal::to_t(longitudinal), internal::to_t(lateral));
  return {n.x, n.y};
}

CharacteristicValue evaluate_characteristic(const TmeasyCurve& curve, double slip) noexcept {
  const double s = std::abs(slip);
  const auto sd = internal::Dual<1>::variable(s, 0);
  const internal::CurveT<internal::Dual<1>> k{curve.initial_slope_n, curve.max_force_n,
                                              curve.max_slip, curve.slide_force_n,
                                              curve.slide_slip};
  const auto f = internal::f_of_s_t(k, sd);
  CharacteristicValue r;
  r.f_n = f.v;
  r.df_ds = f.d[0];
  r.force_n = f.v * s;
  r.dforce_ds = f.d[0] * s + f.v;
  return r;
}

TmeasyCurve generalized_curve(const TmeasyCurve& longitudinal, const TmeasyCurve& lateral,
                              const SlipNormalization& norm, double cos_phi,
                              double sin_phi) noexcept {
  return internal::from_t(
      internal::generalized_curve_t(internal::to_t(longitudinal), internal::to_t(lateral),
                                    internal::NormT<double>{norm.x, norm.y}, cos_phi, sin_phi));
}

}  // namespace rig::model::tire
