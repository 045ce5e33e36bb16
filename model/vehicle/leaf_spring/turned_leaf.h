#pragma once
/// @file
/// A leaf whose one frame point (eye or shackle pin) is carried by a rocker (leaf balance,
/// model/vehicle/leaf_balance.h): the leaf with that end lifted by dz and the other end fixed is,
/// to first order, the same leaf turned as a whole by alpha = dz / (x_moving - x_fixed) about
/// its fixed frame point F. So the leaf is evaluated unchanged at the seat pose seen from the
/// turned leaf, seat' = (F + R(-alpha)(c - F), pitch + alpha) (c the axle centre, R turning +x
/// towards +z), and its generalized forces are carried back by virtual work:
///   Q = G^T Q',  G = d seat' / d(x, z, pitch, alpha),
///   K = G^T K' G + sum_j Q'_j d2 seat'_j / d(.)^2   (the second term: the turn's geometry).
/// What the first order drops: the moving end's travel along the leaf's span (dz^2 / (2 L),
/// a few um; the shackle takes it). But the turn also moves the moving end sideways by
/// -alpha (z_moving - z_fixed) (the pin sits a shackle length above the eyes' line), so Q_alpha
/// (the moment about F of the seat's load) holds the leaf's fore-aft end force on that lever
/// too; a rocker whose ends move vertically takes the moving end's force instead
/// (end_force_n: the leaf's force on the frame there, frame axes, with its partials).

#include <Eigen/Core>

#include "model/vehicle/leaf_spring/leaf_spring.h"

namespace rig::model::vehicle::leaf_spring {

/// Which frame point rides on the rocker (the other is fixed, the turn's centre).
enum class MovingEnd { kPin, kEye };

struct TurnedLeafForces {
  LeafForces leaf;              ///< the leaf's own evaluation (its axes: turned by alpha)
  Eigen::Vector4d q;            ///< on (x, z, pitch, alpha) [N, N, N m, N m]
  Eigen::Matrix4d stiffness;    ///< d q / d(x, z, pitch, alpha)
  Eigen::Vector2d end_force_n;  ///< on the frame at the moving end (frame axes) [N]
  Eigen::Matrix<double, 2, 4> d_end_force;  ///< d end_force_n / d(x, z, pitch, alpha)
};

/// The leaf at `seat_pose` (frame axes), turned by `alpha_rad` about its fixed frame point (the
/// eye if the pin moves, else the pin). Warm-started from `state` as LeafSpring::evaluate.
/// No allocation.
TurnedLeafForces evaluate_turned(const LeafSpring& leaf, const SeatPose& seat_pose,
                                 double alpha_rad, MovingEnd moving, LeafState& state) noexcept;

}  // namespace rig::model::vehicle::leaf_spring
