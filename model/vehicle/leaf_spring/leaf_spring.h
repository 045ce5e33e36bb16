#pragma once
/// @file
/// The quasi-static five-link leaf spring as a generalized force element (paper sec. 2.3,
/// Fig. 9). Given the axle seat's pose relative to the frame, the leaf's internal states (four
/// link directions and the shackle angle) are those of minimal potential energy with the rear
/// eye on the shackle; Newton finds them each step, warm-started from the last solution plus
/// its first-order change (the sensitivity of the last step), to a stated tolerance, in at most
/// params.max_iterations iterations, without allocation. The forces on the axle and their
/// partials for the implicit step follow from the equilibrium by the implicit function theorem:
///   d(internal)/d(seat) = -K_ii^-1 K_is,   dQ/d(seat) = -(K_ss - K_si K_ii^-1 K_is)
/// with K the Hessian of the Lagrangian bordered by the shackle closure (leaf_spring_energy.h).
///
/// Seat pose: (x_m, z_m, pitch_rad) of the axle centre relative to the frame, measured from its
/// position with the leaf free (unloaded); x forward, z up, pitch about +y (ISO 8855: > 0 turns
/// +x towards -z). The leaf spans the frame's vertical plane at the spring's lateral position.

#include <Eigen/Core>

#include "model/vehicle/leaf_spring/leaf_spring_energy.h"
#include "model/vehicle/leaf_spring/leaf_spring_params.h"

namespace rig::model::vehicle::leaf_spring {

using SeatPose = Eigen::Vector3d;                         ///< (x_m, z_m, pitch_rad)
using Internal = Eigen::Matrix<double, 7, 1>;             ///< 5 link coordinates, lambda (2)
using InternalSensitivity = Eigen::Matrix<double, 7, 3>;  ///< d(internal)/d(x, z, theta)

/// The leaf's mutable state: its last equilibrium and how that moved with the seat. Owned by
/// the axle block (copied with the vehicle state; a reset takes LeafSpring::settle()).
struct LeafState {
  /// (a_S1A, a_AE, a_S2B, a_BR [rad, from +x towards +z], shackle angle psi [rad, from the
  /// vertical, > 0 with the eye behind the pin], lambda [N]: minus the shackle's force on the leaf)
  Internal internal = Internal::Zero();
  InternalSensitivity d_internal_d_seat = InternalSensitivity::Zero();
  Eigen::Vector3d seat = Eigen::Vector3d::Zero();  ///< (x, z, theta = -pitch) of that solution

  [[nodiscard]] double shackle_angle_rad() const noexcept { return internal(4); }
};

/// What one evaluation gives the integrator.
struct LeafForces {
  /// On the axle at its centre: (F_x [N], F_z [N], M_y [N m]), generalized forces of the seat
  /// pose (F = -dV/d(seat)).
  Eigen::Vector3d on_axle = Eigen::Vector3d::Zero();
  /// d(on_axle)/d(seat pose): the leaf's tangent stiffness, negated (symmetric).
  Eigen::Matrix3d d_on_axle_d_seat = Eigen::Matrix3d::Zero();
  /// On the frame (x, z) [N]: at the front eye (acting at eye_m) and at the shackle pin.
  Eigen::Vector2d on_frame_at_eye_n = Eigen::Vector2d::Zero();
  Eigen::Vector2d on_frame_at_pin_n = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, 3> d_on_frame_at_eye_d_seat = Eigen::Matrix<double, 2, 3>::Zero();
  Eigen::Matrix<double, 2, 3> d_on_frame_at_pin_d_seat = Eigen::Matrix<double, 2, 3>::Zero();
  Eigen::Vector2d eye_m = Eigen::Vector2d::Zero();  ///< the front eye now (frame axes)
  double energy_j = 0;                              ///< the leaf's potential energy V
  int iterations = 0;                               ///< Newton iterations taken (0 if at rest)
  bool converged = false;                           ///< residuals within the tolerances
};

class LeafSpring {
 public:
  /// Throws std::invalid_argument on bad parameters (construction time only).
  explicit LeafSpring(const LeafSpringParams& params);

  /// The leaf at `seat_pose`, Newton warm-started from `state`, which it updates. RT-safe:
  /// no allocation, at most params().max_iterations iterations.
  LeafForces evaluate(const SeatPose& seat_pose, LeafState& state) const noexcept;

  /// The free (unloaded) leaf: the state at seat pose 0.
  [[nodiscard]] LeafState free_state() const noexcept;
  /// The converged state at `seat_pose`, reached from the free leaf in small steps (a reset or
  /// a start, not for the RT step). Returns false if it did not converge.
  bool settle(const SeatPose& seat_pose, LeafState& state) const noexcept;

  [[nodiscard]] const LeafSpringParams& params() const noexcept { return params_; }
  [[nodiscard]] const LeafGeometry& geometry() const noexcept { return geometry_; }

 private:
  LeafSpringParams params_;
  LeafGeometry geometry_;
};

}  // namespace rig::model::vehicle::leaf_spring
