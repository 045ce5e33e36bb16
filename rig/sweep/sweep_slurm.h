#pragma once
/// @file
/// `rig sweep --slurm`: the plan's runs as a Slurm job array. The sbatch script DIR/sweep.sbatch
/// runs `rig sweep SPEC --out DIR --task $SLURM_ARRAY_TASK_ID` (task i: runs i K .. i K + K - 1,
/// K = [slurm] runs_per_task); it is submitted with `sbatch --parsable`, and the sweep waits
/// until squeue lists none of the array's tasks, then collects. The rig executable, the spec,
/// the configurations and DIR must be at the same paths on the nodes (a shared file system).

#include <string>

#include "rig/sweep/sweep_plan.h"

namespace rig::sweep {

/// The number of array tasks (runs / runs_per_task, rounded up).
std::size_t slurm_tasks(const Plan& plan);

/// The sbatch script; `max_parallel` > 0 limits the tasks running at once (`%N`).
std::string sbatch_script(const Plan& plan, int max_parallel);

/// Writes DIR/sweep.sbatch, submits it and waits for the array to end (on a stop signal:
/// scancel, then waits). Returns the job id; throws std::runtime_error if sbatch fails.
std::string run_slurm(const Plan& plan, int max_parallel);

/// `--task I`: runs the array task's runs one after another; the largest exit code.
int run_slurm_task(const Plan& plan, std::size_t task);

}  // namespace rig::sweep
