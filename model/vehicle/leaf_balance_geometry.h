#pragma once
/// @file
/// The rocker of a leaf balance (leaf_balance.h) from its two leaves: where its ends are, its
/// arms about the pivot, and each leaf's share of its seat load at its rocker end (the statics
/// that make the tandem's split: W_1 front_share a_1 = W_2 rear_share a_2).

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
[[nodiscard]] LeafBalanceGeometry leaf_balance_geometry(const AxleParams& front,
                                                        const AxleParams& rear, double pivot_x_m);

}  // namespace rig::model::vehicle
