#pragma once
/// @file
/// Loads a vehicle file (config/vehicles/*.toml) into model::vehicle::VehicleParams, strictly:
/// every key has its unit in its name, unknown keys and impossible values are ConfigErrors
/// with `file:line`. Load time only.

#include <filesystem>

#include <vector>

#include "io/config/overrides.h"
#include "io/config/strict_table.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::io::config {

/// Reads a whole vehicle file, with `patch` (--set KEY=VALUE of this file, io/config/overrides.h)
/// put into it first.
model::vehicle::VehicleParams load_vehicle_file(const std::filesystem::path& file,
                                                const std::vector<Override>& patch = {});

/// Reads the road keys (road_grade, road_bank, road_friction, road_friction_right for split mu)
/// of a maneuver's [model] table; absent keys keep the defaults (flat, dry).
model::road::RoadParams read_road(StrictTable& model_table);

/// The vehicle keys of a rig configuration's [model] table (kind = "vehicle"):
///   vehicle = "../vehicles/sedan.toml"   (relative to the configuration file)
///   road_grade, road_bank (tan of the slopes), road_friction, initial_speed_mps,
///   slip_mask_speed_mps (VehicleParams).
/// road_friction scales every tire's F_M and F_S by road_friction / reference_friction (1): so 1
/// means "the tire data as given", not a peak friction of 1 (the sedan's p205 peaks at F_M / F_z
/// = 1.07-1.27 over 1.75-7 kN: lateral 1.20, longitudinal 1.26 at its nominal 3.5 kN).
struct VehicleModelSettings {
  std::filesystem::path file;  ///< the vehicle file (named in fault messages)
  model::vehicle::VehicleParams params;
  double initial_speed_mps = 0;
};

/// Reads the vehicle keys from [model] (the caller has read `kind`); leaves finish() to the caller.
/// `patch`: the --set overrides of the vehicle file.
VehicleModelSettings read_vehicle_model(StrictTable& model_table,
                                        const std::vector<Override>& patch = {});

}  // namespace rig::io::config
