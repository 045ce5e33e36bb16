#pragma once
/// @file
/// Loads a vehicle file (config/vehicles/*.toml) into model::vehicle::VehicleParams, strictly:
/// every key has its unit in its name, unknown keys and impossible values are ConfigErrors
/// with `file:line`. Load time only.

#include <filesystem>

#include "io/config/strict_table.h"
#include "model/report.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::vehicle_config {

/// Reads a whole vehicle file.
model::vehicle::VehicleParams load_vehicle_file(const std::filesystem::path& file);

/// Reads the road keys (road_grade, road_bank, road_friction) of a maneuver's [model] table;
/// absent keys keep the defaults (flat, dry).
model::vehicle::RoadParams read_road(io::StrictTable& model_table);

}  // namespace rig::vehicle_config
