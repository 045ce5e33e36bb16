#pragma once
/// @file
/// The Transit-like van's rear leaf as a constant (the same numbers as van_leaf.toml, which the
/// FE reference reads; the test checks they agree with the reference file's echo).

#include "model/vehicle/leaf_spring/leaf_spring_params.h"

namespace rig::test {

inline model::vehicle::leaf_spring::LeafSpringParams van_rear_leaf() {
  model::vehicle::leaf_spring::LeafSpringParams p;
  p.eye_to_eye_m = 1.40;
  p.seat_from_front_eye_m = 0.60;
  p.free_camber_m = 0.10;
  p.seat_length_m = 0.10;
  p.leaf_above_axle_m = 0.08;
  p.front_bending_stiffness_nm2 = 4500.0;
  p.rear_bending_stiffness_nm2 = 4500.0;
  p.shackle_length_m = 0.12;
  p.shackle_angle_free_rad = -0.10;
  p.eye_bushing_x_npm = 1.0e7;
  p.eye_bushing_z_npm = 1.0e7;
  return p;
}

inline constexpr double kVanLeafStaticLoadN = 7500.0;  ///< per spring, laden
inline constexpr double kVanSpringTrackM = 1.10;

}  // namespace rig::test
