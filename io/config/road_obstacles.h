#pragma once
/// @file
/// `[[road.obstacle]]` of a run configuration's [road] section -> model/road/obstacles.h.
///
///   [[road.obstacle]]
///   kind = "cleat"        # cleat | pothole | ramp | bump | sine (shapes: model/road/obstacles.h)
///   x_m = 0.0             # the line it lies along: origin and heading (default 0)
///   y_m = 0.0
///   heading_rad = 0.0
///   s_m = 20.0            # where it starts along the line (default 0)
///   length_m = 0.02       # along the line, > 0
///   width_m = 3.0         # across, > 0; absent (or inf): across the whole road
///   height_m = 0.02       # != 0, |height_m| <= 1 m; cleat > 0, pothole < 0 (its depth)
///   rise_m = 0.5          # ramp only: up-slope length (default length_m), then flat,
///   fall_m = 0.0          #   then the down-slope (default 0: a vertical wall)
///   wavelength_m = 2.0    # sine only (required): length_m a whole number of them
///
/// Errors are ConfigError `file:line: [road].obstacle[i] key: what is wrong`.

#include <memory>

#include "io/config/strict_table.h"
#include "model/road/obstacles.h"

namespace rig::io::config {

/// At most this many obstacles (each query sums over all of them).
inline constexpr std::size_t kMaxObstacles = 1000;

/// The obstacles of `road` (the [road] table; its `obstacle` key is read, if there is one);
/// nullptr when there are none. Lay them on the base surface with
/// model::road::with_overlay(base, load_obstacles(road)).
std::shared_ptr<const model::road::Obstacles> load_obstacles(StrictTable& road);

}  // namespace rig::io::config
