#include "rig/rt/thread_setup.h"

#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rig::rt {
namespace {

SetupResult failed(const char* call, int error) {
  return {false, std::string(call) + ": " + std::strerror(error)};
}

}  // namespace

SetupResult lock_memory() {
  if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0) return failed("mlockall", errno);
  return {true, {}};
}

SetupResult set_sched_fifo(int priority) {
  sched_param sp{};
  sp.sched_priority = priority;
  if (const int e = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp); e != 0)
    return failed("pthread_setschedparam(SCHED_FIFO)", e);
  return {true, {}};
}

SetupResult set_cpu_affinity(int cpu) {
  if (cpu < 0 || cpu >= CPU_SETSIZE) return failed("pthread_setaffinity_np", EINVAL);
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(static_cast<std::size_t>(cpu), &set);
  if (const int e = pthread_setaffinity_np(pthread_self(), sizeof set, &set); e != 0)
    return failed("pthread_setaffinity_np", e);
  return {true, {}};
}

int cpu_count() noexcept {
  const long n = sysconf(_SC_NPROCESSORS_CONF);
  return n > 0 ? static_cast<int>(n) : 1;
}

SetupResult set_timer_slack(std::uint64_t slack_ns) {
  if (prctl(PR_SET_TIMERSLACK, static_cast<unsigned long>(slack_ns), 0UL, 0UL, 0UL) != 0)
    return failed("prctl(PR_SET_TIMERSLACK)", errno);
  return {true, {}};
}

CpuDmaLatency::~CpuDmaLatency() {
  if (fd_ >= 0) ::close(fd_);
}

SetupResult CpuDmaLatency::hold() {
  if (fd_ >= 0) return {true, {}};
  fd_ = ::open("/dev/cpu_dma_latency", O_WRONLY | O_CLOEXEC);
  if (fd_ < 0) return failed("open(/dev/cpu_dma_latency)", errno);
  const std::int32_t zero_us = 0;
  if (::write(fd_, &zero_us, sizeof zero_us) != static_cast<ssize_t>(sizeof zero_us)) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    return failed("write(/dev/cpu_dma_latency)", e);
  }
  return {true, {}};
}

}  // namespace rig::rt
