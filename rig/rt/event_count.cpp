#include "rig/rt/event_count.h"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <climits>
#include <ctime>

namespace rig::rt {
namespace {

static_assert(sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t) &&
                  std::atomic<std::uint32_t>::is_always_lock_free,
              "the futex word must be a plain 32-bit word");

std::uint32_t* word(std::atomic<std::uint32_t>& a) noexcept {
  return reinterpret_cast<std::uint32_t*>(&a);
}

}  // namespace

std::uint32_t EventCount::prepare_wait() noexcept {
  armed_.store(1, std::memory_order_relaxed);
  // Pairs with the fence in notify(): either the notifier sees the waiter armed, or the waiter's
  // re-check sees the notifier's state change.
  std::atomic_thread_fence(std::memory_order_seq_cst);
  return epoch_.load(std::memory_order_acquire);
}

void EventCount::cancel_wait() noexcept { armed_.store(0, std::memory_order_relaxed); }

void EventCount::wait(std::uint32_t key, std::int64_t timeout_ns) noexcept {
  if (timeout_ns < 0) timeout_ns = 0;
  timespec timeout{};
  timeout.tv_sec = static_cast<time_t>(timeout_ns / 1'000'000'000);
  timeout.tv_nsec = static_cast<long>(timeout_ns % 1'000'000'000);
  // Returns at once if a notify() already moved the epoch past `key`.
  (void)syscall(SYS_futex, word(epoch_), FUTEX_WAIT_PRIVATE, key, &timeout, nullptr, 0);
  armed_.store(0, std::memory_order_relaxed);
}

void EventCount::notify() noexcept {
  std::atomic_thread_fence(std::memory_order_seq_cst);
  // Only the first notify() after an announcement wakes: the others find the waiter disarmed.
  if (armed_.load(std::memory_order_relaxed) == 0 ||
      armed_.exchange(0, std::memory_order_relaxed) == 0)
    return;
  epoch_.fetch_add(1, std::memory_order_release);
  (void)syscall(SYS_futex, word(epoch_), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
}

}  // namespace rig::rt
