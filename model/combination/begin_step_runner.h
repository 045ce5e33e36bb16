#pragma once
/// @file
/// The parallel option of the coupled step (issue 7): begin_step of units 1..N-1 runs elsewhere
/// while the caller runs unit 0. model/ owns no threads: the rig provides the runner
/// (rig/thread_begin_step_runner.h), with the loop thread's scheduling.

#include <functional>
#include <memory>
#include <vector>

#include "model/solver/couplable_system.h"

namespace rig::model::combination {

/// Runs begin_step of a fixed set of units. start(h) returns at once; wait() returns when all of
/// them have finished. Neither allocates.
class BeginStepRunner {
 public:
  BeginStepRunner() = default;
  BeginStepRunner(const BeginStepRunner&) = delete;
  BeginStepRunner& operator=(const BeginStepRunner&) = delete;
  virtual ~BeginStepRunner() = default;
  virtual void start(double h) noexcept = 0;
  virtual void wait() noexcept = 0;
};

/// Makes a runner for the given units (not owned); called once, at construction.
using BeginStepRunnerFactory =
    std::function<std::unique_ptr<BeginStepRunner>(std::vector<solver::CouplableSystem*>)>;

}  // namespace rig::model::combination
