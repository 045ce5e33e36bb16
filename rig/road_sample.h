#pragma once
/// @file
/// `rig road sample --config FILE --xy POINTS.csv`: the road a run configuration gives its tires,
/// sampled at points, so that it can be checked against another tool. POINTS.csv: the header
/// `x,y`, then one point per line (road frame, m). Output (stdout): the header
/// `x,y,z,nx,ny,nz,mu` and one row per point: the height, the upward unit normal and the tires'
/// mu scale there (model/road/road.h Road::sample; the split mu of the [model] road_* plane
/// applies to y < 0, the right-hand side of a vehicle driving along +x). Numbers are written in
/// their shortest round-trip form.

#include <iosfwd>
#include <string>
#include <vector>

namespace rig {

struct RoadPoint {
  double x_m = 0;
  double y_m = 0;
};

/// Parses POINTS.csv text (`name` for messages). Throws io::config::ConfigError
/// (`name:line: what is wrong`).
std::vector<RoadPoint> parse_road_points(const std::string& text, const std::string& name);

/// The command. Returns the exit code: 0; 2 (a bad configuration or POINTS.csv: `file:line: what
/// is wrong` on `err`, nothing on `out`); 3 if writing `out` failed.
int road_sample_command(const std::string& config_file, const std::string& points_file,
                        std::ostream& out, std::ostream& err);

}  // namespace rig
