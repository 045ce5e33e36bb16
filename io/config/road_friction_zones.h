#pragma once
/// @file
/// `[[road.friction_zone]]` of a run configuration's [road] section ->
/// model/road/friction_zones.h. Each zone is a rectangle along a line or a polygon in x/y, with
/// the mu the tires take there (replacing the road's `friction`); later zones win where they
/// overlap.
///
///   [[road.friction_zone]]   # a rectangle along a line (bounds default to -inf / inf)
///   mu = 0.2
///   x_m = 0.0                # the line: origin and heading (default 0)
///   y_m = 0.0
///   heading_rad = 0.0
///   s_from_m = 30.0          # along it: mu-jump from s = 30 m on (s_to_m absent: inf)
///   v_to_m = 0.0             # across (> 0 left): only the right half (a mu-split)
///
///   [[road.friction_zone]]   # a polygon
///   mu = 0.5
///   points_m = [[10.0, -2.0], [14.0, -2.0], [14.0, 2.0], [10.0, 2.0]]
///
/// Errors are ConfigError `file:line: [road].friction_zone[i] key: what is wrong`.

#include <memory>

#include "io/config/strict_table.h"
#include "model/road/friction_zones.h"

namespace rig::io::config {

/// At most this many zones, and corners per polygon.
inline constexpr std::size_t kMaxFrictionZones = 1000;
inline constexpr std::size_t kMaxPolygonCorners = 1000;

/// The friction zones of `road` (the [road] table; its `friction_zone` key is read, if there is
/// one); nullptr when there are none. Goes to RoadParams::friction_field as it is.
std::shared_ptr<const model::road::FrictionZones> load_friction_zones(StrictTable& road);

}  // namespace rig::io::config
