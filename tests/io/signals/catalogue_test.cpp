// The signal catalogue (io/signals): names and counts from the model's shape, aliases, ranges,
// the closest-name error, and the enum's names giving bit for bit what they gave before.
#include "io/signals/catalogue.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>

#include "io/config/config_error.h"
#include "rig/config.h"
#include "rig/model_factory.h"

namespace rig::io::signals {
namespace {

const std::string kDir = std::string(RIG_SOURCE_DIR);
const std::string kSedan = kDir + "/config/rig.toml";
const std::string kTruck = kDir + "/tests/io/signals/configs/truck.toml";
const std::string kThreeUnits = kDir + "/tests/io/signals/configs/three-units.toml";
const std::string kSedan4x4 = kDir + "/config/maneuvers/mu-split-acceleration-4x4.toml";
const std::string kTractorCab = kDir + "/tests/io/signals/configs/tractor-cab.toml";

// Per unit: 15 body quantities, 18 per wheel (17 doubles of the field table and slip_valid);
// the vehicle rows with a catalogue name: 9 steering, 2 engine and the gear; 5 per joint; 4 per
// configured differential (issue 17: input and output speeds, locked).
// Inputs: 14 of unit 1 (issue 17: the two differential locks) and per unit 2 circuits and one
// pressure per wheel.
constexpr std::size_t count(std::initializer_list<int> axles, int joints, int differentials = 0) {
  std::size_t n =
      14 + 12 + 5 * static_cast<std::size_t>(joints) + 4 * static_cast<std::size_t>(differentials);
  // per wheel: 19, and the road under it (issue 16: road_z_m, road_normal_x/y/z, road_mu), and
  // its rigid axle's heave and roll (issue 17: axle_heave_m, axle_roll_rad), its leaf spring's
  // wind-up, fore-aft travel, shackle, eye links and iterations (issue 17, leaf_axle.h: 6) and
  // its leaf balance's rocker angle (leaf_balance.h: 1)
  // per unit also the frame's twist, twist rate and torsion moment (issue 17 item 5): 15 + 3
  for (const int a : axles) n += 2 + 15 + 3 + static_cast<std::size_t>(2 * a) * (19 + 5 + 2 + 7);
  return n;
}

TEST(Catalogue, NamesAndCountsFollowTheModelShape) {
  const RigConfig sedan = load_config(kSedan);
  const RigConfig truck = load_config(kTruck);
  const RigConfig three = load_config(kThreeUnits);
  const RigConfig awd = load_config(kSedan4x4);
  EXPECT_EQ(sedan.catalogue->entries().size(), count({2}, 0));        // 178
  EXPECT_EQ(truck.catalogue->entries().size(), count({3}, 0));        // 244
  EXPECT_EQ(three.catalogue->entries().size(), count({2, 2, 2}, 2));  // 492
  EXPECT_EQ(awd.catalogue->entries().size(), count({2}, 0, 3));       // 190
  EXPECT_EQ(sedan.catalogue->entries().size(), 178u);
  EXPECT_NE(sedan.catalogue->find("unit1.drivetrain.differential_lock_axle_cmd"), nullptr);
  EXPECT_EQ(sedan.catalogue->find("unit1.drivetrain.diff1.locked"), nullptr);
  EXPECT_NE(awd.catalogue->find("unit1.drivetrain.diff3.output_b_speed_radps"), nullptr);
  EXPECT_EQ(awd.catalogue->find("unit1.drivetrain.diff4.locked"), nullptr);
  // free bodies (issue 17 item 4): 12 doubles and on_stop per body; none without (above)
  const RigConfig cab = load_config(kTractorCab);
  EXPECT_EQ(cab.catalogue->entries().size(), count({3}, 0) + 3 * 13);  // 283
  for (const char* name : {"body1.roll_rad", "body2.x_m", "body3.z_m", "body3.on_stop"})
    EXPECT_NE(cab.catalogue->find(name), nullptr) << name;
  EXPECT_EQ(cab.catalogue->find("body4.z_m"), nullptr);
  EXPECT_EQ(truck.catalogue->find("body1.z_m"), nullptr);
  for (const char* name : {"unit1.axle2.right.load_n", "unit1.axle1.left.brake_pressure_pa",
                           "unit1.steering.overlay_angle_cmd_rad", "unit1.ignition_state",
                           "unit1.drivetrain.gear", "unit1.axle1.left.applied_brake_pressure_pa",
                           "unit1.frame_twist_rad", "unit1.frame_torsion_moment_nm"})
    EXPECT_NE(sedan.catalogue->find(name), nullptr) << name;
  EXPECT_EQ(sedan.catalogue->find("unit1.axle3.left.load_n"), nullptr);
  EXPECT_NE(truck.catalogue->find("unit1.axle3.right.slip_x"), nullptr);
  for (const char* name : {"unit2.yaw_rate_radps", "unit3.speed_x_mps", "unit3.axle2.left.load_n",
                           "unit3.brake_circuit_rear_pa", "joint2.rod_force_n"})
    EXPECT_NE(three.catalogue->find(name), nullptr) << name;
  EXPECT_EQ(three.catalogue->find("joint3.rod_force_n"), nullptr);
  EXPECT_EQ(three.catalogue->find("unit4.speed_x_mps"), nullptr);
}

TEST(Catalogue, ShapeMatchesTheConstructedModelsReport) {
  for (const std::string& file : {kSedan, kTruck, kThreeUnits, kSedan4x4, kTractorCab}) {
    const RigConfig c = load_config(file);
    const auto m = make_model(c);
    model::ModelReport r;
    m->fill_report(r);
    const ModelShape& shape = c.catalogue->shape();
    ASSERT_EQ(r.unit_count, shape.unit_count) << file;
    for (int k = 0; k < r.unit_count; ++k)
      EXPECT_EQ(r.units[static_cast<std::size_t>(k)].wheel_count,
                2 * shape.axle_count[static_cast<std::size_t>(k)])
          << file;
    EXPECT_EQ(r.joint_count, shape.joint_count) << file;
    EXPECT_EQ(r.differential_count, shape.differential_count) << file;
    EXPECT_EQ(r.body_count, shape.body_count) << file;
  }
}

TEST(Catalogue, AliasesNameTheSameEntry) {
  const RigConfig sedan = load_config(kSedan);
  const RigConfig truck = load_config(kTruck);
  const RigConfig three = load_config(kThreeUnits);
  const Catalogue& s = *sedan.catalogue;
  EXPECT_EQ(s.find("unit1.wheel_fl.load_n"), s.find("unit1.axle1.left.load_n"));
  EXPECT_EQ(s.find("unit1.wheel_rr.brake_pressure_pa"),
            s.find("unit1.axle2.right.brake_pressure_pa"));
  EXPECT_EQ(s.find("vehicle_speed_mps"), s.find("unit1.speed_x_mps"));
  EXPECT_EQ(s.find("rack_position_m"), s.find("unit1.steering.rack_travel_m"));
  EXPECT_EQ(s.find("assist_torque_nm"), s.find("unit1.steering.eps_motor_torque_nm"));
  EXPECT_EQ(s.find("brake_pressure_fl_pa"), s.find("unit1.axle1.left.applied_brake_pressure_pa"));
  EXPECT_EQ(s.find("brake_pressure_front_pa"), s.find("unit1.brake_circuit_front_pa"));
  EXPECT_EQ(s.find("heading_rad"), s.find("unit1.yaw_rad"));
  const Catalogue& t = *truck.catalogue;
  EXPECT_EQ(t.find("wheel_speed_rl_radps"), t.find("unit1.axle3.left.spin_radps"));
  EXPECT_EQ(t.find("brake_pressure_rr_pa"), t.find("unit1.axle3.right.applied_brake_pressure_pa"));
  EXPECT_EQ(t.find("unit1.wheel_fl.load_n"), nullptr);  // three axles: no corner names
  const Catalogue& c = *three.catalogue;
  EXPECT_EQ(c.find("unit3.wheel_rl.spin_radps"), c.find("unit3.axle2.left.spin_radps"));
  // every one of the enum's names is an alias, of an entry of its direction
  for (const model::SignalInfo& info : model::kSignalTable) {
    for (const Catalogue* cat : {&s, &t, &c}) {
      const Entry* e = cat->find(info.name);
      ASSERT_NE(e, nullptr) << info.name;
      EXPECT_EQ(e->binding.is_input(), info.is_input) << info.name;
      EXPECT_EQ(e->binding.slot, model::index(info.id)) << info.name;
    }
  }
}

TEST(Catalogue, InputRangesAreTheSlotRanges) {
  const Catalogue& c = Catalogue::two_axle_vehicle();
  EXPECT_EQ(c.find("unit1.throttle_pedal")->min, 0.0);
  EXPECT_EQ(c.find("unit1.throttle_pedal")->max, 1.0);
  EXPECT_EQ(c.find("unit1.gear_request")->min, -1.0);
  EXPECT_EQ(c.find("unit1.gear_request")->max, 99.0);
  EXPECT_EQ(c.find("unit1.ignition_state")->max, 3.0);
  EXPECT_EQ(c.find("unit1.axle2.left.brake_pressure_pa")->max, 3e7);  // 300 bar
  EXPECT_EQ(c.find("unit1.axle2.left.brake_pressure_pa")->binding.slot,
            model::wheel_brake_slot(0, 2));
  EXPECT_EQ(c.find("unit1.steering.overlay_angle_cmd_rad")->max, 1.0);
  EXPECT_TRUE(std::isnan(c.find("unit1.speed_x_mps")->min));  // outputs: unbounded
}

TEST(Catalogue, UnknownNameListsTheClosestOnesAtFileAndLine) {
  const Catalogue& c = Catalogue::two_axle_vehicle();
  const auto near = c.closest("unit1.axle1.left.lod_n");
  ASSERT_EQ(near.size(), 5u);
  EXPECT_EQ(near.front(), "unit1.axle1.left.load_n");
  EXPECT_EQ(c.closest("wheel_speed_fl_rads").front(), "wheel_speed_fl_radps");
  const toml::table doc = toml::parse(std::string_view("[x]\n\nmodel = \"yaw_rate_rad\"\n"),
                                      std::string_view("mapping.toml"));
  io::config::StrictTable t(*doc["x"].as_table(), "mapping.toml", "[x]");
  try {
    (void)c.lookup(t, "model", "yaw_rate_rad");
    FAIL() << "no error";
  } catch (const io::config::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mapping.toml:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown signal 'yaw_rate_rad'"), std::string::npos) << what;
    EXPECT_NE(what.find("yaw_rate_radps"), std::string::npos) << what;
  }
  EXPECT_THROW((void)c.lookup(t, "model", "yaw_rate_radps", true), io::config::ConfigError);
}

/// Runs `file`'s model with its driver and compares, every step, each of the enum's outputs in
/// model::Signals with what its name reads through the catalogue (the report): bit for bit.
void expect_aliases_bit_identical(const std::string& file, int steps) {
  const RigConfig c = load_config(file);
  const auto m = make_model(c);
  const auto d = make_driver(c);
  model::Signals s{};
  model::ModelReport r{};
  int compared = 0;
  for (int n = 0; n < steps; ++n) {
    if (d) d->update(m->time_s(), s);
    ASSERT_EQ(m->step(s), model::StepStatus::kOk) << file << " step " << n;
    m->fill_report(r);
    const CycleView view{s, r};
    for (std::size_t i = model::index(model::kFirstOutput); i < model::kSignalCount; ++i) {
      const Entry* e = c.catalogue->find(model::kSignalTable[i].name);
      const double v = e->binding.value(view);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(v), std::bit_cast<std::uint64_t>(s.value[i]))
          << file << " step " << n << ": " << model::kSignalTable[i].name << " = " << v
          << " through " << e->name << ", " << s.value[i] << " in the signals";
      ASSERT_EQ(e->binding.valid(view), s.valid[i]) << model::kSignalTable[i].name;
      ++compared;
    }
  }
  EXPECT_EQ(compared, steps * 22);
}

TEST(Catalogue, EnumNamesGiveTheSameBitsAsBeforeSedan) {
  expect_aliases_bit_identical(kSedan, 1500);
}
TEST(Catalogue, EnumNamesGiveTheSameBitsAsBeforeTruck) {
  expect_aliases_bit_identical(kTruck, 1500);
}
TEST(Catalogue, EnumNamesGiveTheSameBitsAsBeforeThreeUnits) {
  expect_aliases_bit_identical(kThreeUnits, 1500);
}

}  // namespace
}  // namespace rig::io::signals
