#pragma once
/// @file
/// The five-link leaf spring's parameters (paper sec. 2.3, Fig. 9): the leaf's geometry in its
/// free (unloaded) state and its stiffnesses, and the constant link model derived from them.
/// Constant data, kept apart from the leaf's internal state (leaf_spring_state.h).
///
/// Axes: the frame's x forward, z up (ISO 8855), in the leaf's vertical plane; the origin is the
/// axle centre in the free state. The front eye is ahead of the axle, the shackle behind it,
/// hanging from its frame pin above the rear eye.

#include <Eigen/Core>

namespace rig::model::vehicle::leaf_spring {

/// The leaf as built ([axle.leaf_spring]). Each arm (seat edge to eye) is a uniform beam of the
/// given bending stiffness, shaped as a circular arc leaving the seat horizontally.
struct LeafSpringParams {
  double eye_to_eye_m = 1.40;           ///< free state, eye centre to eye centre (horizontal)
  double seat_from_front_eye_m = 0.60;  ///< axle seat centre behind the front eye (horizontal)
  double free_camber_m = 0.10;          ///< arc height: eyes above the seat, free state
  double seat_length_m = 0.10;          ///< clamped length (U-bolts): a rigid block on the axle
  double leaf_above_axle_m = 0.08;      ///< leaf at the seat above the axle centre (< 0: below)
  double front_bending_stiffness_nm2 = 4500.0;  ///< EI of the front arm
  double rear_bending_stiffness_nm2 = 4500.0;   ///< EI of the rear arm
  double shackle_length_m = 0.12;               ///< shackle pin to rear eye
  /// Shackle angle from the vertical in the free state, > 0 when the rear eye lies behind the pin.
  double shackle_angle_free_rad = -0.10;
  double eye_bushing_x_npm = 1.0e7;  ///< front eye bushing, fore-aft
  double eye_bushing_z_npm = 1.0e7;  ///< front eye bushing, vertical
  /// Newton stops when the internal moments are below this (and the shackle closes, below).
  double tolerance_nm = 1.0e-6;
  double closure_tolerance_m = 1.0e-10;
  int max_iterations = 4;  ///< Newton iterations per evaluation (issue 17: at most 4)
};

/// The link model derived from LeafSpringParams (make_leaf_geometry). Links, from the seat out:
/// front S1->A, A->E (eye); rear S2->B, B->R (rear eye); the seat S1-S2 is the fifth, rigid on
/// the axle. Each arm of arc length a is two links joined at a/3 from the eye, with rotational
/// springs 4 EI/a at the seat edge and 4 EI/(3a) at the joint: the two links then have exactly
/// the tip compliance of a cantilever of length a, [[a^3/3, a^2/2], [a^2/2, a]] / EI. The joint
/// sits on the arc, moved off it just enough that the two links are as long as the arc (so the
/// eye travels as the beam's does when the arm flattens: the shackle's swing).
struct LeafGeometry {
  Eigen::Vector2d seat_front_m;  ///< S1 in the axle's frame (seat front edge)
  Eigen::Vector2d seat_rear_m;   ///< S2 in the axle's frame
  double front_inner_m = 0;      ///< |S1 A|
  double front_outer_m = 0;      ///< |A E|
  double rear_inner_m = 0;       ///< |S2 B|
  double rear_outer_m = 0;       ///< |B R|
  /// Link directions in the free state (rad, from +x towards +z): S1->A, A->E, S2->B, B->R.
  Eigen::Vector4d free_angle_rad;
  /// Rotational springs at S1, A, S2, B [N m/rad].
  Eigen::Vector4d spring_nmprad;
  Eigen::Vector2d eye_frame_m;  ///< front eye bushing centre on the frame (E0)
  Eigen::Vector2d pin_frame_m;  ///< shackle pin on the frame (P)
  double shackle_length_m = 0;
  double shackle_angle_free_rad = 0;
  Eigen::Vector2d bushing_npm;  ///< (k_x, k_z)
  double front_arc_m = 0;       ///< arc length seat edge -> front eye
  double rear_arc_m = 0;        ///< arc length seat edge -> rear eye
};

/// Checks `p` (std::invalid_argument with the offending field otherwise) and derives the links.
LeafGeometry make_leaf_geometry(const LeafSpringParams& p);

}  // namespace rig::model::vehicle::leaf_spring
