#include "rig/rt/clock.h"

#include <cerrno>
#include <ctime>

namespace rig::rt {
namespace {
std::int64_t read(clockid_t id) noexcept {
  timespec ts{};
  clock_gettime(id, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}
}  // namespace

std::int64_t MonotonicClock::now_ns() noexcept { return read(CLOCK_MONOTONIC); }
std::int64_t MonotonicClock::realtime_ns() noexcept { return read(CLOCK_REALTIME); }

void MonotonicClock::sleep_until(std::int64_t deadline_ns) noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

}  // namespace rig::rt
