#pragma once
/// @file
/// `rig sweep` on this machine: the plan's runs by a pool of worker processes.

#include <cstddef>

#include "rig/sweep/sweep_plan.h"

namespace rig::sweep {

/// Runs every run of the plan, at most `workers` at a time, each in a forked child (a process
/// group of its own) that runs run_task. Progress on stderr every 10 s. A stop signal (SIGINT,
/// SIGTERM, SIGHUP: rig/signals.h) stops the launching and sends SIGTERM to the running runs,
/// which end cleanly. Returns how many runs ended.
std::size_t run_local(const Plan& plan, int workers);

}  // namespace rig::sweep
