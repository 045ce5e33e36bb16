#pragma once
/// @file
/// The rig's signal handling, installed first thing in main() (before the command line is even
/// parsed), so that no signal in the first milliseconds kills the rig without its logs:
///   SIGINT, SIGTERM, SIGHUP (a dropped SSH session): stop cleanly (exit 0, complete logs);
///   SIGPIPE: ignored (a closed pipe or socket is an error return, not death);
///   SIGUSR1: print the status line (on stderr, by the supervising main thread).
/// The handlers only set flags and ask the executive to stop (async-signal-safe). The four are
/// unblocked if the rig inherited them blocked; one already pending then counts at once.

#include <pthread.h>

#include <csignal>
#include <thread>
#include <utility>

namespace rig {

class Executive;

/// The signals the rig handles: INT, TERM, HUP (stop) and USR1 (status line).
inline sigset_t rig_signals() noexcept {
  sigset_t set;
  sigemptyset(&set);
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGUSR1}) sigaddset(&set, s);
  return set;
}

/// While alive, the calling thread blocks the rig's signals; a thread started meanwhile inherits
/// that mask. (Header only: the combination's worker, rig/thread_begin_step_runner.h, uses it.)
class SignalsBlocked {
 public:
  SignalsBlocked() noexcept {
    const sigset_t set = rig_signals();
    pthread_sigmask(SIG_BLOCK, &set, &previous_);
  }
  ~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  SignalsBlocked(const SignalsBlocked&) = delete;
  SignalsBlocked& operator=(const SignalsBlocked&) = delete;

 private:
  sigset_t previous_{};
};

/// Every thread of the rig starts here: with the rig's signals blocked, so that their handlers
/// run on the main thread only - never on the real-time loop (whose sleep a signal would cut
/// short) or a worker.
template <class F>
std::thread start_thread(F&& f) {
  const SignalsBlocked blocked;
  return std::thread(std::forward<F>(f));
}

void install_signal_handlers();

/// The executive a stop signal stops (nullptr: none yet; the signal is remembered).
void set_signal_target(Executive* exec);
/// A stop signal (SIGINT, SIGTERM or SIGHUP) arrived: its number, else 0.
[[nodiscard]] int stop_signal();
/// True once per SIGUSR1 received since the last call.
[[nodiscard]] bool take_status_request();

}  // namespace rig
