#pragma once
/// @file
/// ISO 3888-1 double lane change: which lanes the vehicle kept and which cones it hit, from its
/// recorded pose (CG x, y and yaw in the road frame) and its outline, a rectangle of
/// `length_m` x `width_m` whose front is `cg_to_front_m` ahead of the CG.
///
/// The track (ISO 3888-1, vehicle width b): lane 1 from `start_x_m` over 15 m, width
/// 1.1 b + 0.25 m; lane 3 from 45 to 70 m, width 1.2 b + 0.25 m, its centre `lane_offset_m` to
/// the left (+y); lane 5 from 95 to 110 m, width 1.3 b + 0.25 m; the lane changes between them
/// are not bounded. The lanes are centred on the path driver's ISO 3888-1 centreline
/// (rig/driver/path_driver.h), 3.5 m apart. A lane is kept when some of the outline was in
/// the lane's x range and no part of it there crossed one of the lane's two limits; none is
/// kept unless the whole outline got past lane 5. The limits are tangent to the cones' bases
/// (ISO 3888-1), so a cone of base radius `cone_radius_m` stands `cone_radius_m` outside a
/// limit, at the lane's two ends and every `cone_spacing_m` between them, on both sides; it is
/// hit when the outline comes within its base radius of its centre.

#include <span>
#include <vector>

namespace rig::kpi {

struct Iso3888Params {
  double start_x_m = 0.0;  ///< lane 1's start on the road's x axis
  double lane_offset_m = 3.5;
  double vehicle_width_m = 1.8;  ///< b: the lanes' widths and the outline's
  double vehicle_length_m = 4.7;
  double cg_to_front_m = 2.1;
  double cone_spacing_m = 5.0;
  double cone_radius_m = 0.15;
};

struct Iso3888Lane {
  double from_x_m, to_x_m, centre_y_m, width_m;
};

/// Lanes 1, 3 and 5 of the track.
std::vector<Iso3888Lane> iso3888_lanes(const Iso3888Params& p);

/// How many of the three lanes were kept (0..3).
double lanes_kept(const Iso3888Params& p, std::span<const double> x_m, std::span<const double> y_m,
                  std::span<const double> yaw_rad);

/// How many cones were hit (each counts once).
double cones_hit(const Iso3888Params& p, std::span<const double> x_m, std::span<const double> y_m,
                 std::span<const double> yaw_rad);

}  // namespace rig::kpi
