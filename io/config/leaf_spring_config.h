#pragma once
/// @file
/// [axle.leaf_spring]: the five-link leaf spring of a rigid axle (model/vehicle/leaf_spring).
/// Strict: every key named, units in the names, each value range-checked, errors `file:line`.
/// The axle loader calls read_axle_leaf_spring on each [[axle]] table; a file
/// holding just that table (rig check --kind leaf-spring, the tests) goes through
/// load_leaf_spring_file.

#include <filesystem>
#include <optional>

#include "io/config/strict_table.h"
#include "model/vehicle/leaf_spring/leaf_spring_params.h"

namespace rig::io::config {

struct LeafSpringConfig {
  model::vehicle::leaf_spring::LeafSpringParams params;  ///< one leaf (both sides alike)
  double spring_track_m = 0;  ///< lateral distance of the axle's two leaves
};

/// Reads and checks the [axle.leaf_spring] table; calls leaf.finish() (unknown keys are errors).
LeafSpringConfig read_leaf_spring(StrictTable& leaf);

/// The axle loader's call: the `leaf_spring` sub-table of one [[axle]] if it has one (messages
/// name it [axle.leaf_spring]); std::nullopt if not. Marks the key as read.
std::optional<LeafSpringConfig> read_axle_leaf_spring(StrictTable& axle);

/// A TOML file with one [axle.leaf_spring] table (and nothing else).
LeafSpringConfig load_leaf_spring_file(const std::filesystem::path& file);

}  // namespace rig::io::config
