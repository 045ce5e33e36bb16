#pragma once
/// @file
/// `[[drivetrain.differential]]` of a vehicle file (model/vehicle/differential/README.md):
/// each differential across an axle (`axle = N`) or between axles (`between = [A, B]`, each
/// side an axle number or a list of them), its kind and locking; the set checked to form one
/// tree over the driven axles. Load time only.

#include <vector>

#include "io/config/strict_table.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::io::config {

/// Reads `differential` of the [drivetrain] table `t` (none: an empty list, today's open
/// differentials). Throws ConfigError (file:line) on anything that does not make one tree.
std::vector<model::vehicle::differential::DifferentialParams> read_differentials(
    StrictTable& t, const std::vector<model::vehicle::AxleParams>& axles);

}  // namespace rig::io::config
