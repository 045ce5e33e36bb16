#include "io/config/road_obstacles.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rig::io::config {

namespace {

using model::road::ObstacleKind;
using model::road::ObstacleParams;

constexpr double kFar_m = 1e7;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct KindName {
  std::string_view name;
  ObstacleKind kind;
};
constexpr KindName kKinds[] = {{"cleat", ObstacleKind::kCleat},
                               {"pothole", ObstacleKind::kPothole},
                               {"ramp", ObstacleKind::kRamp},
                               {"bump", ObstacleKind::kBump},
                               {"sine", ObstacleKind::kSine}};

ObstacleKind read_kind(StrictTable& t) {
  if (!t.has("kind"))
    throw t.error("kind", "missing required key (cleat, pothole, ramp, bump or sine)");
  const std::string name = t.choice("kind", "", {"cleat", "pothole", "ramp", "bump", "sine"});
  for (const auto& k : kKinds) {
    if (k.name == name) return k.kind;
  }
  return ObstacleKind::kCleat;  // unreachable: choice() refused anything else
}

/// A key of another kind (rise_m on a cleat) is named as such, not as unknown.
void refuse_foreign_keys(const StrictTable& t, ObstacleKind kind, const std::string& name) {
  if (kind != ObstacleKind::kRamp) {
    for (const char* key : {"rise_m", "fall_m"}) {
      if (t.has(key)) throw t.error(key, "is a key of kind \"ramp\", not of \"" + name + "\"");
    }
  }
  if (kind != ObstacleKind::kSine && t.has("wavelength_m"))
    throw t.error("wavelength_m", "is a key of kind \"sine\", not of \"" + name + "\"");
}

double read_height(StrictTable& t, ObstacleKind kind) {
  const double h = t.number_in("height_m", -1.0, 1.0);
  if (h == 0) throw t.error("height_m", "must not be 0");
  if (kind == ObstacleKind::kCleat && h < 0)
    throw t.error("height_m", "a cleat stands up: must be > 0 (a hole is kind = \"pothole\")");
  if (kind == ObstacleKind::kPothole && h > 0)
    throw t.error("height_m", "a pothole goes down: must be < 0 (its depth)");
  return h;
}

void read_shape_keys(StrictTable& t, ObstacleParams& p) {
  if (p.kind == ObstacleKind::kRamp) {
    p.rise_m = t.number_in("rise_m", p.length_m, 0.0, p.length_m);
    p.fall_m = t.number_in("fall_m", 0.0, 0.0, p.length_m);
    if (p.rise_m + p.fall_m > p.length_m)
      throw t.error("fall_m", "rise_m + fall_m = " + std::to_string(p.rise_m + p.fall_m) +
                                  " m is longer than length_m");
  } else if (p.kind == ObstacleKind::kSine) {
    p.wavelength_m = t.number_in("wavelength_m", 1e-3, 1e4);
    const double waves = p.length_m / p.wavelength_m;
    if (std::abs(waves - std::round(waves)) > 1e-9 * waves || std::round(waves) < 1)
      throw t.error("length_m", "must be a whole number of wavelengths (" + std::to_string(waves) +
                                    " of wavelength_m)");
  }
}

model::road::Obstacle read_obstacle(StrictTable& t) {
  ObstacleParams p;
  p.kind = read_kind(t);
  const std::string name = t.string("kind");
  refuse_foreign_keys(t, p.kind, name);
  p.x_m = t.number_in("x_m", 0.0, -kFar_m, kFar_m);
  p.y_m = t.number_in("y_m", 0.0, -kFar_m, kFar_m);
  p.heading_rad = t.number_in("heading_rad", 0.0, -100.0, 100.0);
  p.s_m = t.number_in("s_m", 0.0, -kFar_m, kFar_m);
  p.length_m = t.number_in("length_m", 1e-4, 1e5);
  p.width_m = t.number_in("width_m", kInf, 1e-3, kInf);
  p.height_m = read_height(t, p.kind);
  read_shape_keys(t, p);
  t.finish();
  try {
    return model::road::Obstacle(p);
  } catch (const std::invalid_argument& e) {
    throw t.error(e.what());  // the checks above come first; this is a last guard
  }
}

}  // namespace

std::shared_ptr<const model::road::Obstacles> load_obstacles(StrictTable& road) {
  if (!road.has("obstacle")) return nullptr;
  std::vector<model::road::Obstacle> obstacles;
  for (StrictTable& t : road.tables("obstacle", kMaxObstacles))
    obstacles.push_back(read_obstacle(t));
  if (obstacles.empty()) return nullptr;
  return std::make_shared<const model::road::Obstacles>(std::move(obstacles));
}

}  // namespace rig::io::config
