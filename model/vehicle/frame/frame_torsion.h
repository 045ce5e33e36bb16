#pragma once
/// @file
/// Frame torsion (issue 17 item 5): a truck's ladder frame as a front and a rear part joined by
/// a torsional spring-damper about the longitudinal torsion axis. The front part is the chassis
/// (the framework's 6-DOF body); one more framework coordinate, the twist theta, is the rear
/// part's roll against it (+ as the body's roll: left side up). A point p0 of the rear part
/// (body axes from the sprung CG, at design) is at
///   p(theta) = a + Rx(theta)(p0 - a),  dp/dtheta = e_x x Rx(theta)(p0 - a)
/// with a on the torsion axis. The axles behind the split (their hub travels, unsprung masses,
/// wheel carriers and contacts) move with the rear part.
///
/// Where the twist sits in the arrowhead of eqs. (30-31): in the body's corner. Every axle couples
/// to the body through J_v already; a rear axle's unsprung masses also move with theta, so it
/// couples to the twist too - but to nothing else: kept in the corner (ArrowheadPartition's body
/// tail), every axle stays one leaf and the leaves stay uncoupled, so the factorization keeps its
/// cost (a 7 x 7 Schur complement instead of 6 x 6). A leaf of its own would couple the rear
/// leaves to each other through it. The twist is stored last in y, z (the hub travels keep their
/// indices); the factorization moves it next to the body.
///
/// Mass matrix (Jourdain): the chassis' mass and inertia stay those of the whole sprung mass
/// at design (the rear part's share included, as without [frame]); the twist adds the rear
/// part's terms m_r |g|^2 + I_r on theta, m_r g (v) and m_r c x g + I_r e_x (omega) beside it
/// (g = dc/dtheta at its CG c; I_r about its own CG, principal), and the rear wheels' point masses
/// with the theta column g_w = dr/dtheta in their J_v. The rear part's own gyroscopic terms are
/// left out (its roll rate is small beside the chassis').

#include <cmath>

#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/frame/frame_params.h"
#include "model/vehicle/sin_cos_memo.h"

namespace rig::model::vehicle {

/// The frame's geometry in body axes (from the sprung CG) and its spring-damper.
struct FrameGeometry {
  double split_x_m = 0;
  double axis_z_m = 0;  ///< the torsion axis' height above the sprung CG (body z)
  double rear_mass_kg = 0;
  Vec3 rear_cg_m = Vec3::Zero();  ///< at design
  double rear_roll_inertia_kgm2 = 0;
  double stiffness_nmprad = 0, damping_nmsprad = 0;
};

[[nodiscard]] inline FrameGeometry frame_geometry(const FrameParams& f,
                                                  double cg_height_m) noexcept {
  FrameGeometry g;
  g.split_x_m = f.split_x_m;
  g.axis_z_m = f.axis_height_m - cg_height_m;
  g.rear_mass_kg = f.rear_mass_kg;
  g.rear_cg_m = Vec3(f.rear_cg_x_m, 0, 0);
  g.rear_roll_inertia_kgm2 = f.rear_roll_inertia_kgm2;
  g.stiffness_nmprad = f.torsion_stiffness_nmprad;
  g.damping_nmsprad = f.torsion_damping_nmsprad;
  return g;
}

/// e_x x v
[[nodiscard]] inline Vec3 ex_cross(const Vec3& v) noexcept { return {0.0, -v.z(), v.y()}; }

/// Rx(theta) by its cosine and sine (the framework takes them once per twist, SinCosMemo), for
/// several vectors at one twist: Rx(theta) v.
struct TwistRotation {
  double c = 1.0, s = 0.0;
  explicit TwistRotation(const SinCos& theta) noexcept : c(theta.cos), s(theta.sin) {}
  [[nodiscard]] Vec3 operator*(const Vec3& v) const noexcept {
    return {v.x(), c * v.y() - s * v.z(), s * v.y() + c * v.z()};
  }
};
/// A point of the rear part at twist theta: where it is and d/dtheta.
struct TwistedPoint {
  Vec3 point_m;
  Vec3 d_dtwist_m;  ///< e_x x (p - a)
};
[[nodiscard]] inline TwistedPoint twisted_point(const FrameGeometry& g, const Vec3& p0,
                                                const TwistRotation& rx) noexcept {
  const Vec3 axis(p0.x(), 0.0, g.axis_z_m);
  const Vec3 from_axis = rx * (p0 - axis);
  return {axis + from_axis, ex_cross(from_axis)};
}

/// The torsion moment the frame transmits (+ resisting a + twist) [N m] and its partials.
[[nodiscard]] inline double torsion_moment_nm(const FrameGeometry& g, double theta,
                                              double theta_rate) noexcept {
  return g.stiffness_nmprad * theta + g.damping_nmsprad * theta_rate;
}

}  // namespace rig::model::vehicle
