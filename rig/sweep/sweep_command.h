#pragma once
/// @file
/// `rig sweep SPEC.toml [--workers N] [--out DIR] [--slurm] [--keep-logs] [--fail-on-kpi]`
/// (docs/sweeps.md): expands the spec into runs, checks that every value loads (exit 2 before
/// any run otherwise), writes DIR/plan.json, runs them locally or as a Slurm job array, and
/// writes DIR/campaign.csv, DIR/junit.xml and DIR/plots/. `--task I` is one array task (what
/// the sbatch script runs); `--collect` only gathers DIR's results again.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace rig::sweep {

struct SweepOptions {
  std::string spec;
  int workers = 0;  ///< 0: this machine's CPUs (with --slurm: no limit on the running tasks)
  std::string out;  ///< "" : out/sweep-NAME
  bool slurm = false;
  bool keep_logs = false;
  bool fail_on_kpi = false;
  bool collect = false;
  bool no_plots = false;
  std::optional<long long> task;
};

/// Checks SPEC as `rig sweep` does before any run (strict spec, every run's configuration with
/// each axis value loaded); throws what is wrong (ConfigError, or naming the run). Returns the
/// number of runs. `rig check` uses it for the sweep kind.
std::size_t check_sweep_spec(const std::filesystem::path& spec);

/// The exit code: 0 every run ended as asked; 1 a run did not (or never ran); 3 with
/// --fail-on-kpi a KPI failed; 2 a bad spec, value or command line (before any run).
int sweep_command(const SweepOptions& options);

}  // namespace rig::sweep
