#pragma once
/// @file
/// The rig's signal handling, installed first thing in main() (before the command line is even
/// parsed), so that no signal in the first milliseconds kills the rig without its logs:
///   SIGINT, SIGTERM, SIGHUP (a dropped SSH session): stop cleanly (exit 0, complete logs);
///   SIGPIPE: ignored (a closed pipe or socket is an error return, not death);
///   SIGUSR1: print the status line (on stderr, by the supervising main thread).
/// The handlers only set flags and ask the executive to stop (async-signal-safe). The four are
/// unblocked if the rig inherited them blocked; one already pending then counts at once.

namespace rig {

class Executive;

void install_signal_handlers();

/// The executive a stop signal stops (nullptr: none yet; the signal is remembered).
void set_signal_target(Executive* exec);
/// A stop signal (SIGINT, SIGTERM or SIGHUP) arrived: its number, else 0.
[[nodiscard]] int stop_signal();
/// True once per SIGUSR1 received since the last call.
[[nodiscard]] bool take_status_request();

}  // namespace rig
