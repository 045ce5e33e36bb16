#pragma once
/// @file
/// The kinematic functions of one wheel (eq. 29): wheel-centre position x, y (relative to the
/// design position, in the body frame) and the rotation angles alpha (about x: camber), beta
/// (about y), gamma (about z: toe/steer) of the wheel carrier as functions of hub travel z and
/// rack travel u, as five tables on one grid, or generated from a simple suspension geometry.

#include "model/kinematics/kinematic_table.h"

namespace rig::model::kinematics {

/// The five functions of eq. (29) with their partials, at one (z, u).
struct WheelPose {
  TableValue x_m;        ///< longitudinal wheel-centre position [m]
  TableValue y_m;        ///< lateral wheel-centre position [m]
  TableValue alpha_rad;  ///< rotation about x (camber change)
  TableValue beta_rad;   ///< rotation about y
  TableValue gamma_rad;  ///< rotation about z (toe + steer angle)
};

/// Five tables on one grid.
class WheelKinematics {
 public:
  WheelKinematics() = default;
  /// All five tables must share the same grid (checked; std::invalid_argument otherwise).
  WheelKinematics(KinematicTable x, KinematicTable y, KinematicTable alpha, KinematicTable beta,
                  KinematicTable gamma, Interpolation method);

  [[nodiscard]] const Grid2D& grid() const noexcept { return x_.grid(); }
  [[nodiscard]] Interpolation method() const noexcept { return method_; }
  /// Eq. (29) at hub travel z and rack travel u; allocation-free.
  [[nodiscard]] WheelPose evaluate(double hub_travel_m, double rack_travel_m) const noexcept;
  /// The five tables, to evaluate a subset with one set of weights (table_weights()).
  [[nodiscard]] const KinematicTable& x() const noexcept { return x_; }
  [[nodiscard]] const KinematicTable& y() const noexcept { return y_; }
  [[nodiscard]] const KinematicTable& alpha() const noexcept { return alpha_; }
  [[nodiscard]] const KinematicTable& beta() const noexcept { return beta_; }
  [[nodiscard]] const KinematicTable& gamma() const noexcept { return gamma_; }

 private:
  KinematicTable x_, y_, alpha_, beta_, gamma_;
  Interpolation method_ = Interpolation::kBicubic;
};

/// A simple suspension geometry (double-wishbone/McPherson-like approximation) used to generate
/// the tables when a configuration gives none. Linear + quadratic in hub travel z; the steer
/// angle from rack travel u through the steering arm: gamma_steer = asin(u / arm).
struct SuspensionGeometry {
  double x0_m = 0;              ///< design wheel-centre x (relative to the axle reference)
  double y0_m = 0.78;           ///< design wheel-centre y (half track; negative for a right wheel)
  double x_per_z = 0.0;         ///< dx/dz: wheel recession with travel (anti-dive geometry) [-]
  double track_per_z = 0.05;    ///< dy/dz: half-track change (scrub), positive = outwards [-]
  double track_per_z2 = -0.5;   ///< d2y/dz2 / 2: the arc of the swing arm [1/m]
  double camber0_rad = 0.0;     ///< static camber
  double camber_per_z = -0.35;  ///< dalpha/dz: camber gain [rad/m] (sign as for a left wheel)
  double beta_per_z = 0.0;      ///< dbeta/dz [rad/m]
  double toe0_rad = 0.0;        ///< static toe
  double bump_steer_per_z = 0.02;  ///< dgamma/dz: bump steer [rad/m]
  double steering_arm_m = 0.0;     ///< effective steering arm; 0 = not steered (u ignored)
  double steer_y_per_u = 0.0;      ///< dy/du: wheel-centre shift with steer (scrub radius) [-]
  /// Ackermann: cot(gamma_steer) = cot(asin(u / arm)) - k; k = ackermann t / (2 L) for the left
  /// wheel, -k for the right, so that cot(outer) - cot(inner) = ackermann t / L. 0: none [-].
  double ackermann_cot_shift = 0.0;
};

/// Fills five tables on the grid from the geometry (z in [z_min, z_max], u in [u_min, u_max]);
/// for an unsteered wheel pass a grid with u_count = 1. Allocates (construction time only).
[[nodiscard]] WheelKinematics generate_wheel_kinematics(const SuspensionGeometry& geometry,
                                                        const Grid2D& grid, Interpolation method);

/// The exact geometry functions (for tests and for checking table resolution).
[[nodiscard]] WheelPose evaluate_geometry(const SuspensionGeometry& geometry, double hub_travel_m,
                                          double rack_travel_m) noexcept;

}  // namespace rig::model::kinematics
