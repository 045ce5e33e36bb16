#include "io/config/road_friction_zones.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rig::io::config {

namespace {

using model::road::FrictionZone;

constexpr double kFar_m = 1e7;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxMu = 10.0;

void read_polygon(StrictTable& t, FrictionZone& z) {
  for (const char* key :
       {"x_m", "y_m", "heading_rad", "s_from_m", "s_to_m", "v_from_m", "v_to_m"}) {
    if (t.has(key))
      throw t.error(key, "a zone is a polygon (points_m) or a rectangle along a line, not both");
  }
  z.is_polygon = true;
  const auto rows = t.number_rows("points_m", 2, kMaxPolygonCorners);
  if (rows.size() < 3)
    throw t.error("points_m", std::to_string(rows.size()) + " corners: a polygon needs 3 or more");
  for (const auto& row : rows) {
    if (!(std::abs(row[0]) <= kFar_m && std::abs(row[1]) <= kFar_m))
      throw t.error("points_m", "a corner is not finite or beyond 1e7 m");
    z.polygon.x_m.push_back(row[0]);
    z.polygon.y_m.push_back(row[1]);
  }
}

/// [from, to] along or across the line; absent bounds are infinite.
void read_range(StrictTable& t, const char* from_key, const char* to_key, double& from,
                double& to) {
  from = t.number_in(from_key, -kInf, -kInf, kInf);
  to = t.number_in(to_key, kInf, -kInf, kInf);
  if (!(from < to)) {
    throw t.error(t.has(to_key) ? to_key : from_key,
                  std::string(from_key) + " must be below " + to_key + " (an empty zone)");
  }
}

void read_rectangle(StrictTable& t, FrictionZone& z) {
  auto& r = z.rectangle;
  r.x_m = t.number_in("x_m", 0.0, -kFar_m, kFar_m);
  r.y_m = t.number_in("y_m", 0.0, -kFar_m, kFar_m);
  r.heading_rad = t.number_in("heading_rad", 0.0, -100.0, 100.0);
  read_range(t, "s_from_m", "s_to_m", r.s_from_m, r.s_to_m);
  read_range(t, "v_from_m", "v_to_m", r.v_from_m, r.v_to_m);
}

FrictionZone read_zone(StrictTable& t) {
  FrictionZone z;
  z.mu = t.number_in("mu", 0.0, kMaxMu);
  if (t.has("points_m")) {
    read_polygon(t, z);
  } else {
    read_rectangle(t, z);
  }
  t.finish();
  return z;
}

}  // namespace

std::shared_ptr<const model::road::FrictionZones> load_friction_zones(StrictTable& road) {
  if (!road.has("friction_zone")) return nullptr;
  std::vector<FrictionZone> zones;
  for (StrictTable& t : road.tables("friction_zone", kMaxFrictionZones))
    zones.push_back(read_zone(t));
  if (zones.empty()) return nullptr;
  try {
    return std::make_shared<const model::road::FrictionZones>(std::move(zones));
  } catch (const std::invalid_argument& e) {
    throw road.error("friction_zone", e.what());  // the checks above come first
  }
}

}  // namespace rig::io::config
