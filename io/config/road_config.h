#pragma once
/// @file
/// The `[road]` section of a run configuration (and of a combination): the road every unit's
/// tires touch (model/road/DESIGN.md). Strict (ConfigError `file:line`), load time only.
///
///   [road]
///   kind = "plane" | "crg" | "opendrive" | "iso8608"    # default "plane"
///   friction = 1.0            # the base mu scale (as [model] road_friction: 1 = tire data)
///   # plane:   grade = 0.0, bank = 0.0   (tan of a real, tilted plane's slopes; gravity stays
///   #          straight down)
///   # crg:     file = "roads/x.crg"      (relative to this file)
///   # opendrive: file = "roads/x.xodr", road_id = "1" (default: the file's first road)
///   # iso8608: class = "A".."E", seed = 1, length_m = 1000, width_m = 4, spacing_m = 0.05,
///   #          fade_m = 5                (model/road/iso8608.h)
///   [road.placement]          # crg, iso8608, opendrive: model/road/placement.h (absent: where
///   u_m, v_m, x_m, y_m, z_m, heading_rad    # the file or the generator puts it; opendrive:
///                                           # u_m, v_m are s, t of the road)
///   [[road.obstacle]]         # on any kind: io/config/road_obstacles.h
///   [[road.friction_zone]]    # on any kind: io/config/road_friction_zones.h
///
/// A `[road]` section and any `[model] road_*` key together is an error.

#include <toml++/toml.h>

#include "io/config/strict_table.h"
#include "model/road/placement.h"
#include "model/road/road.h"

namespace rig::io::config {

/// Reads [road]; returns the road with its surface (nullptr: the flat plane z = 0) and friction
/// field. Leaves finish() to itself (unknown keys are errors).
model::road::RoadParams read_road_section(StrictTable road);

/// [road.placement] (given = false if absent).
model::road::Placement read_placement(StrictTable& road);

/// Throws if `model` (the [model] table) has a road_* key: with a [road] section the road is
/// given once, there.
void check_no_model_road_keys(const StrictTable& model);

}  // namespace rig::io::config
