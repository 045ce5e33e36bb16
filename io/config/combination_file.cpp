#include "io/config/combination_file.h"

#include <string>

#include "io/config/vehicle_file.h"
#include "model/report.h"

namespace rig::io::config {

CombinationModelSettings read_combination_model(StrictTable& m, const Overrides* overrides) {
  using model::combination::JointKind;
  using model::combination::JointParams;
  CombinationModelSettings c;
  const model::road::RoadParams road = read_road(m);
  c.initial_speed_mps = m.number_in("initial_speed_mps", 0.0, -100, 100);
  c.parallel = m.boolean("parallel", false);
  for (auto& u : m.tables("unit", model::kMaxUnits)) {
    c.unit_files.push_back(u.existing_path("vehicle"));
    const int unit = static_cast<int>(c.units.size()) + 1;  // unit<k>, k from 1
    c.units.push_back(load_vehicle_file(
        c.unit_files.back(), overrides ? overrides->of_file(unit) : std::vector<Override>{}));
    c.units.back().road = road;
    u.finish();
  }
  if (c.units.size() < 2 || c.units.size() > static_cast<std::size_t>(model::kMaxUnits)) {
    throw m.error("unit",
                  "needs 2 to " + std::to_string(model::kMaxUnits) + " [[model.unit]] tables");
  }
  auto joints = m.tables("joint", model::kMaxJoints);
  if (joints.size() != c.units.size() - 1)
    throw m.error("joint", "needs one [[model.joint]] between each pair of units");
  for (std::size_t i = 0; i < joints.size(); ++i) {
    StrictTable& j = joints[i];
    const std::string kind_name = j.choice("kind", "ball", {"ball", "fifth-wheel", "tow-bar"});
    const JointKind kind = kind_name == "ball"          ? JointKind::kBall
                           : kind_name == "fifth-wheel" ? JointKind::kFifthWheel
                                                        : JointKind::kTowBar;
    const double leading_x = j.number_in("leading_x_m", -30, 30);
    const double trailing_x = j.number_in("trailing_x_m", -30, 30);
    const double height = j.number_in("height_m", 0.05, 5);
    const auto& a = c.units[i];
    const auto& b = c.units[i + 1];
    // A coupling pulls the trailing unit from ahead of its axles, and sits behind the leading
    // unit's front axle.
    if (!(leading_x < a.axles.front().position_x_m))
      throw j.error("leading_x_m", "must lie behind the leading unit's front axle (x = " +
                                       std::to_string(a.axles.front().position_x_m) + " m)");
    if (!(trailing_x > b.axles.front().position_x_m))
      throw j.error("trailing_x_m", "must lie ahead of the trailing unit's front axle (x = " +
                                        std::to_string(b.axles.front().position_x_m) + " m)");
    JointParams p;
    p.kind = kind;
    p.leading_point_m = {leading_x, 0, height - a.chassis.cg_height_m};
    p.trailing_point_m = {trailing_x, 0, height - b.chassis.cg_height_m};
    if (kind == JointKind::kTowBar) p.length_m = j.number_in("length_m", 0.1, 20);
    p.stiffness_npm = j.number_in("stiffness_npm", p.stiffness_npm, 1e3, 1e12);
    p.damping_nspm = j.number_in("damping_nspm", p.damping_nspm, 0, 1e9);
    p.roll_stiffness_nmpr = j.number_in("roll_stiffness_nmpr", p.roll_stiffness_nmpr, 1e3, 1e12);
    p.roll_damping_nmspr = j.number_in("roll_damping_nmspr", p.roll_damping_nmspr, 0, 1e9);
    j.finish();
    c.joints.push_back(p);
  }
  c.name = c.units.front().name;
  for (std::size_t i = 1; i < c.units.size(); ++i) c.name += " + " + c.units[i].name;
  return c;
}

}  // namespace rig::io::config
