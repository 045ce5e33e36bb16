#pragma once
/// @file
/// The keys of [model] kind = "combination" (config/combinations/*.toml): the units front to
/// rear as [[model.unit]] tables (vehicle = "../vehicles/x.toml"), the joints between them as
/// [[model.joint]] tables (kind = "ball" | "fifth-wheel" | "tow-bar", leading_x_m, trailing_x_m,
/// height_m, for a tow bar length_m; optional stiffness_npm, damping_nspm for the force-coupled
/// baseline), `parallel`, the road keys (applied to every unit) and initial_speed_mps. Strict
/// (ConfigError with `file:line`), load time only.

#include <filesystem>
#include <string>
#include <vector>

#include "io/config/overrides.h"
#include "io/config/strict_table.h"
#include "model/combination/joint.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::io::config {

struct CombinationModelSettings {
  std::string name;
  std::vector<model::vehicle::VehicleParams> units;
  std::vector<std::filesystem::path> unit_files;  ///< each unit's vehicle file, in order
  std::vector<model::combination::JointParams> joints;
  bool parallel = false;
  double initial_speed_mps = 0;
};

/// Reads the combination keys from [model] (the caller has read `kind`); `overrides`: --set of
/// the units' vehicle files (unit<k>.KEY=VALUE), none if null.
CombinationModelSettings read_combination_model(StrictTable& model_table,
                                                const Overrides* overrides = nullptr);

}  // namespace rig::io::config
