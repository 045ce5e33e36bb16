#pragma once
/// @file
/// The rocker of a leaf balance (leaf_balance.h) from its two leaves: where its ends are, its
/// arms about the pivot, and each leaf's share of its seat load at its rocker end (the statics
/// that make the tandem's split: W_1 front_share a_1 = W_2 rear_share a_2). Header-only: the
/// vehicle loader (io/config) checks a file's rocker with it.

#include <stdexcept>
#include <string>

#include "model/vehicle/leaf_spring/leaf_spring_params.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

/// The rocker's geometry from the leaves: its ends are the front leaf's shackle pin and the rear
/// leaf's front eye (frame x from the CG, forward +).
struct LeafBalanceGeometry {
  double front_end_x_m = 0;  ///< the front leaf's shackle pin
  double rear_end_x_m = 0;   ///< the rear leaf's front eye
  double front_arm_m = 0;    ///< a_1 = front end - pivot (> 0)
  double rear_arm_m = 0;     ///< a_2 = pivot - rear end (> 0)
  /// Each leaf's share of its seat load at its rocker end: s_1/L_1 (front), (L_2 - s_2)/L_2.
  double front_share = 0;
  double rear_share = 0;
};

/// Throws std::invalid_argument if the two axles are not leaf-sprung or the rocker's ends are not
/// on opposite sides of the pivot.
[[nodiscard]] inline LeafBalanceGeometry leaf_balance_geometry(const AxleParams& front,
                                                               const AxleParams& rear,
                                                               double pivot_x_m) {
  if (!front.has_leaf_spring || !rear.has_leaf_spring)
    throw std::invalid_argument("a leaf balance carries two leaf-sprung rigid axles");
  const leaf_spring::LeafGeometry gf = leaf_spring::make_leaf_geometry(front.leaf_spring);
  const leaf_spring::LeafGeometry gr = leaf_spring::make_leaf_geometry(rear.leaf_spring);
  LeafBalanceGeometry g;
  g.front_end_x_m = front.position_x_m + gf.pin_frame_m.x();
  g.rear_end_x_m = rear.position_x_m + gr.eye_frame_m.x();
  g.front_arm_m = g.front_end_x_m - pivot_x_m;
  g.rear_arm_m = pivot_x_m - g.rear_end_x_m;
  if (!(g.front_arm_m > 0) || !(g.rear_arm_m > 0))
    throw std::invalid_argument(
        "the rocker's ends (the front leaf's shackle pin at x = " +
        std::to_string(g.front_end_x_m) +
        " m, the rear leaf's front eye at x = " + std::to_string(g.rear_end_x_m) +
        " m) are not on opposite sides of pivot_x_m = " + std::to_string(pivot_x_m) +
        " m (the pin must be ahead of it, the eye behind)");
  const leaf_spring::LeafSpringParams& f = front.leaf_spring;
  const leaf_spring::LeafSpringParams& r = rear.leaf_spring;
  g.front_share = f.seat_from_front_eye_m / f.eye_to_eye_m;
  g.rear_share = (r.eye_to_eye_m - r.seat_from_front_eye_m) / r.eye_to_eye_m;
  return g;
}

}  // namespace rig::model::vehicle
