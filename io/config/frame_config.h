#pragma once
/// @file
/// `[frame]` of a vehicle file (model/vehicle/frame): frame torsion between a front and a rear
/// part. Strict (ConfigError `file:line`), load time only. Read after the chassis, the axles and
/// the free bodies (the split is checked against them).
///
///   [frame]
///   torsion_stiffness_nmprad = 2.3e5   # the frame's torsional stiffness between the parts
///   torsion_damping_nmsprad = 2.0e3
///   split_x_m = -0.2                   # from the sprung CG, forward +; axles behind: rear part
///   rear_mass_kg = 1800                # the rear part's share of [chassis] mass_kg
///   rear_cg_x_m = -1.8                 # its CG (at the sprung CG's height)
///   rear_roll_inertia_kgm2 = 1300      # about its own CG, longitudinal; < inertia_xx_kgm2
///   axis_height_m = 0.95               # the torsion axis above the ground

#include "io/config/strict_table.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::io::config {

/// Reads [frame] of the vehicle table into p.frame (absent: not enabled, p.frame unchanged).
void read_frame(StrictTable& vehicle, model::vehicle::VehicleParams& p);

}  // namespace rig::io::config
