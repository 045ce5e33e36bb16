// The field table of rig.vehicle_state_t (io/lcm/vehicle_state_fields.h): names, groups and units
// follow the naming rules, and the message builder fills every row from its source. Its
// agreement with the .lcm file and rig-log2csv is field_table_test.py's.

#include <set>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "io/lcm/message_builder.h"
#include "io/lcm/vehicle_state_fields.h"
#include "tests/io/lcm/synthetic_snapshot.h"

namespace rig::io::lcm {
namespace {

using Fields = VehicleStateFields;

/// The SI unit a name's suffix promises (names carry their unit); "1" without a unit suffix.
std::string_view unit_of_suffix(std::string_view name) {
  static constexpr std::pair<std::string_view, std::string_view> kSuffixes[] = {
      {"_mps2", "m/s^2"}, {"_radps", "rad/s"}, {"_mps", "m/s"}, {"_rad", "rad"},
      {"_nm", "N m"},     {"_pa", "Pa"},       {"_m", "m"},     {"_n", "N"},
  };
  for (const auto& [suffix, unit] : kSuffixes) {
    if (name.ends_with(suffix)) return unit;
  }
  return "1";
}

template <typename Rows>
void expect_rows_named(const Rows& rows, std::string_view group, std::set<std::string>& names) {
  for (const auto& row : rows) {
    EXPECT_TRUE(names.insert(std::string(row.name)).second) << row.name << " twice";
    if (!group.empty()) {
      EXPECT_EQ(group_of(row.name), group) << row.name;
    }
    EXPECT_EQ(row.unit, unit_of_suffix(row.name)) << row.name;
  }
}

TEST(VehicleStateFields, NamesAreUniqueInTheirGroupAndCarryTheirUnit) {
  std::set<std::string> names(std::begin(Fields::kFrame), std::end(Fields::kFrame));
  ASSERT_EQ(names.size(), std::size(Fields::kFrame));
  expect_rows_named(Fields::kUnit, "unit", names);
  expect_rows_named(Fields::kWheel, "wheel", names);
  expect_rows_named(Fields::kWheelFlag, "wheel", names);
  expect_rows_named(Fields::kJoint, "joint", names);
  expect_rows_named(Fields::kDiff, "diff", names);
  expect_rows_named(Fields::kDiffFlag, "diff", names);
  expect_rows_named(Fields::kBody, "body", names);
  expect_rows_named(Fields::kBodyFlag, "body", names);
  expect_rows_named(Fields::kVehicle, "", names);
  expect_rows_named(Fields::kVehicleInt, "", names);
  for (const auto& row : Fields::kVehicle) {
    const std::string_view group = group_of(row.name);
    EXPECT_TRUE(group != "unit" && group != "wheel" && group != "joint" && group != "diff")
        << row.name;
  }
}

TEST(VehicleStateFields, TheBuilderFillsEveryRowFromItsSource) {
  const Snapshot s = test::make_synthetic_snapshot(321, 0.001);
  rig::vehicle_state_t msg;
  fill_vehicle_state(s, msg);
  const auto& r = s.report;
  ASSERT_EQ(msg.num_units, test::kSyntheticUnits);
  for (const auto& row : Fields::kUnit) {
    ASSERT_EQ((msg.*row.lcm).size(), 2u) << row.name;
    for (std::size_t u = 0; u < 2; ++u) {
      EXPECT_EQ((msg.*row.lcm)[u], row.source(r.units[u])) << row.name << " unit " << u;
    }
  }
  ASSERT_EQ(msg.num_wheels, 6);
  for (const auto& row : Fields::kWheel) {
    ASSERT_EQ((msg.*row.lcm).size(), 6u) << row.name;
    for (std::size_t k = 0; k < 6; ++k) {
      const auto& wheel = r.units[k < 4 ? 0 : 1].wheels[k < 4 ? k : k - 4];
      EXPECT_EQ((msg.*row.lcm)[k], row.source(wheel)) << row.name << " wheel " << k;
    }
  }
  for (const auto& row : Fields::kWheelFlag) {
    ASSERT_EQ((msg.*row.lcm).size(), 6u) << row.name;
    for (std::size_t k = 0; k < 6; ++k) {
      const auto& wheel = r.units[k < 4 ? 0 : 1].wheels[k < 4 ? k : k - 4];
      EXPECT_EQ((msg.*row.lcm)[k], row.source(wheel)) << row.name << " wheel " << k;
    }
  }
  for (const auto& row : Fields::kVehicle) EXPECT_EQ(msg.*row.lcm, row.source(r)) << row.name;
  for (const auto& row : Fields::kVehicleInt) EXPECT_EQ(msg.*row.lcm, row.source(r)) << row.name;
  ASSERT_EQ(msg.num_joints, 1);
  for (const auto& row : Fields::kJoint) {
    ASSERT_EQ((msg.*row.lcm).size(), 1u) << row.name;
    EXPECT_EQ((msg.*row.lcm)[0], row.source(r.joints[0])) << row.name;
  }
  // The sources read what their rows say (spot checks against the synthetic formulas).
  EXPECT_EQ(msg.wheel_x_e_m[5], 1e-4 * 11);
  EXPECT_EQ(msg.unit_pitch_rad[1], 0.02);
  EXPECT_EQ(msg.brake_pressure_rl_pa, 0.5e5);
  EXPECT_EQ(msg.joint_force_z_n[0], 300.0);
  EXPECT_EQ(msg.num_diffs, 0);  // none configured: no elements
}

TEST(VehicleStateFields, DifferentialsAreFilledPerDifferential) {
  Snapshot s = test::make_synthetic_snapshot(321, 0.001);
  s.report.differential_count = 2;
  s.report.differentials[0] = {10.0, 11.0, 9.0, 0};
  s.report.differentials[1] = {11.0, 11.0, 11.0, 1};
  rig::vehicle_state_t msg;
  fill_vehicle_state(s, msg);
  ASSERT_EQ(msg.num_diffs, 2);
  for (const auto& row : Fields::kDiff) {
    ASSERT_EQ((msg.*row.lcm).size(), 2u) << row.name;
    for (std::size_t j = 0; j < 2; ++j)
      EXPECT_EQ((msg.*row.lcm)[j], row.source(s.report.differentials[j])) << row.name;
  }
  EXPECT_EQ(msg.diff_output_b_speed_radps[0], 9.0);
  EXPECT_EQ(msg.diff_locked[1], 1);
  s.report.differential_count = 0;  // and back to none: the arrays shrink
  fill_vehicle_state(s, msg);
  EXPECT_EQ(msg.num_diffs, 0);
  EXPECT_TRUE(msg.diff_locked.empty());
}

}  // namespace
}  // namespace rig::io::lcm
