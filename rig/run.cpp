#include "rig/run.h"

#include <atomic>
#include <csignal>

#include "io/systemd/notifier.h"
#include "rig/executive.h"
#include "rig/rt/clock.h"
#include "rig/rt/thread_setup.h"
#include "rig/run_assembly.h"
#include "rig/run_finish.h"
#include "rig/run_start.h"
#include "rig/run_supervision.h"

namespace rig {
namespace {

std::atomic<Executive*> g_executive{nullptr};
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int signo) {
  g_signal = signo;
  if (Executive* e = g_executive.load()) e->request_stop();
}

void install_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

}  // namespace

int run(const RunOptions& options) {
  install_signal_handlers();
  RunParts parts;
  if (const int exit_code = assemble(options, parts); exit_code != 0) return exit_code;

  rt::MonotonicClock wall;
  rt::VirtualClock virtual_clock;
  rt::Clock& loop_clock =
      options.offline ? static_cast<rt::Clock&>(virtual_clock) : static_cast<rt::Clock&>(wall);
  const std::int64_t wall_start_ns = wall.now_ns();
  Executive exec(parts.params, loop_clock, *parts.model, parts.driver.get(), parts.io_adapters(),
                 parts.snapshot_sinks(), *parts.log, parts.config.routing.source);
  g_executive.store(&exec);
  if (g_signal != 0) exec.request_stop();

  rt::CpuDmaLatency dma_latency;  // held for the whole real-time run
  if (!start_real_time(exec, *parts.log, parts.params, options, dma_latency, wall)) {
    g_executive.store(nullptr);
    return 1;
  }
  io::systemd::SystemdNotifier notifier;
  exec.go();
  notifier.ready();
  supervise(exec, notifier, parts.config.rig.status_interval_s, wall);
  notifier.stopping();
  const StopReason reason = exec.join();
  g_executive.store(nullptr);
  return finish_run(exec, *parts.log, {reason, parts.params.abort_after, wall_start_ns}, options,
                    notifier, wall);
}

}  // namespace rig
