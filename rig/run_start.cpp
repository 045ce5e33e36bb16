#include "rig/run_start.h"

#include <iostream>
#include <stdexcept>
#include <string>

namespace rig {
namespace {

void stop_before_start(Executive& exec) {
  exec.request_stop();
  exec.go();
  exec.join();
}

/// Logs the RT outcome; warns once on stderr. Returns whether SCHED_FIFO and mlockall were
/// granted.
bool report_rt_outcome(const Executive& exec, EventLog& log, const ExecutiveParams& params,
                       const RunOptions& options, const rt::SetupResult& dma, rt::Clock& wall) {
  const io::RunInfo& info = exec.run_info();
  const bool pinned = params.cpu < 0 || info.cpu == params.cpu;  // --cpu / [rig] cpu
  log.event(wall.realtime_ns(), wall.now_ns(), "cpu_dma_latency",
            dma.ok ? "held at 0 us" : "not available (no permission)");
  const std::string rt =
      std::string("SCHED_FIFO ") + (info.sched_fifo ? "granted" : "REFUSED") + " (priority " +
      std::to_string(params.priority) + "), mlockall " +
      (info.memory_locked ? "granted" : "REFUSED") + ", cpu " + std::to_string(info.cpu) +
      (pinned ? "" : " (pinning to CPU " + std::to_string(params.cpu) + " REFUSED)");
  const bool rt_ok = info.sched_fifo && info.memory_locked && pinned;
  log.event(wall.realtime_ns(), wall.now_ns(), rt_ok ? "rt_granted" : "rt_refused", rt);
  if (!rt_ok) {
    std::cerr << "rig: warning: real-time settings refused: " << rt << " (" << exec.rt_problems()
              << ")" << (options.require_rt ? "" : "; running without them (timing is best effort)")
              << "\n";
  } else if (!exec.rt_problems().empty()) {
    std::cerr << "rig: warning: real-time set-up: " << exec.rt_problems() << "\n";
  }
  return rt_ok;
}

}  // namespace

bool start_real_time(Executive& exec, EventLog& log, const ExecutiveParams& params,
                     const RunOptions& options, rt::CpuDmaLatency& dma_latency, rt::Clock& wall) {
  try {
    (void)exec.prepare(options.config_file);
  } catch (const std::exception& e) {
    std::cerr << "rig: " << e.what() << "\n";
    stop_before_start(exec);
    return false;
  }
  // The loop thread waits for go(): log the start and the RT outcome first (one producer).
  log.event(wall.realtime_ns(), wall.now_ns(), "start",
            "config " + options.config_file + ", period " + std::to_string(params.period_s) +
                " s, policy " + exec.run_info().policy + (params.offline ? ", offline" : ""));
  if (params.offline) {
    if (!exec.rt_problems().empty())
      std::cerr << "rig: warning: real-time set-up: " << exec.rt_problems() << "\n";
    return true;
  }
  const rt::SetupResult dma = dma_latency.hold();
  if (report_rt_outcome(exec, log, params, options, dma, wall) || !options.require_rt) return true;
  std::cerr << "rig: --require-rt: giving up (grant CAP_SYS_NICE and CAP_IPC_LOCK, or "
               "LimitRTPRIO/LimitMEMLOCK)\n";
  stop_before_start(exec);
  log.event(wall.realtime_ns(), wall.now_ns(), "stop",
            "real-time settings refused with --require-rt");
  log.stop();
  return false;
}

}  // namespace rig
