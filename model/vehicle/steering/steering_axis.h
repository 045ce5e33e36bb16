#pragma once
/// @file
/// The one room for the moment about a steered wheel's steering (kingpin) axis from its tire's
/// contact forces (sec. 2.2): the aligning torque (pneumatic trail n(s_y) of model/tire), the
/// caster trail's moment of F_y, and - with the steering-axis geometry - the jacking torque of
/// F_z, the scrub radius' moment of F_x, the drive torque's moment and the tire's bore torque.
/// Both steering models load their tie rods with it: the simple one by virtual work at the rack,
/// the enhanced one on the knuckle.
///
/// Geometry of the left wheel (the right one mirrored in y), wheel frame at the contact centre C
/// (x forward, y left = outboard, z up), zero camber: the axis meets the ground at
/// G = (n_c, -r_s, 0) (caster trail n_c ahead, scrub radius r_s inboard of C) with the direction
/// e = (-tan(sigma), -tan(delta), 1) / N, N = sqrt(1 + tan^2 sigma + tan^2 delta) (sigma the
/// caster angle, delta the kingpin inclination); the wheel centre W = C + (0, 0, R), its spin
/// axis a = e_y. Steering by psi turns the wheel (a rigid disc of radius R) about e; its lowest
/// point's height h(psi) = W_z(psi) - R sqrt(1 - a_z(psi)^2) (Rodrigues' rotation of W - G and a)
/// falls, so the load lifts the car by -h: V = -F_z h(psi) and the jacking torque
///   M_jack = -dV/dpsi = F_z dh/dpsi,
///   dh/dpsi = w_z'(psi) + R a_z a_z' / sqrt(1 - a_z^2),
///   w_z'(psi) = -w_z sin psi + (e x w)_z cos psi + e_z (e.w) sin psi  (w = W - G, a alike).
/// For small psi and angles: M_jack ~ -F_z (r_s + R tan delta) sin(delta) psi (both wheels restore;
/// with r_s = 0 the spindle offset R tan(delta) is the lever, Milliken & Milliken, Race Car
/// Vehicle Dynamics, 1995, ch. 19: the lift of kingpin inclination) plus the caster's
/// F_z (r_s sin sigma + n_c sin delta) terms, mirrored, which cancel between equal loads left and
/// right (Gillespie, Fundamentals of Vehicle Dynamics, 1992, ch. 8).
/// The contact forces act at C: M = e.((C - G) x (F_x, F_y, 0)) + e_z (M_z + M_B); the drive
/// torque T_s about the spin axis adds (e.a) T_s, which is the drive force T_s/R moved from C to
/// the hub (the spindle offset its lever), while brake forces stay at C (lever r_s).

#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

/// One wheel's contact forces and torques, in its wheel frame (x forward along the wheel, y left,
/// z up) [N, N m].
struct SteeringAxisLoads {
  double long_force_n = 0;     ///< F_x
  double lat_force_n = 0;      ///< F_y
  double load_n = 0;           ///< F_z (>= 0)
  double aligning_nm = 0;      ///< the tire's self-aligning torque about the contact normal
  double bore_nm = 0;          ///< the tire's bore torque about the contact normal
  double shaft_torque_nm = 0;  ///< drive torque on the wheel about its spin axis (+ forward)
  double wheel_radius_m = 0;   ///< R: the wheel centre's height over the contact
};

/// The moment about the steering axis, positive steering the wheel left (raising its steer
/// angle) [N m]. side: +1 left wheel, -1 right wheel (the geometry is mirrored).
[[nodiscard]] double steering_axis_moment_nm(const AxleParams& axle, const SteeringAxisLoads& loads,
                                             double steer_rad, int side) noexcept;

/// The jacking torque F_z dh/dpsi of the left wheel's geometry alone (see above) at steer psi
/// [N m]; steering_axis_moment_nm mirrors it for the right wheel. For the hand estimates of tests.
[[nodiscard]] double jacking_torque_left_nm(const AxleParams& axle, double load_n,
                                            double wheel_radius_m, double steer_rad) noexcept;

}  // namespace rig::model::vehicle
