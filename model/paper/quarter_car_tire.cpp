#include "model/paper/quarter_car_tire.h"

namespace rig::model::paper {

QuarterCarTire::QuarterCarTire(const tire::TmeasyParams& params, double wheel_load_n,
                               double radius_m)
    : tire_(params), wheel_load_n_(wheel_load_n), radius_m_(radius_m) {}

double QuarterCarTire::max_force_n() const noexcept {
  return tire_.max_long_force_n(wheel_load_n_, 1.0);
}

TireLongitudinalState QuarterCarTire::evaluate(double x_e, double v, double w) const noexcept {
  if (cache_valid_ && x_e == cached_x_e_ && v == cached_v_ && w == cached_w_) return cached_;
  tire::legacy::TireInput in;
  in.long_speed_mps = v;
  in.spin_radps = w;
  in.rolling_radius_m = radius_m_;
  in.load_n = wheel_load_n_;
  in.friction = 1.0;
  tire::legacy::TireOutput out;
  tire_.evaluate(in, tire::legacy::TireDeflection{x_e, 0.0}, out);
  TireLongitudinalState st;
  st.deflection_rate_mps = out.deflection_rate(0);
  st.force_n = out.long_force_n;
  st.limited = out.long_limited;
  st.d_rate_d_deflection = out.d_rate_d_deflection(0);
  st.d_force_d_speed = out.d_force(0, tire::legacy::kByLongSpeed);
  st.d_force_d_spin = out.d_force(0, tire::legacy::kBySpin);
  st.rolling_torque_nm = out.rolling_torque_nm;
  st.d_rolling_torque_d_spin = out.d_rolling_torque_d_spin;
  cached_x_e_ = x_e;
  cached_v_ = v;
  cached_w_ = w;
  cached_ = st;
  cache_valid_ = true;
  return st;
}

double QuarterCarTire::limit_deflection(double x_e) const noexcept {
  tire::legacy::TireDeflection d{x_e, 0.0};
  tire_.clamp_deflection(wheel_load_n_, 1.0, d);
  return d.long_m;
}

}  // namespace rig::model::paper
