#pragma once
/// @file
/// The five-link leaf's potential energy and its shackle closure, with first and second
/// derivatives, in the coordinates
///   w = (x, z, theta | a_S1A, a_AE, a_S2B, a_BR, psi)
/// seat (axle centre displacement, leaf angle theta = -pitch) | internal (link directions from
/// +x towards +z, shackle angle). The rear chain S2-B-R must meet the shackle's end:
///   g(w) = S2 + l_SB e(a_S2B) + l_BR e(a_BR) - (P - l_sh (sin psi, cos psi)) = 0,
/// held by the multipliers lambda (the force the shackle puts on the leaf is -lambda). The
/// Lagrangian L = V + lambda . g is what Newton makes stationary (leaf_spring.cpp).

#include <Eigen/Core>

#include "model/vehicle/leaf_spring/leaf_spring_params.h"

namespace rig::model::vehicle::leaf_spring {

inline constexpr int kSeatCoords = 3;
inline constexpr int kLinkCoords = 5;
inline constexpr int kCoords = kSeatCoords + kLinkCoords;
using Coords = Eigen::Matrix<double, kCoords, 1>;
using CoordMatrix = Eigen::Matrix<double, kCoords, kCoords>;
using PointJacobian = Eigen::Matrix<double, 2, kCoords>;

/// Indices into w.
enum Coord : int { kX = 0, kZ, kTheta, kFrontInner, kFrontOuter, kRearInner, kRearOuter, kShackle };

struct LeafTerms {
  double energy_j = 0;              ///< V: four rotational springs + the eye bushing
  Coords gradient;                  ///< dL/dw
  CoordMatrix hessian;              ///< d2L/dw2
  Eigen::Vector2d closure_m;        ///< g
  PointJacobian closure_jacobian;   ///< dg/dw
  Eigen::Vector2d eye_m;            ///< front eye E
  PointJacobian eye_jacobian;       ///< dE/dw
  Eigen::Vector2d bushing_force_n;  ///< K_b (E - E0): the force on the frame at the eye
};

/// The free state: seat at rest, links at their free directions, shackle at its free angle.
Coords free_coords(const LeafGeometry& g) noexcept;

/// Fills `out` at (w, lambda). Allocation-free.
void leaf_terms(const LeafGeometry& g, const Coords& w, const Eigen::Vector2d& lambda,
                LeafTerms& out) noexcept;

}  // namespace rig::model::vehicle::leaf_spring
