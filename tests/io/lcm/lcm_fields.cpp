/// @file
/// rig-lcm-fields: prints the field table of rig.vehicle_state_t (io/lcm/vehicle_state_fields.h),
/// one row per line: GROUP NAME TYPE UNIT, tab-separated. GROUP is frame, unit, wheel, joint or
/// vehicle (scalars); TYPE the LCM type. For tests/io/lcm/field_table_test.py, which compares it
/// with lcm-gen's reading of vehicle_state_t.lcm.

#include <cstdint>
#include <cstdio>
#include <string_view>
#include <type_traits>

#include "io/lcm/vehicle_state_fields.h"

namespace {

using Fields = rig::io::lcm::VehicleStateFields;

void print(std::string_view group, std::string_view name, std::string_view type,
           std::string_view unit) {
  std::printf("%.*s\t%.*s\t%.*s\t%.*s\n", static_cast<int>(group.size()), group.data(),
              static_cast<int>(name.size()), name.data(), static_cast<int>(type.size()),
              type.data(), static_cast<int>(unit.size()), unit.data());
}

/// The LCM type name of a row's value type.
template <typename Value>
constexpr std::string_view lcm_type() {
  if constexpr (std::is_same_v<Value, double>) return "double";
  if constexpr (std::is_same_v<Value, std::int64_t>) return "int64_t";
  if constexpr (std::is_same_v<Value, std::int32_t>) return "int32_t";
  if constexpr (std::is_same_v<Value, std::int8_t>) return "int8_t";
}

template <typename Rows>
void print_rows(std::string_view group, const Rows& rows) {
  for (const auto& row : rows) {
    using Row = std::remove_cvref_t<decltype(row)>;
    print(group, row.name, lcm_type<typename Row::value_type>(), row.unit);
  }
}

}  // namespace

int main() {
  for (const std::string_view name : Fields::kFrame) print("frame", name, "-", "-");
  print_rows("unit", Fields::kUnit);
  print_rows("wheel", Fields::kWheel);
  print_rows("wheel", Fields::kWheelFlag);
  print_rows("vehicle", Fields::kVehicle);
  print_rows("vehicle", Fields::kVehicleInt);
  print_rows("joint", Fields::kJoint);
  print_rows("diff", Fields::kDiff);
  print_rows("diff", Fields::kDiffFlag);
  print_rows("body", Fields::kBody);
  print_rows("body", Fields::kBodyFlag);
  return 0;
}
