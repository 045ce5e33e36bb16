#include "rig/run.h"

#include "io/systemd/notifier.h"
#include "rig/executive.h"
#include "rig/rt/clock.h"
#include "rig/rt/thread_setup.h"
#include "rig/run_assembly.h"
#include "rig/run_finish.h"
#include "rig/run_start.h"
#include "rig/run_supervision.h"
#include "rig/signals.h"
#include "rig/stderr_relay.h"

namespace rig {

int run(const RunOptions& options) {
  install_signal_handlers();  // main() did already; a second time is harmless
  const StderrRelay relay;    // no stderr reader can hold the rig (rig/stderr_relay.h)
  RunParts parts;
  if (const int exit_code = assemble(options, parts); exit_code != 0) return exit_code;

  rt::MonotonicClock wall;
  rt::VirtualClock virtual_clock;
  rt::Clock& loop_clock =
      options.offline ? static_cast<rt::Clock&>(virtual_clock) : static_cast<rt::Clock&>(wall);
  const std::int64_t wall_start_ns = wall.now_ns();
  Executive exec(parts.params, loop_clock, *parts.model, parts.driver.get(), parts.io_adapters(),
                 parts.snapshot_sinks(), *parts.log, parts.config.routing.source);
  exec.set_events(parts.events.get());
  set_signal_target(&exec);  // a stop signal during assembly stops it before its first cycle

  rt::CpuDmaLatency dma_latency;  // held for the whole real-time run
  if (!start_real_time(exec, *parts.log, parts.params, options, dma_latency, wall)) {
    set_signal_target(nullptr);
    return 1;
  }
  io::systemd::SystemdNotifier notifier;
  exec.go();
  notifier.ready();
  supervise(exec, notifier, parts.config.rig.status_interval_s, wall);
  notifier.stopping();
  const StopReason reason = exec.join();
  set_signal_target(nullptr);
  const auto sinks = parts.snapshot_sinks();
  FinishInputs finish{reason,
                      parts.params.abort_after,
                      wall_start_ns,
                      {sinks.begin(), sinks.end()},
                      parts.summary.get(),
                      parts.kpis.get(),
                      parts.events.get(),
                      parts.junit.get()};
  return finish_run(exec, *parts.log, finish, options, notifier, wall);
}

}  // namespace rig
