#pragma once
/// @file
/// `--set KEY=VALUE`: values put into a run configuration, or into a file it names, before it is
/// read (`rig run --set`, the runs of `rig sweep`). The strict readers then read the patched
/// tables as they would the file, so a bad value or an unknown key is the same error as in the
/// file, located at `--set KEY=VALUE` instead of `file:line`. Load time only.
///
/// Key paths (docs/sweeps.md), dot-separated TOML keys, an array of tables indexed `NAME[i]`
/// (from 0, as `rig check` names tables: `kpi[0]`, `axle[1]`):
///
///   SECTION.KEY...     a key of the run configuration: `rig.duration_s`, `model.road_friction`,
///                      `driver.target_speed_mps`, `lcm.channel_prefix`, `kpi[2].max`
///   vehicle.KEY...     a key of the vehicle file that [model] vehicle names:
///                      `vehicle.chassis.mass_kg`, `vehicle.axle[1].position_x_m`
///   unit<k>.KEY...     a key of unit k's vehicle file (k from 1, as the signal names): a
///                      combination's [[model.unit]] k, or (`unit1.`) a single vehicle's file
///
/// VALUE is a TOML value (`1600`, `0.8`, `true`, `"text"`, `[1, 2]`); text that is not one is
/// taken as a string (`driver.path=circle`). A missing section or key is created, so the
/// strict reader judges it: an unknown key is "unknown key", a wrong type "expected a number".

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace rig::io::config {

/// One dotted segment of a key path: `axle[1]` is {"axle", 1}.
struct KeySegment {
  std::string name;
  std::optional<std::size_t> index;
};

struct Override {
  std::string text;  ///< "KEY=VALUE" as given (messages start with "--set TEXT")
  std::string key;   ///< KEY
  /// 0: the run configuration; k >= 1: the vehicle file of unit k.
  int file = 0;
  bool vehicle_prefix = false;   ///< written `vehicle.` (a single vehicle's file, unit 1)
  std::vector<KeySegment> path;  ///< within that file (the prefix removed)
  std::string value;             ///< VALUE
};

/// The most units a key may name (model::kMaxUnits).
inline constexpr int kMaxOverrideUnit = 4;

/// Parses "KEY=VALUE". Throws ConfigError("--set TEXT: what is wrong") on a malformed key path.
Override parse_override(std::string_view text);

/// The --set overrides of one run, in the order given (a later one wins).
class Overrides {
 public:
  Overrides() = default;
  /// Throws ConfigError on the first malformed one.
  explicit Overrides(const std::vector<std::string>& texts);

  [[nodiscard]] bool empty() const { return all_.empty(); }
  [[nodiscard]] const std::vector<Override>& all() const { return all_; }
  /// The overrides of one file (0: the run configuration, k: unit k's vehicle file).
  [[nodiscard]] std::vector<Override> of_file(int file) const;

  /// Every override names a file the configuration has: `unit_count` units (0 for a model
  /// without vehicle files, the quarter car); `vehicle.` only for a single vehicle. Throws
  /// ConfigError("--set TEXT: ...") naming what can be set.
  void check_files(int unit_count, bool combination) const;

 private:
  std::vector<Override> all_;
};

/// Puts `overrides` into `doc` (the parsed `file`), creating missing tables and keys; the new
/// nodes' source is "--set TEXT" (StrictTable names it instead of file:line). Throws
/// ConfigError("--set TEXT: ...") when a path runs through a value that is not a table or
/// indexes past an array's end.
void apply_overrides(const std::vector<Override>& overrides, toml::table& doc,
                     const std::filesystem::path& file);

/// The source name of a --set node ("--set TEXT"), and whether a source path is one.
std::string override_source(const Override& o);
bool is_override_source(std::string_view source_path);

}  // namespace rig::io::config
