#include "model/tire/tmeasy_params.h"

namespace rig::model::tire {
namespace {

const char* check_curve(const TmeasyCurve& c, const char* slope, const char* force,
                        const char* slips, const char* slide) {
  if (!(c.initial_slope_n > 0)) return slope;
  if (!(c.max_force_n > 0)) return force;
  if (!(c.max_slip > 0 && c.slide_slip > c.max_slip)) return slips;
  if (!(c.slide_force_n > 0 && c.slide_force_n <= c.max_force_n)) return slide;
  return nullptr;
}

}  // namespace

const char* check_params(const TmeasyParams& p) noexcept {
  if (!(p.nominal_load_n > 0)) return "nominal_load_n: F_zN must be > 0";
  const char* e = nullptr;
  if ((e = check_curve(p.longitudinal.at_nominal, "longitudinal.at_nominal: need dF0 > 0",
                       "longitudinal.at_nominal: need F_M > 0",
                       "longitudinal.at_nominal: need 0 < s_M < s_S",
                       "longitudinal.at_nominal: need 0 < F_S <= F_M")))
    return e;
  if ((e = check_curve(p.longitudinal.at_double, "longitudinal.at_double: need dF0 > 0",
                       "longitudinal.at_double: need F_M > 0",
                       "longitudinal.at_double: need 0 < s_M < s_S",
                       "longitudinal.at_double: need 0 < F_S <= F_M")))
    return e;
  if ((e = check_curve(p.lateral.at_nominal, "lateral.at_nominal: need dF0 > 0",
                       "lateral.at_nominal: need F_M > 0", "lateral.at_nominal: need 0 < s_M < s_S",
                       "lateral.at_nominal: need 0 < F_S <= F_M")))
    return e;
  if ((e = check_curve(p.lateral.at_double, "lateral.at_double: need dF0 > 0",
                       "lateral.at_double: need F_M > 0", "lateral.at_double: need 0 < s_M < s_S",
                       "lateral.at_double: need 0 < F_S <= F_M")))
    return e;
  if (!(p.reference_friction > 0)) return "reference_friction: mu0 must be > 0";
  if (!(p.rolling_resistance >= 0)) return "rolling_resistance: f_r must be >= 0";
  if (!(p.longitudinal_stiffness_npm > 0 && p.longitudinal_damping_nspm > 0))
    return "longitudinal_stiffness_npm, longitudinal_damping_nspm: c_x, d_x must be > 0";
  if (!(p.lateral_stiffness_npm > 0 && p.lateral_damping_nspm > 0))
    return "lateral_stiffness_npm, lateral_damping_nspm: c_y, d_y must be > 0";
  if (!(p.radius_unloaded_m > 0)) return "radius_unloaded_m: r_0 must be > 0";
  if (!(p.vertical_stiffness_npm > 0 && p.vertical_damping_nspm >= 0))
    return "vertical_stiffness_npm > 0 and vertical_damping_nspm >= 0 required";
  if (!(p.velocity_floor_mps > 0)) return "velocity_floor_mps: v_N must be > 0";
  if (!(p.low_speed_damping_ratio >= 0)) return "low_speed_damping_ratio: zeta_low must be >= 0";
  if (!(p.low_speed_damping_speed_mps > 0)) return "low_speed_damping_speed_mps: v_low must be > 0";
  const TmeasyTrail& t = p.trail;
  if (!(t.zero_slip_nominal > 0 && t.end_slip_nominal > t.zero_slip_nominal &&
        t.zero_slip_double > 0 && t.end_slip_double > t.zero_slip_double))
    return "trail: need 0 < s_y0 < s_yE at both loads";
  return nullptr;
}

}  // namespace rig::model::tire
