#pragma once
/// @file
/// The tire's vertical force with lift-off, and TMeasy's dynamic rolling radius: the one
/// vertical law of the project (the vehicle's contacts use it).

namespace rig::model::tire {

/// F_z = max(0, c_z dz + d_z dz') and its partials (zero when lifted off).
struct VerticalForce {
  double force_n = 0;               ///< F_z >= 0
  double d_force_d_deflection = 0;  ///< dF_z/ddz = c_z (0 lifted off)
  double d_force_d_rate = 0;        ///< dF_z/ddz' = d_z (0 lifted off)
  bool in_contact = false;
};

/// @param deflection_m dz = r_0 - (height of the wheel centre) (> 0 compressed, the tire's
/// penetration into the road); @param deflection_rate_mps dz'.
[[nodiscard]] constexpr VerticalForce vertical_tire_force(double stiffness_npm, double damping_nspm,
                                                          double deflection_m,
                                                          double deflection_rate_mps) noexcept {
  if (deflection_m <= 0.0) return {};  // lift-off
  const double f = stiffness_npm * deflection_m + damping_nspm * deflection_rate_mps;
  if (!(f > 0.0)) return {};  // the tire cannot pull the road
  return {f, stiffness_npm, damping_nspm, true};
}

/// TMeasy's dynamic rolling radius r_D ~ 2/3 r_0 + 1/3 r_S (Rill 2011, eq. 3.20) with the
/// loaded radius r_S = r_0 - dz, dz the vertical deflection; dz <= 0 (lifted off) gives r_0.
[[nodiscard]] constexpr double dynamic_rolling_radius(double radius_unloaded_m,
                                                      double deflection_m) noexcept {
  return radius_unloaded_m - (deflection_m > 0.0 ? deflection_m : 0.0) / 3.0;
}

}  // namespace rig::model::tire
