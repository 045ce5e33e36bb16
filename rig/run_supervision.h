#pragma once
/// @file
/// `rig run`, supervision (the main thread while the loop runs): systemd watchdog pings while
/// the loop makes progress, the stall report, the periodic status line. It sleeps until the
/// loop finishes or the next ping or status is due, so a run ends as soon as its loop does.

#include "io/systemd/notifier.h"
#include "rig/executive.h"
#include "rig/rt/clock.h"

namespace rig {

/// Returns when the loop has finished.
void supervise(Executive& exec, io::systemd::SystemdNotifier& notifier, double status_interval_s,
               rt::Clock& wall);

}  // namespace rig
