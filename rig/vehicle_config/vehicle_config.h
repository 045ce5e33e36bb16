#pragma once
/// @file
/// Loads a vehicle file (config/vehicles/*.toml) into model::vehicle::VehicleParams, strictly:
/// every key has its unit in its name, unknown keys and impossible values are ConfigErrors
/// with `file:line`. Load time only.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/config/strict_table.h"
#include "model/combination/joint.h"
#include "model/report.h"
#include "model/stepped_model.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::vehicle_config {

/// Reads a whole vehicle file.
model::vehicle::VehicleParams load_vehicle_file(const std::filesystem::path& file);

/// Reads the road keys (road_grade, road_bank, road_friction, road_friction_right for split mu)
/// of a maneuver's [model] table; absent keys keep the defaults (flat, dry).
model::vehicle::RoadParams read_road(io::StrictTable& model_table);

/// The vehicle keys of a rig configuration's [model] table (kind = "vehicle"):
///   vehicle = "../vehicles/sedan.toml"   (relative to the configuration file)
///   road_grade, road_bank (tan of the slopes), road_friction (mu), initial_speed_mps.
struct VehicleModelSettings {
  model::vehicle::VehicleParams params;
  double initial_speed_mps = 0;
};

/// Reads the vehicle keys from [model] (the caller has read `kind`); leaves finish() to the caller.
VehicleModelSettings read_vehicle_model(io::StrictTable& model_table);

/// The model for the factory (library rig_vehicle_factory): a VehicleModel at step h, at rest
/// or at the initial speed.
std::unique_ptr<model::SteppedModel> make_vehicle_model(const VehicleModelSettings& settings,
                                                        double step_s);

/// The keys of [model] kind = "combination" (config/combinations/*.toml): the units front to
/// rear as [[model.unit]] tables (vehicle = "../vehicles/x.toml"), the joints between them as
/// [[model.joint]] tables (kind = "ball" | "fifth-wheel" | "tow-bar", leading_x_m, trailing_x_m,
/// height_m, for a tow bar length_m;
/// optional stiffness_npm, damping_nspm for the force-coupled baseline), `parallel`, the road
/// keys (applied to every unit) and initial_speed_mps.
struct CombinationModelSettings {
  std::string name;
  std::vector<model::vehicle::VehicleParams> units;
  std::vector<model::combination::JointParams> joints;
  bool parallel = false;
  double initial_speed_mps = 0;
};

/// Reads the combination keys from [model] (the caller has read `kind`).
CombinationModelSettings read_combination_model(io::StrictTable& model_table);

/// The model for the factory (library rig_vehicle_factory): a model::combination::Combination.
std::unique_ptr<model::SteppedModel> make_combination_model(
    const CombinationModelSettings& settings, double step_s);

}  // namespace rig::vehicle_config
