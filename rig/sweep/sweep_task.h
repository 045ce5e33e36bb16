#pragma once
/// @file
/// One run of a sweep, as a local worker's child process or a Slurm array task runs it.

#include <cstddef>
#include <filesystem>

#include "rig/sweep/sweep_plan.h"

namespace rig::sweep {

/// Runs run `index` of the plan: creates DIR/runs/ID/, runs `rig run` there (stdout and stderr
/// in rig.log), then writes status.json ({"id", "exit_code", "wall_time_s", "started", "host"},
/// renamed
/// into place whole, so a reader never sees half of it); with keep_logs also csv/ (rig-log2csv)
/// and figures/ (scripts/plot log). Returns the run's exit code (128 + a signal that killed it;
/// 1 if it could not be started).
int run_task(const Plan& plan, std::size_t index);

/// The folder of scripts/plot: $RIG_SCRIPTS_DIR, else <bin>/../share/rig/scripts, else the
/// source tree's scripts/ (a build tree); "" if none has it.
std::filesystem::path scripts_dir(const std::filesystem::path& rig_exe);

}  // namespace rig::sweep
