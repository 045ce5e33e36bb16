#include "model/vehicle/leaf_balance_geometry.h"

#include <stdexcept>
#include <string>

#include "model/vehicle/leaf_spring/leaf_spring_params.h"

namespace rig::model::vehicle {

namespace ls = leaf_spring;

LeafBalanceGeometry leaf_balance_geometry(const AxleParams& front, const AxleParams& rear,
                                          double pivot_x_m) {
  if (!front.has_leaf_spring || !rear.has_leaf_spring)
    throw std::invalid_argument("a leaf balance carries two leaf-sprung rigid axles");
  const ls::LeafGeometry gf = ls::make_leaf_geometry(front.leaf_spring);
  const ls::LeafGeometry gr = ls::make_leaf_geometry(rear.leaf_spring);
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
  const ls::LeafSpringParams& f = front.leaf_spring;
  const ls::LeafSpringParams& r = rear.leaf_spring;
  g.front_share = f.seat_from_front_eye_m / f.eye_to_eye_m;
  g.rear_share = (r.eye_to_eye_m - r.seat_from_front_eye_m) / r.eye_to_eye_m;
  return g;
}

}  // namespace rig::model::vehicle
