#pragma once
/// @file
/// Vertical tire force with lift-off, and TMeasy's dynamic rolling radius.

namespace rig::model::tire {

/// F_z = max(0, c_z dz + d_z dz') and its partials (zero when lifted off).
struct VerticalForce {
  double force_n = 0;               ///< F_z >= 0
  double d_force_d_deflection = 0;  ///< dF_z/ddz = c_z (0 lifted off)
  double d_force_d_rate = 0;        ///< dF_z/ddz' = d_z (0 lifted off)
  bool in_contact = false;
};

/// @param deflection_m dz = r_0 - r_S (> 0 compressed); @param deflection_rate_mps dz'.
[[nodiscard]] constexpr VerticalForce vertical_tire_force(double stiffness_npm, double damping_nspm,
                                                          double deflection_m,
                                                          double deflection_rate_mps) noexcept {
  const double f = stiffness_npm * deflection_m + damping_nspm * deflection_rate_mps;
  if (deflection_m <= 0.0 || f <= 0.0) return {};  // lift-off: the tire cannot pull the road
  return {f, stiffness_npm, damping_nspm, true};
}

/// TMeasy's dynamic rolling radius r_D ~ 2/3 r_0 + 1/3 r_S with the static radius
/// r_S = r_0 - F_z/c_z (Rill 2011, eq. 3.20). F_z <= 0 gives r_0.
[[nodiscard]] constexpr double dynamic_rolling_radius(double unloaded_radius_m, double load_n,
                                                      double vertical_stiffness_npm) noexcept {
  const double deflection = load_n > 0.0 ? load_n / vertical_stiffness_npm : 0.0;
  return unloaded_radius_m - deflection / 3.0;
}
/// d r_D / d F_z.
[[nodiscard]] constexpr double dynamic_rolling_radius_d_load(
    double load_n, double vertical_stiffness_npm) noexcept {
  return load_n > 0.0 ? -1.0 / (3.0 * vertical_stiffness_npm) : 0.0;
}

}  // namespace rig::model::tire
