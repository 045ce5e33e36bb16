#pragma once
/// @file
/// The signal catalogue: every model input a bench may drive and every output of the model's
/// report, named after the configured model's structure (docs/signals.md):
///
///   unit<k>.axle<j>.<left|right>.<quantity>   per wheel (k, j from 1, config order)
///   unit<k>.<quantity>                        per unit body, and its brake circuits
///   unit1.steering.<quantity>, unit1.drivetrain.<quantity>
///   joint<i>.<quantity>                       per coupling of a combination
///   unit1.drivetrain.diff<i>.<quantity>       per configured differential of the first unit
///
/// with `unit<k>.wheel_fl|fr|rl|rr.<quantity>` aliases on two-axle units and the enum's names
/// (model::kSignalTable, `vehicle_speed_mps`, ...) as aliases of their entries. Outputs come
/// from the field table io/lcm/vehicle_state_fields.h (its `quantity` column), inputs from the
/// slots of model/signals.h. Built once at load time; sizes are fixed from then on. The CAN
/// mapping, [routing], the table driver and [lcm] signals bind through lookup().

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "io/config/strict_table.h"
#include "io/signals/binding.h"
#include "model/report.h"

namespace rig::io::signals {

inline constexpr int kMaxAxlesPerUnit = model::kMaxWheelsPerUnit / 2;

/// What the names follow: the units of the model and their axles (a single vehicle is one unit).
struct ModelShape {
  int unit_count = 1;
  std::array<int, model::kMaxUnits> axle_count{2, 0, 0, 0};
  int joint_count = 0;  ///< couplings (unit_count - 1 for a combination)
  /// The first unit's differentials (model::ModelReport::differential_count; 0: none configured).
  int differential_count = 0;
  int body_count = 0;   ///< free bodies of the leading unit (`[[free_body]]`): body1, body2, ...
};

struct Entry {
  std::string name;
  std::string unit;  ///< SI unit, "1" for ratios and counts
  Direction direction = Direction::kOut;
  double min = 0.0;  ///< inputs: model::slot_range; outputs: unbounded (NaN here, null in JSON)
  double max = 0.0;
  std::vector<std::string> aliases;
  Binding binding;
};

class Catalogue {
 public:
  /// Throws std::invalid_argument for a shape beyond kMaxUnits x kMaxAxlesPerUnit.
  explicit Catalogue(const ModelShape& shape);

  /// The catalogue of one unit of two axles (the sedan): for code that binds names without a
  /// configured model (a CAN mapping checked on its own, tests).
  static const Catalogue& two_axle_vehicle();

  [[nodiscard]] std::span<const Entry> entries() const { return entries_; }
  [[nodiscard]] const ModelShape& shape() const { return shape_; }
  /// The entry of a name or alias, nullptr if there is none.
  [[nodiscard]] const Entry* find(std::string_view name) const;
  /// At most `count` names and aliases closest to `name` (edit distance), nearest first.
  [[nodiscard]] std::vector<std::string> closest(std::string_view name,
                                                 std::size_t count = 5) const;
  /// "unknown signal 'X' (closest: a, b, ...; `rig signals CONFIG` lists them all)", `lead`
  /// instead of "unknown signal" if given.
  [[nodiscard]] std::string unknown_message(std::string_view name,
                                            std::string_view lead = "unknown signal") const;
  /// The entry `name`, read from `key` of `table`; else a ConfigError at that key's file:line
  /// with the closest names. `inputs_only`: an output is an error too ("`what`").
  const Entry& lookup(const config::StrictTable& table, std::string_view key, std::string_view name,
                      bool inputs_only = false, std::string_view what = "only inputs can be set",
                      std::string_view lead = "unknown signal") const;

 private:
  void add(Entry e);
  void add_inputs();
  void add_outputs();
  void add_differential_outputs();
  void add_body_outputs();  ///< body1.x_m, ...: the leading unit's free bodies
  void add_aliases();
  void alias(std::string_view name, std::string alias_name);

  ModelShape shape_;
  std::vector<Entry> entries_;
  std::unordered_map<std::string, std::size_t> index_;  ///< names and aliases -> entry
};

/// `unit<k>.axle<j>.<left|right>` of wheel `wheel` (from 0, as in model/report.h) of unit `unit`
/// (from 0).
std::string wheel_prefix(int unit, int wheel);

}  // namespace rig::io::signals
