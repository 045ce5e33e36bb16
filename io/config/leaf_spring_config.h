#pragma once
/// @file
/// [axle.leaf_spring]: the five-link leaf spring of a rigid axle (model/vehicle/leaf_spring).
/// Strict: every key named, units in the names, each value range-checked, errors `file:line`.
/// The axle loader hands over the axle's `leaf_spring` sub-table (read_leaf_spring); a file
/// holding just that table (rig check --kind leaf-spring, the tests) goes through
/// load_leaf_spring_file.

#include <filesystem>

#include "io/config/strict_table.h"
#include "model/vehicle/leaf_spring/leaf_spring_params.h"

namespace rig::io::config {

struct LeafSpringConfig {
  model::vehicle::leaf_spring::LeafSpringParams params;  ///< one leaf (both sides alike)
  double spring_track_m = 0;  ///< lateral distance of the axle's two leaves
};

/// Reads and checks the [axle.leaf_spring] table; calls leaf.finish() (unknown keys are errors).
LeafSpringConfig read_leaf_spring(StrictTable& leaf);

/// A TOML file with one [axle.leaf_spring] table (and nothing else).
LeafSpringConfig load_leaf_spring_file(const std::filesystem::path& file);

}  // namespace rig::io::config
