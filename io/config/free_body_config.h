#pragma once
/// @file
/// `[[free_body]]` of a vehicle file (model/vehicle/free_body): generic free bodies on mounts.
/// Strict (ConfigError `file:line`), load time only.
///
///   [[free_body]]
///   name = "cab"                       # unique in the vehicle (outputs: body<i>_*)
///   kind = "cab" | "engine" | "seat"
///   mass_kg = 1200
///   inertia_kgm2 = [Ixx, Iyy, Izz]     # cab, engine: principal, about the CG
///   position_m = [x, y, z]             # CG at design, chassis axes from the chassis CG
///   through_margin_m = 0.01            # beyond the stop clearance: a vehicle fault
///   crankshaft_axis = [1, 0, 0]        # engine: body axes; the drive torque reacts about it
///   [[free_body.mount]]                # cab: 4, engine: 3
///   body_point_m = [x, y, z]           # body axes from the body's CG
///   chassis_point_m = [x, y, z]        # chassis axes from its CG (default: position + body point)
///   orientation_rad = [roll, pitch, yaw]  # the mount's axes in chassis axes (default 0)
///   stiffness_npm = [kx, ky, kz]
///   damping_nspm = [cx, cy, cz]
///   stop_clearance_m = [ex, ey, ez]
///   stop_stiffness_npm = [sx, sy, sz]
///   # seat (no mounts; along road z): stiffness_npm, damping_nspm, stop_clearance_m,
///   # stop_stiffness_npm as numbers
///
/// A body may also sit out: no [[free_body]] at all is a vehicle without free bodies.

#include <vector>

#include "io/config/strict_table.h"
#include "model/vehicle/free_body/free_body_params.h"

namespace rig::io::config {

/// Reads every [[free_body]] of the vehicle table (none: empty).
std::vector<model::vehicle::FreeBodyParams> read_free_bodies(StrictTable& vehicle);

}  // namespace rig::io::config
