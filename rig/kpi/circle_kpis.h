#pragma once
/// @file
/// ISO 4138 (steady-state circular driving), constant-radius method: the understeer gradient
/// from the steady states of a run whose speed rises in plateaus of `plateau_s` (the path
/// driver's speed steps). Each plateau gives one steady point: the means over its last
/// `steady_s` of the steering-wheel angle delta_H, the speed v and the yaw rate r, kept if v
/// varied by less than `speed_band_mps` there. At a steady state a_y = v r and the radius driven
/// is R = v / r, so (ISO 4138, at the road wheels, the overall steering ratio i_s)
///
///   K = d(delta_H / i_s - l / R) / d(a_y)
///
/// is the least-squares slope over the steady points with a_y in [ay_min, ay_max] (l the
/// wheelbase; on a constant radius l / R barely changes, its slope is taken out all the same).
/// NaN with fewer than two such points.

#include <span>

namespace rig::kpi {

struct CircleParams {
  double from_s = 0.0;     ///< the first plateau's start
  double plateau_s = 8.0;  ///< the length of each plateau
  double steady_s = 3.0;   ///< its last part, averaged
  double speed_band_mps = 0.1;
  double ay_min_mps2 = 0.0, ay_max_mps2 = 4.0;
  double wheelbase_m = 2.8;
  double steering_ratio = 16.0;
};

double understeer_gradient(std::span<const double> t_s, std::span<const double> wheel_angle_rad,
                           std::span<const double> speed_mps,
                           std::span<const double> yaw_rate_radps, const CircleParams& p);

}  // namespace rig::kpi
