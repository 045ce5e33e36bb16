#pragma once
/// @file
/// `rig run`, real-time start: prepares the executive (sinks, loop thread with its RT settings,
/// dispatcher), holds cpu_dma_latency in real time, logs the start and the RT outcome and warns
/// once about what was refused. The loop itself starts with Executive::go().

#include "rig/event_log.h"
#include "rig/executive.h"
#include "rig/rt/clock.h"
#include "rig/rt/thread_setup.h"
#include "rig/run_options.h"

namespace rig {

/// False if the run must end here with exit code 1 (prepare failed, or --require-rt and the RT
/// settings were refused); the executive is then stopped and joined, and the stop logged.
bool start_real_time(Executive& exec, EventLog& log, const ExecutiveParams& params,
                     const RunOptions& options, rt::CpuDmaLatency& dma_latency, rt::Clock& wall);

}  // namespace rig
