#pragma once
/// @file
/// A sweep's plan: the expanded runs and how to run them, written to DIR/plan.json before any
/// run starts. The local workers and the Slurm array tasks (`rig sweep SPEC --out DIR --task I`)
/// run from it, and `--collect` reads it back, so a run is exactly the one planned.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rig/sweep/sweep_spec.h"

namespace rig::sweep {

struct Plan {
  std::string name;
  std::filesystem::path spec;  ///< the spec file (absolute)
  std::filesystem::path dir;   ///< --out (absolute)
  std::filesystem::path rig;   ///< the rig executable the runs use (absolute)
  std::optional<double> duration_s;
  bool keep_logs = false;
  std::vector<std::string> vary_keys;
  std::vector<SweepRun> runs;
  SlurmOptions slurm;
};

/// DIR/runs/ID of a run.
std::filesystem::path run_dir(const Plan& plan, const SweepRun& run);

/// The plan of a spec: every run, the rig executable this one.
Plan make_plan(const SweepSpec& spec, const std::filesystem::path& dir, bool keep_logs);

/// DIR/plan.json; throws std::runtime_error naming the file if it cannot be written.
void write_plan(const Plan& plan);
/// Reads DIR/plan.json; throws std::runtime_error naming what is wrong.
Plan read_plan(const std::filesystem::path& dir);

/// The `rig run` command line of a run (argv[0] the rig executable): offline, no LCM, no CAN,
/// its summary and JUnit XML in its folder, its --set overrides; with keep_logs its LCM log and
/// overrun log too.
std::vector<std::string> run_command(const Plan& plan, const SweepRun& run);

}  // namespace rig::sweep
