#pragma once
/// @file
/// Real-time set-up of the process and of the calling thread. Each call returns {ok, message}:
/// the caller decides and warns once (no privilege is normal on a development machine).
/// Depends on nothing of the project.

#include <cstdint>
#include <string>

namespace rig::rt {

struct SetupResult {
  bool ok = false;
  std::string message;  ///< why not, e.g. "mlockall: Operation not permitted"; empty if ok
};

/// mlockall(MCL_CURRENT | MCL_FUTURE): no page faults on the loop thread later.
SetupResult lock_memory();
/// SCHED_FIFO at `priority` for the calling thread.
SetupResult set_sched_fifo(int priority);
/// Pins the calling thread to `cpu`.
SetupResult set_cpu_affinity(int cpu);
/// The CPUs this machine has (configured, online or not; isolated ones included): a CPU index
/// for set_cpu_affinity must be below it.
int cpu_count() noexcept;
/// The calling thread's timer slack (1 ns: absolute sleeps wake on time, not up to 50 us late).
SetupResult set_timer_slack(std::uint64_t slack_ns);

/// Holds /dev/cpu_dma_latency at 0 us while alive (as cyclictest does): keeps the CPUs out of
/// deep idle states whose exit latency would show up as wake-up lateness. Released on close.
class CpuDmaLatency {
 public:
  CpuDmaLatency() = default;
  ~CpuDmaLatency();
  CpuDmaLatency(const CpuDmaLatency&) = delete;
  CpuDmaLatency& operator=(const CpuDmaLatency&) = delete;

  SetupResult hold();
  [[nodiscard]] bool held() const noexcept { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace rig::rt
