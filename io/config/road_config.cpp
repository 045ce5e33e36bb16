#include "io/config/road_config.h"

#include <cmath>
#include <memory>
#include <string>

#include "io/config/crg_file.h"
#include "io/config/opendrive_file.h"
#include "io/config/road_friction_zones.h"
#include "io/config/road_obstacles.h"
#include "model/road/crg_surface.h"
#include "model/road/iso8608.h"
#include "model/road/layered_surface.h"
#include "model/road/plane_surface.h"

namespace rig::io::config {
namespace {

using model::road::Surface;

/// The ISO 8608 grid's bounds: its generation factors a coherence matrix of every long section
/// pair per frequency (model/road/iso8608.h), so the long sections are few.
constexpr int kMaxIsoLongSections = 201;
constexpr double kMaxIsoCells = 2e7;

// ---- OpenDRIVE, obstacles, friction zones (io/config/opendrive_file.h, road_obstacles.h,
// road_friction_zones.h)

std::shared_ptr<const Surface> opendrive_surface(StrictTable& road) {
  const OpenDriveFile file = load_opendrive_file(road.existing_path("file"));
  const std::string road_id = road.string("road_id", "");
  const model::road::Placement placement = read_placement(road);
  if (!road_id.empty()) {
    try {
      (void)select_road(file, road_id);
    } catch (const ConfigError& e) {
      throw road.error("road_id", e.what());  // where it was asked for, and the file's roads
    }
  }
  return make_opendrive_surface(file, road_id, placement);
}

// ---- the surfaces of this branch

std::shared_ptr<const Surface> plane_surface(StrictTable& road) {
  const double grade = road.number_in("grade", 0.0, -1.0, 1.0);
  const double bank = road.number_in("bank", 0.0, -1.0, 1.0);
  if (road.has("placement"))
    throw road.error("placement", "a plane has no placement (it is everywhere)");
  if (grade == 0 && bank == 0) return nullptr;  // the flat plane of today, bit-identical
  return std::make_shared<model::road::PlaneSurface>(grade, bank);
}

std::shared_ptr<const Surface> crg_surface(StrictTable& road) {
  const model::road::CrgData data = load_crg_file(road.existing_path("file"));
  return std::make_shared<model::road::CrgSurface>(data, read_placement(road));
}

model::road::Iso8608Params iso8608_params(StrictTable& road) {
  model::road::Iso8608Params p;
  const std::string road_class = road.string("class");
  if (road_class.size() != 1 || road_class[0] < 'A' || road_class[0] > 'E')
    throw road.error("class", "\"" + road_class + "\": ISO 8608 classes are \"A\" to \"E\"");
  p.road_class = road_class[0];
  p.seed = static_cast<std::uint64_t>(road.integer_in("seed", 1, 0, 1LL << 62));
  p.length_m = road.number_in("length_m", p.length_m, 10, 20000);
  p.width_m = road.number_in("width_m", p.width_m, 0.5, 20);
  p.spacing_m = road.number_in("spacing_m", p.spacing_m, 0.01, 1);
  p.fade_m = road.number_in("fade_m", p.fade_m, 0, p.length_m / 2);
  const double long_sections = std::round(p.width_m / p.spacing_m) + 1;
  const double cells = long_sections * (std::round(p.length_m / p.spacing_m) + 1);
  if (long_sections > kMaxIsoLongSections || cells > kMaxIsoCells)
    throw road.error("spacing_m",
                     "a grid of " + std::to_string(static_cast<long long>(long_sections)) +
                         " long sections and " + std::to_string(static_cast<long long>(cells)) +
                         " cells; at most " + std::to_string(kMaxIsoLongSections) + " and " +
                         std::to_string(static_cast<long long>(kMaxIsoCells)));
  return p;
}

std::shared_ptr<const Surface> iso8608_surface(StrictTable& road) {
  const model::road::CrgData data = model::road::generate_iso8608(iso8608_params(road));
  return std::make_shared<model::road::CrgSurface>(data, read_placement(road));
}

}  // namespace

model::road::Placement read_placement(StrictTable& road) {
  model::road::Placement p;
  auto t = road.optional_table("placement");
  if (!t) return p;
  p.given = true;
  if (t->has("u_m")) p.u_m = t->number_in("u_m", -1e8, 1e8);
  p.v_m = t->number_in("v_m", 0.0, -1e4, 1e4);
  p.x_m = t->number_in("x_m", 0.0, -1e8, 1e8);
  p.y_m = t->number_in("y_m", 0.0, -1e8, 1e8);
  p.z_m = t->number_in("z_m", 0.0, -1e5, 1e5);
  p.heading_rad = t->number_in("heading_rad", 0.0, -100, 100);
  t->finish();
  return p;
}

model::road::RoadParams read_road_section(StrictTable road) {
  model::road::RoadParams r;
  const std::string kind = road.choice("kind", "plane", {"plane", "crg", "opendrive", "iso8608"});
  r.friction = road.number_in("friction", 1.0, 0.05, 2);
  std::shared_ptr<const Surface> surface;
  if (kind == "plane") surface = plane_surface(road);
  if (kind == "crg") surface = crg_surface(road);
  if (kind == "iso8608") surface = iso8608_surface(road);
  if (kind == "opendrive") surface = opendrive_surface(road);
  r.surface = model::road::with_overlay(surface, load_obstacles(road));
  r.friction_field = load_friction_zones(road);
  road.finish();
  return r;
}

void check_no_model_road_keys(const StrictTable& model) {
  for (const auto& entry : model.raw()) {
    const std::string_view key = entry.first.str();
    if (key.starts_with("road_"))
      throw ConfigError(model.location(key) + ": [model] " + std::string(key) +
                        ": the road is given by the [road] section; give it there or by the "
                        "[model] road_* keys, not both");
  }
}

}  // namespace rig::io::config
