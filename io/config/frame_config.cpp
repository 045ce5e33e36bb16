#include "io/config/frame_config.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rig::io::config {
namespace {

using model::vehicle::VehicleParams;

/// The split must have an axle on each side: strictly inside the wheelbase.
void check_split(StrictTable& t, const VehicleParams& p, double split_x_m) {
  double front = -1e9, rear = 1e9;
  for (const auto& a : p.axles) {
    front = std::max(front, a.position_x_m);
    rear = std::min(rear, a.position_x_m);
  }
  if (!(split_x_m < front && split_x_m > rear))
    throw t.error("split_x_m", "the split must lie inside the wheelbase, between the front axle (" +
                                   std::to_string(front) + " m) and the rear axle (" +
                                   std::to_string(rear) + " m), away from every axle");
  for (const auto& a : p.axles) {
    if (std::abs(a.position_x_m - split_x_m) < 0.05)
      throw t.error("split_x_m", "the split must lie at least 0.05 m from every axle (an axle at " +
                                     std::to_string(a.position_x_m) + " m)");
  }
  for (const auto& b : p.free_bodies) {
    for (const auto& m : b.mounts) {
      if (m.chassis_point_m[0] < split_x_m)
        throw t.error("split_x_m", "free body '" + b.name +
                                       "' has a mount behind the split: mounts on the frame's "
                                       "rear part are not supported yet");
    }
  }
}

}  // namespace

void read_frame(StrictTable& vehicle, VehicleParams& p) {
  auto table = vehicle.optional_table("frame");
  if (!table) return;
  StrictTable& t = *table;
  model::vehicle::FrameParams& f = p.frame;
  f.enabled = true;
  f.torsion_stiffness_nmprad = t.number_in("torsion_stiffness_nmprad", 1e3, 1e9);
  f.torsion_damping_nmsprad = t.number_in("torsion_damping_nmsprad", 0, 1e7);
  f.split_x_m = t.number_in("split_x_m", -20, 20);
  check_split(t, p, f.split_x_m);
  f.rear_mass_kg = t.number_in("rear_mass_kg", 1, 0.95 * p.chassis.mass_kg);
  double rear = 1e9;
  for (const auto& a : p.axles) rear = std::min(rear, a.position_x_m);
  f.rear_cg_x_m = t.number_in("rear_cg_x_m", rear - 3, f.split_x_m);
  f.rear_roll_inertia_kgm2 =
      t.number_in("rear_roll_inertia_kgm2", 1, 0.95 * p.chassis.inertia_kgm2[0]);
  f.axis_height_m = t.number_in("axis_height_m", 0, 3);
  t.finish();
}

}  // namespace rig::io::config
