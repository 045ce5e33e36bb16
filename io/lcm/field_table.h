#pragma once
/// @file
/// The row types of a field table: which member of an LCM message carries a quantity, its SI
/// unit, and where it comes from in a model report struct. The rows of rig.vehicle_state_t are
/// in vehicle_state_fields.h; the message builder fills the message from them and rig-log2csv
/// names its CSV columns after them.
///
/// A row's source is a plain function reading one value, made from member pointers:
///   member<&WheelReport::load_n>                                   wheel.load_n
///   member<&ModelReport::steering, &SteeringReport::rack_force_n>  report.steering.rack_force_n
///   element<&UnitReport::position_m, 0>                            unit.position_m[0]

#include <cstddef>
#include <iterator>
#include <string_view>
#include <utility>
#include <vector>

namespace rig::io::lcm {

namespace detail {
template <typename MemberPointer>
struct class_of;
template <typename Class, typename Value>
struct class_of<Value Class::*> {
  using type = Class;
};
template <auto MemberPointer>
using class_of_t = typename class_of<decltype(MemberPointer)>::type;
}  // namespace detail

/// Reads a member, or a member of a member (applied left to right).
template <auto First, auto... Rest>
constexpr auto member(const detail::class_of_t<First>& from) {
  if constexpr (sizeof...(Rest) == 0) {
    return from.*First;
  } else {
    return member<Rest...>(from.*First);
  }
}

/// Reads element `Index` of an array member.
template <auto Array, std::size_t Index>
constexpr auto element(const detail::class_of_t<Array>& from) {
  return (from.*Array)[Index];
}

/// A quantity with one value per element of a group (unit, wheel, joint). Its LCM member is an
/// array named `<group>_<quantity>`, sized by the message's count of that group; its CSV
/// columns are `<group><i>_<quantity>` (wheel_load_n -> wheel0_load_n, wheel1_load_n, ...).
template <typename Message, typename From, typename Value = double>
struct ArrayField {
  using value_type = Value;
  std::string_view name;  ///< the LCM member
  std::string_view unit;  ///< SI; "1" for ratios and counts
  Value (*source)(const From&);
  std::vector<Value> Message::*lcm;
  /// Its name in the signal catalogue (io/signals), after the element's prefix
  /// (`unit2.` + "yaw_rate_radps"); empty: not a catalogue output.
  std::string_view quantity;
};

/// A quantity with one value per message: LCM member and CSV column `name`.
template <typename Message, typename From, typename Value = double>
struct ScalarField {
  using value_type = Value;
  std::string_view name;
  std::string_view unit;
  Value (*source)(const From&);
  Value Message::*lcm;
  /// Its name in the signal catalogue after `unit1.` ("steering.rack_force_n"); empty: none.
  std::string_view quantity;
};

/// Calls `apply(row)` for every row of the constexpr table `Rows`, unrolled at compile time so
/// that each row's source becomes a direct, inlined call: a table-driven builder is as fast as
/// hand-written assignments (tests/bench/lcm).
template <const auto& Rows, typename Apply>
constexpr void for_each_row(Apply&& apply) {
  [&]<std::size_t... I>(std::index_sequence<I...>) { (apply(Rows[I]), ...); }
  (std::make_index_sequence<std::size(Rows)>{});
}

/// The group of an array field's name: the text before its first '_' ("wheel" of wheel_load_n).
constexpr std::string_view group_of(std::string_view name) {
  return name.substr(0, name.find('_'));
}

}  // namespace rig::io::lcm
