#include "io/config/free_body_config.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <string>

namespace rig::io::config {
namespace {

using model::vehicle::FreeBodyKind;
using model::vehicle::FreeBodyParams;
using model::vehicle::MountParams;
using Array3 = std::array<double, 3>;

std::string range_text(double lo, double hi) {
  char text[64];
  std::snprintf(text, sizeof text, "[%g, %g]", lo, hi);
  return text;
}

/// A list of exactly three finite numbers in [lo, hi].
Array3 read_vec3(StrictTable& t, std::string_view key, double lo, double hi) {
  const std::vector<double> v = t.numbers(key, 3);
  if (v.size() != 3) throw t.error(key, "must be a list of 3 numbers");
  for (const double x : v) {
    if (!std::isfinite(x) || x < lo || x > hi)
      throw t.error(key, "every entry must be a finite number in " + range_text(lo, hi));
  }
  return {v[0], v[1], v[2]};
}

Array3 read_vec3(StrictTable& t, std::string_view key, const Array3& fallback, double lo,
                 double hi) {
  return t.has(key) ? read_vec3(t, key, lo, hi) : fallback;
}

MountParams read_mount(StrictTable m, const Array3& position) {
  MountParams out;
  out.body_point_m = read_vec3(m, "body_point_m", -20, 20);
  const Array3 design{position[0] + out.body_point_m[0], position[1] + out.body_point_m[1],
                      position[2] + out.body_point_m[2]};
  out.chassis_point_m = read_vec3(m, "chassis_point_m", design, -20, 20);
  out.orientation_rad = read_vec3(m, "orientation_rad", Array3{}, -3.2, 3.2);
  out.stiffness_npm = read_vec3(m, "stiffness_npm", 1, 1e9);
  out.damping_nspm = read_vec3(m, "damping_nspm", 0, 1e8);
  out.stop_clearance_m = read_vec3(m, "stop_clearance_m", 1e-4, 1);
  out.stop_stiffness_npm = read_vec3(m, "stop_stiffness_npm", 0, 1e10);
  m.finish();
  return out;
}

/// The seat's one vertical mount from its own keys.
MountParams read_seat_mount(StrictTable& t, const Array3& position) {
  MountParams m;
  m.chassis_point_m = position;
  m.stiffness_npm[2] = t.number_in("stiffness_npm", 1, 1e8);
  m.damping_nspm[2] = t.number_in("damping_nspm", 0, 1e7);
  m.stop_clearance_m[2] = t.number_in("stop_clearance_m", 1e-4, 1);
  m.stop_stiffness_npm[2] = t.number_in("stop_stiffness_npm", 0, 1e9);
  return m;
}

FreeBodyParams read_free_body(StrictTable t) {
  FreeBodyParams b;
  b.name = t.string("name");
  if (b.name.empty()) throw t.error("name", "must not be empty");
  const std::string kind = t.choice("kind", "cab", {"cab", "engine", "seat"});
  b.kind = kind == "engine" ? FreeBodyKind::kEngine
           : kind == "seat" ? FreeBodyKind::kSeat
                            : FreeBodyKind::kCab;
  b.mass_kg = t.number_in("mass_kg", 1, 1e5);
  b.position_m = read_vec3(t, "position_m", -20, 20);
  b.through_margin_m = t.number_in("through_margin_m", 0.01, 1e-4, 1);
  if (b.kind == FreeBodyKind::kSeat) {
    b.mounts.push_back(read_seat_mount(t, b.position_m));
    t.finish();
    return b;
  }
  b.inertia_kgm2 = read_vec3(t, "inertia_kgm2", 1e-3, 1e6);
  if (b.kind == FreeBodyKind::kEngine) {
    b.crankshaft_axis = read_vec3(t, "crankshaft_axis", Array3{1, 0, 0}, -1, 1);
    const Array3& a = b.crankshaft_axis;
    if (std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) < 0.5)
      throw t.error("crankshaft_axis", "must be a direction (length about 1)");
  }
  const std::size_t mounts = b.kind == FreeBodyKind::kCab ? 4 : 3;
  if (!t.has("mount"))
    throw t.error("a " + kind + " needs " + std::to_string(mounts) + " [[free_body.mount]] tables");
  std::vector<StrictTable> tables = t.tables("mount", mounts);
  if (tables.size() != mounts)
    throw t.error("mount", "a " + kind + " needs " + std::to_string(mounts) +
                               " [[free_body.mount]] tables, found " +
                               std::to_string(tables.size()));
  for (auto& m : tables) b.mounts.push_back(read_mount(std::move(m), b.position_m));
  t.finish();
  return b;
}

}  // namespace

std::vector<FreeBodyParams> read_free_bodies(StrictTable& vehicle) {
  std::vector<FreeBodyParams> out;
  if (!vehicle.has("free_body")) return out;
  std::vector<StrictTable> tables =
      vehicle.tables("free_body", static_cast<std::size_t>(model::vehicle::kMaxFreeBodies));
  std::set<std::string> names;
  for (auto& t : tables) {
    const std::string where = t.location("name");
    out.push_back(read_free_body(std::move(t)));
    if (!names.insert(out.back().name).second)
      throw ConfigError(where + ": [[free_body]] name \"" + out.back().name +
                        "\" is used twice (names must be unique)");
  }
  return out;
}

}  // namespace rig::io::config
