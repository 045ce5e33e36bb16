#pragma once
/// @file
/// Parameters of the TMeasy tire model (G. Rill; method.md sec. 3, eqs. 14-26). Constant data,
/// kept apart from the deflection state (TireDeflection) and the per-call inputs (TireInput).

namespace rig::model::tire {

/// One TMeasy force characteristic at one wheel load: initial slope, maximum and sliding value.
struct TmeasyCurve {
  double initial_slope_n = 0;  ///< dF0 [N per unit slip]
  double max_force_n = 0;      ///< F_M [N]
  double max_slip = 0;         ///< s_M [-]
  double slide_force_n = 0;    ///< F_S [N]
  double slide_slip = 0;       ///< s_S [-] (> s_M)
};

/// A characteristic given at the two reference loads F_zN and 2 F_zN (TMeasy's load model).
struct TmeasyCurvePair {
  TmeasyCurve at_nominal;  ///< w1: values at F_z = F_zN
  TmeasyCurve at_double;   ///< w2: values at F_z = 2 F_zN
};

/// TMeasy pneumatic trail model (self-aligning torque M_z = -n F_y). The trail over contact
/// length, n/L, falls from (n/L)_0 at zero lateral slip through zero at s_y0 to a negative
/// minimum and back to zero at s_yE (Rill, Road Vehicle Dynamics, sec. 3.4.3).
struct TmeasyTrail {
  double trail_over_length_nominal = 0.178;  ///< (n/L)_0 at F_zN [-]
  double trail_over_length_double = 0.19;    ///< (n/L)_0 at 2 F_zN [-]
  double zero_slip_nominal = 0.40;           ///< s_y0 at F_zN: trail crosses zero [-]
  double zero_slip_double = 0.40;            ///< s_y0 at 2 F_zN [-]
  double end_slip_nominal = 0.60;            ///< s_yE at F_zN: trail back to zero [-]
  double end_slip_double = 0.60;             ///< s_yE at 2 F_zN [-]
};

/// TMeasy's bore torque (Rill, Road Vehicle Dynamics, 2012, sec. 3.3.6; method.md ref. [12]):
/// the patch's torsional deflection about the contact normal with a stiffness and a damping,
/// limited by M_B,max = (2/3) R_P mu F_z, R_P = (L/2 + B/2)/2 (tmeasy_bore.h). Off by default.
struct TmeasyBore {
  bool enabled = false;          ///< bore_torque
  double stiffness_nmprad = 0;   ///< c_B [N m/rad]
  double damping_nmsprad = 0;    ///< d_B [N m s/rad]
  double contact_width_m = 0.2;  ///< B, the patch width [m]
};

/// All TMeasy parameters of one tire.
struct TmeasyParams {
  double nominal_load_n = 3500.0;    ///< F_zN [N]
  TmeasyCurvePair longitudinal;      ///< F_x(s_x) curves at F_zN, 2 F_zN
  TmeasyCurvePair lateral;           ///< F_y(s_y) curves at F_zN, 2 F_zN
  double reference_friction = 1.0;   ///< mu0: the road friction the curves were measured on
  double rolling_resistance = 0.01;  ///< f_r: rolling resistance torque = f_r F_z r_D [-]
  TmeasyTrail trail;                 ///< pneumatic trail (self-aligning torque)
  double longitudinal_stiffness_npm = 250e3;  ///< c_x, eq. (22) [N/m]
  double longitudinal_damping_nspm = 2000.0;  ///< d_x, eq. (22) [N s/m]
  double lateral_stiffness_npm = 175e3;       ///< c_y [N/m]
  double lateral_damping_nspm = 1750.0;       ///< d_y [N s/m]
  double radius_unloaded_m = 0.3469;          ///< r_0 [m]
  double vertical_stiffness_npm = 200e3;      ///< c_z [N/m]
  double vertical_damping_nspm = 50.0;        ///< d_z [N s/m] (small; not in the issue's table)
  double velocity_floor_mps = 0.5;  ///< v_N, the artificial velocity of eqs. (14-15) [m/s]
  /// Low-speed damping of the contact patch: below v_low the deflection's damping grows by
  /// d_low = 2 zeta_low sqrt(c F_z / g) (per direction, F_z/g the mass the tire carries) with the
  /// weight (1 + cos(pi |v_x| / v_low)) / 2. At stand-still the contact-patch rubber's hysteresis
  /// and the wheel's fore-aft bushings damp the car's rocking on its tire springs (3-4 Hz for a
  /// sedan), which d_x alone (zeta ~ 0.03) leaves ringing for seconds; tire models add such a
  /// term for the same reason (e.g. Pacejka, Tire and Vehicle Dynamics, 3rd ed. 2012, the
  /// low-speed correction of the transient contact model). 0 switches it off.
  double low_speed_damping_ratio = 1.0;      ///< zeta_low [-]
  double low_speed_damping_speed_mps = 1.0;  ///< v_low [m/s]
  TmeasyBore bore;                           ///< bore torque (tmeasy_bore.h)
};

/// The default 215/55 R18 passenger tire (public TMeasy data set): exactly the issue-3
/// table (F_zN = 3500 N; dFx0 100/190 kN, F_xM 3.9/7.4 kN, s_xM 0.11/0.15, F_xS = 0.9 F_xM,
/// s_xS = 3 s_xM; dFy0 80/152 kN, F_yM 3.65/6.935 kN, s_yM 0.16/0.21, F_yS = 0.9 F_yM,
/// s_yS = 3 s_yM; c_x 250 kN/m, d_x 2000 N s/m, c_y 175 kN/m, d_y 1750 N s/m, r_0 0.3469 m,
/// c_z 200 kN/m, v_N 0.5 m/s). Friction mu0 = 1, f_r = 0.01, trail as TmeasyTrail's defaults.
[[nodiscard]] constexpr TmeasyParams default_215_55_r18() noexcept {
  TmeasyParams p;
  p.nominal_load_n = 3500.0;
  p.longitudinal.at_nominal = {100e3, 3.9e3, 0.11, 0.9 * 3.9e3, 3.0 * 0.11};
  p.longitudinal.at_double = {190e3, 7.4e3, 0.15, 0.9 * 7.4e3, 3.0 * 0.15};
  p.lateral.at_nominal = {80e3, 3.65e3, 0.16, 0.9 * 3.65e3, 3.0 * 0.16};
  p.lateral.at_double = {152e3, 6.935e3, 0.21, 0.9 * 6.935e3, 3.0 * 0.21};
  return p;
}

/// Checks a parameter set for impossible values, for configuration loaders (which turn the
/// message into a ConfigError with file:line). Returns nullptr if valid, else a static message
/// naming the first bad field (e.g. "longitudinal.at_nominal: need 0 < s_M < s_S").
[[nodiscard]] const char* check_params(const TmeasyParams& params) noexcept;

}  // namespace rig::model::tire
