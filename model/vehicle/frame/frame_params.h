#pragma once
/// @file
/// `[frame]` of a vehicle file: the frame as a front and a rear part joined by a torsional
/// spring-damper about the longitudinal axis (frame_torsion.h). Plain data, SI units; filled by
/// io/config. Not enabled (no `[frame]`): the chassis is one rigid body, as before.

namespace rig::model::vehicle {

struct FrameParams {
  bool enabled = false;
  double torsion_stiffness_nmprad = 0;  ///< the frame's torsional stiffness between the parts
  double torsion_damping_nmsprad = 0;   ///< its damping
  /// Where the frame splits (body x from the sprung CG, forward +): the axles behind it (and
  /// their unsprung masses) move with the rear part.
  double split_x_m = 0;
  /// The rear part's share of the chassis' sprung mass, its CG's x (its CG at the sprung CG's
  /// height, on the centre line) and its roll inertia about its own CG (longitudinal axis).
  double rear_mass_kg = 0;
  double rear_cg_x_m = 0;
  double rear_roll_inertia_kgm2 = 0;
  /// The torsion axis (body x direction) above the ground at design height.
  double axis_height_m = 0;
};

}  // namespace rig::model::vehicle
