#include "rig/run.h"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "io/config/config_error.h"
#include "io/log/event_log.h"
#include "io/systemd/notifier.h"
#include "rig/executive.h"
#include "rig/model_factory.h"
#include "rig/summary.h"

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

/// Holds /dev/cpu_dma_latency at 0 us for the run (as cyclictest does): keeps the CPUs out of
/// deep idle states whose exit latency would show up as wake-up lateness. Released on close.
class CpuDmaLatency {
 public:
  CpuDmaLatency() {
    fd_ = ::open("/dev/cpu_dma_latency", O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) return;
    const std::int32_t zero = 0;
    if (::write(fd_, &zero, sizeof zero) != static_cast<ssize_t>(sizeof zero)) {
      ::close(fd_);
      fd_ = -1;
    }
  }
  ~CpuDmaLatency() {
    if (fd_ >= 0) ::close(fd_);
  }
  CpuDmaLatency(const CpuDmaLatency&) = delete;
  CpuDmaLatency& operator=(const CpuDmaLatency&) = delete;
  [[nodiscard]] bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace

int run(const RunOptions& options) {
  install_signal_handlers();
  RigConfig config;
  std::vector<std::unique_ptr<io::CycleIo>> io_owned;
  std::vector<std::unique_ptr<io::SnapshotSink>> sinks_owned;
  std::unique_ptr<model::SteppedModel> model;
  std::unique_ptr<driver::Driver> driver;
  try {
    config = load_config(options.config_file);
    io_owned = make_io(config, options);
    sinks_owned = make_sinks(config, options);
    model = make_model(config);
    driver = make_driver(config);
  } catch (const io::config::ConfigError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rig: " << e.what() << "\n";
    return 1;
  }

  std::unique_ptr<io::log::EventLog> log;
  try {
    log = std::make_unique<io::log::EventLog>(options.overrun_log);
  } catch (const std::exception& e) {
    std::cerr << "rig: " << e.what() << "\n";
    return 1;
  }

  ExecutiveParams p;
  p.period_s = config.rig.period_s;
  p.duration_s = options.duration_s ? *options.duration_s : config.rig.duration_s;
  p.offline = options.offline;
  p.policy = config.rig.policy;
  p.abort_after = config.rig.abort_after;
  p.priority = options.priority ? *options.priority : config.rig.priority;
  p.cpu = options.cpu ? *options.cpu : config.rig.cpu;
  p.stall_cycle = options.stall_cycle;
  p.stall_ms = options.stall_ms;

  MonotonicClock wall;
  VirtualClock virtual_clock;
  Clock& loop_clock =
      options.offline ? static_cast<Clock&>(virtual_clock) : static_cast<Clock&>(wall);
  std::vector<io::CycleIo*> io;
  for (auto& a : io_owned) io.push_back(a.get());
  std::vector<io::SnapshotSink*> sinks;
  for (auto& s : sinks_owned) sinks.push_back(s.get());

  const std::int64_t wall_start = wall.now_ns();
  Executive exec(p, loop_clock, *model, driver.get(), io, sinks, *log, config.routing);
  g_executive.store(&exec);
  if (g_signal != 0) exec.request_stop();

  io::RunInfo info;
  try {
    info = exec.prepare(options.config_file);
  } catch (const std::exception& e) {
    std::cerr << "rig: " << e.what() << "\n";
    exec.request_stop();
    exec.go();
    exec.join();
    return 1;
  }
  // The loop thread waits for go(): log the start and the RT outcome first (one producer).
  log->start();
  log->event(wall.realtime_ns(), wall.now_ns(), "start",
             "config " + options.config_file + ", period " + std::to_string(p.period_s) +
                 " s, policy " + info.policy + (p.offline ? ", offline" : ""));
  bool rt_ok = true;
  std::unique_ptr<CpuDmaLatency> dma_latency;
  if (!p.offline) {
    dma_latency = std::make_unique<CpuDmaLatency>();
    log->event(wall.realtime_ns(), wall.now_ns(), "cpu_dma_latency",
               dma_latency->held() ? "held at 0 us" : "not available (no permission)");
    const std::string rt = std::string("SCHED_FIFO ") + (info.sched_fifo ? "granted" : "REFUSED") +
                           " (priority " + std::to_string(p.priority) + "), mlockall " +
                           (info.memory_locked ? "granted" : "REFUSED") + ", cpu " +
                           std::to_string(info.cpu);
    rt_ok = info.sched_fifo && info.memory_locked;
    log->event(wall.realtime_ns(), wall.now_ns(), rt_ok ? "rt_granted" : "rt_refused", rt);
    if (!rt_ok) {
      std::cerr << "rig: warning: real-time settings refused: " << rt
                << (options.require_rt ? "" : "; running without them (timing is best effort)")
                << "\n";
    }
  }
  if (!rt_ok && options.require_rt) {
    std::cerr << "rig: --require-rt: giving up (grant CAP_SYS_NICE and CAP_IPC_LOCK, or "
                 "LimitRTPRIO/LimitMEMLOCK)\n";
    exec.request_stop();
    exec.go();
    exec.join();
    log->event(wall.realtime_ns(), wall.now_ns(), "stop",
               "real-time settings refused with --require-rt");
    log->stop();
    return 1;
  }

  io::systemd::SystemdNotifier notifier;
  exec.go();
  notifier.ready();

  // Supervisor: watchdog while the loop progresses, periodic status.
  const std::int64_t status_ns = static_cast<std::int64_t>(config.rig.status_interval_s * 1e9);
  std::int64_t next_status = wall.now_ns() + status_ns;
  std::int64_t poll_ns = 50'000'000;
  if (notifier.watchdog_ns() > 0) poll_ns = std::min(poll_ns, notifier.ping_interval_ns() / 4);
  std::uint64_t withheld_reported = 0;
  while (!exec.finished()) {
    std::this_thread::sleep_for(std::chrono::nanoseconds(poll_ns));
    const std::int64_t now = wall.now_ns();
    notifier.maybe_ping(exec.cycles(), now);
    if (notifier.withheld() != withheld_reported) {
      withheld_reported = notifier.withheld();
      std::cerr << "rig: loop stalled at cycle " << exec.cycles() << ": watchdog ping withheld\n";
    }
    if (now >= next_status) {
      const std::string line = summary_line(exec);
      std::cerr << "rig: " << line << "\n";
      notifier.status(line);
      next_status = now + status_ns;
    }
  }
  notifier.stopping();
  const StopReason reason = exec.join();
  g_executive.store(nullptr);

  int exit_code = 0;
  std::string message;
  switch (reason) {
    case StopReason::kAbortAfter:
      exit_code = 1;
      message = "aborted after " + std::to_string(p.abort_after) + " consecutive deadline misses";
      break;
    case StopReason::kNonFinite:
      exit_code = 1;
      message = "the model produced a non-finite value (NaN/inf) at t = " +
                std::to_string(exec.sim_time_s()) + " s; stopped";
      break;
    default:
      break;
  }
  log->event(wall.realtime_ns(), wall.now_ns(), "stop",
             std::string("reason ") + stop_reason_name(reason) + ", cycles " +
                 std::to_string(exec.cycles()) + ", misses " +
                 std::to_string(exec.deadline_misses()));
  log->stop();

  SummaryExtras extras;
  extras.wall_time_s = static_cast<double>(wall.now_ns() - wall_start) * 1e-9;
  extras.stop_reason = stop_reason_name(reason);
  extras.exit_code = exit_code;
  extras.events_lost = log->lost();
  std::cerr << summary_report(exec, extras);
  notifier.status(summary_line(exec));
  if (!options.summary_json.empty()) {
    std::ofstream out(options.summary_json);
    out << summary_json(exec, extras);
    if (!out) {
      std::cerr << "rig: cannot write " << options.summary_json << "\n";
      exit_code = 1;
    }
  }
  if (!message.empty()) std::cerr << "rig: error: " << message << "\n";
  return exit_code;
}

}  // namespace rig
