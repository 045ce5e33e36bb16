#pragma once
/// @file
/// A sweep specification (`rig sweep SPEC.toml`, docs/sweeps.md) and its expansion into runs:
///
///   name = "dlc-mass-speed"                 # optional (default: the file's stem)
///   base = "../maneuvers/double-lane-change-iso3888.toml"     # one run configuration, or
///   maneuvers = ["../maneuvers/a.toml", "../maneuvers/b.toml"] # several (relative to SPEC)
///   duration_s = 8.0                        # optional: every run's --duration
///   set = { "model.road_friction" = 0.9 }   # optional: --set of every run
///   seeds = [1, 2, 3]                       # optional: one run per seed, --set SEED_KEY=seed
///   seed_key = "road.seed"                  # where the seed goes (default "road.seed")
///
///   [[roads]]                               # optional: one run per road, each a named --set
///   name = "wet"
///   set = { "model.road_friction" = 0.6 }
///
///   [[vary]]                                # any number: one run per value
///   key = "vehicle.chassis.mass_kg"         # a --set key path (io/config/overrides.h)
///   values = [1400, 1500, 1600]
///
///   [slurm]                                 # optional: rig sweep --slurm's job array
///   partition = "batch"
///   time = "00:10:00"
///   cpus_per_task = 1
///   runs_per_task = 1                       # > 1: fewer, longer array tasks
///   options = ["--account=vd"]              # more #SBATCH lines
///
/// The runs are the product maneuvers x roads x vary[0] x ... x vary[n-1] x seeds, in that
/// order (the last varies fastest): deterministic, each numbered from 0 (its id: the number,
/// zero-padded to at least 4 digits).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rig::sweep {

/// The most runs one sweep may expand to.
inline constexpr std::size_t kMaxRuns = 1'000'000;

struct SlurmOptions {
  std::string partition;
  std::string time;
  int cpus_per_task = 1;
  int runs_per_task = 1;
  std::vector<std::string> options;
};

struct SweepSpec {
  std::filesystem::path file;
  std::string name;
  std::vector<std::filesystem::path> configs;  ///< base or maneuvers (absolute)
  std::optional<double> duration_s;
  std::vector<std::string> sets;  ///< `set`, as KEY=VALUE
  struct Road {
    std::string name;
    std::vector<std::string> sets;
  };
  std::vector<Road> roads;
  struct Vary {
    std::string key;
    std::vector<std::string> values;  ///< each as TOML text (1500, 0.8, "text")
  };
  std::vector<Vary> vary;
  std::vector<long long> seeds;
  std::string seed_key = "road.seed";
  SlurmOptions slurm;
};

/// One run of the expansion.
struct SweepRun {
  std::size_t index = 0;
  std::string id;
  std::filesystem::path config;
  std::string maneuver;  ///< the configuration's stem
  std::string road;      ///< "" without [[roads]]
  std::optional<long long> seed;
  std::vector<std::pair<std::string, std::string>> vary;  ///< key, value (TOML text)
  std::vector<std::string> sets;  ///< every --set KEY=VALUE of the run, in order
};

/// Reads SPEC strictly (unknown keys, empty lists, a malformed key path, a missing
/// configuration: ConfigError with file:line).
SweepSpec load_sweep_spec(const std::filesystem::path& file);

/// How many runs the spec expands to (at most kMaxRuns, else ConfigError).
std::size_t run_count(const SweepSpec& spec);

/// Every run, in order.
std::vector<SweepRun> expand(const SweepSpec& spec);

/// The run ids' width: the digits of count - 1, at least 4.
int id_width(std::size_t count);

}  // namespace rig::sweep
