#pragma once
/// @file
/// An event count: a thread sleeps until another has changed a state it watches, without a lock
/// and without polling. notify() costs a fence and a load while nobody waits (no syscall), and
/// one futex wake-up per wait however often it is called; wait() sleeps in the kernel. One
/// waiting thread at a time, any number of notifiers. Depends on nothing of the project.
///
///     waiter:    for (;;) { const auto key = ec.prepare_wait();
///                           if (ready()) { ec.cancel_wait(); break; }
///                           ec.wait(key, timeout_ns); }
///     notifier:  make ready() true; ec.notify();
///
/// Both sides re-check after announcing themselves (a fence each), so a wake-up is never lost.

#include <atomic>
#include <cstdint>

namespace rig::rt {

class EventCount {
 public:
  /// Waiter: announces the wait; returns the key for wait(). Then re-check the state.
  std::uint32_t prepare_wait() noexcept;
  /// Waiter: the state was ready after all.
  void cancel_wait() noexcept;
  /// Waiter: sleeps until a notify() after prepare_wait(), or at most `timeout_ns`. May return
  /// early: the caller re-checks its state.
  void wait(std::uint32_t key, std::int64_t timeout_ns) noexcept;
  /// Notifier (any thread, also a signal handler): wakes the announced waiter, once.
  void notify() noexcept;

 private:
  std::atomic<std::uint32_t> epoch_{0};
  std::atomic<std::uint32_t> armed_{0};  ///< a waiter announced itself and was not woken yet
};

}  // namespace rig::rt
