#include "rig/road_sample.h"

#include <charconv>
#include <cmath>
#include <ostream>
#include <string_view>

#include "io/config/config_error.h"
#include "io/config/input_file.h"
#include "model/road/road.h"
#include "rig/config.h"

namespace rig {
namespace {

using io::config::ConfigError;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

double coordinate(std::string_view text, const std::string& where) {
  text = trim(text);
  if (text.starts_with('+')) text.remove_prefix(1);
  double v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
    throw ConfigError(where + ": '" + std::string(text) + "' is not a finite number");
  return v;
}

/// The road the configuration gives its tires (every unit of a combination has the same).
model::road::RoadParams road_of(const RigConfig& c) {
  if (c.model.vehicle) return c.model.vehicle->params.road;
  if (c.model.combination) return c.model.combination->units.front().road;
  throw ConfigError(c.file.string() +
                    ":1: [model] kind = \"quarter-car\" has no road surface to sample (give a "
                    "vehicle or a combination)");
}

void write_number(std::ostream& out, double v) {
  char text[32];
  const auto [ptr, ec] = std::to_chars(text, text + sizeof text, v);
  out.write(text, ptr - text);
}

}  // namespace

std::vector<RoadPoint> parse_road_points(const std::string& text, const std::string& name) {
  std::vector<RoadPoint> points;
  std::size_t pos = 0;
  int line = 0;
  while (pos < text.size() || line == 0) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view raw = trim(std::string_view(text).substr(pos, end - pos));
    pos = end + 1;
    const std::string where = name + ":" + std::to_string(++line);
    if (line == 1) {
      if (raw != "x,y" && raw != "\xEF\xBB\xBFx,y")
        throw ConfigError(where + ": expected the header x,y, not '" + std::string(raw) + "'");
      continue;
    }
    if (raw.empty()) continue;
    const auto comma = raw.find(',');
    if (comma == std::string_view::npos || raw.find(',', comma + 1) != std::string_view::npos)
      throw ConfigError(where + ": expected x,y (two numbers), not '" + std::string(raw) + "'");
    points.push_back(
        {coordinate(raw.substr(0, comma), where), coordinate(raw.substr(comma + 1), where)});
  }
  return points;
}

int road_sample_command(const std::string& config_file, const std::string& points_file,
                        std::ostream& out, std::ostream& err) {
  std::vector<RoadPoint> points;
  model::road::RoadParams params;
  try {
    params = road_of(load_config(config_file));
    points = parse_road_points(io::config::read_input_file(points_file), points_file);
  } catch (const ConfigError& e) {
    err << e.what() << "\n";
    return 2;
  }
  const model::road::Road road(params);
  model::road::SurfaceHint hint;  // one probe visiting the points in turn
  out << "x,y,z,nx,ny,nz,mu\n";
  for (const RoadPoint& p : points) {
    const model::road::RoadSample s = road.sample(p.x_m, p.y_m, p.y_m < 0, hint);
    for (const double v : {p.x_m, p.y_m, s.z_m, s.normal.x(), s.normal.y(), s.normal.z()}) {
      write_number(out, v);
      out << ',';
    }
    write_number(out, s.mu);
    out << '\n';
  }
  out.flush();
  if (!out) {
    err << "rig: error: output lost: writing the samples failed\n";
    return 3;
  }
  return 0;
}

}  // namespace rig
