#include "rig/run_supervision.h"

#include <algorithm>
#include <iostream>
#include <string>

#include "rig/signals.h"
#include "rig/summary.h"

namespace rig {

void supervise(Executive& exec, io::systemd::SystemdNotifier& notifier, double status_interval_s,
               rt::Clock& wall) {
  const auto status_ns = static_cast<std::int64_t>(status_interval_s * 1e9);
  std::int64_t next_status_ns = wall.now_ns() + status_ns;
  // Often enough for the watchdog (pings are due every half period) and the stall report.
  std::int64_t wake_ns = 50'000'000;
  if (notifier.watchdog_ns() > 0) wake_ns = std::min(wake_ns, notifier.ping_interval_ns() / 4);
  std::uint64_t withheld_reported = 0;
  while (!exec.finished()) {
    exec.wait_finished(wake_ns);
    const std::int64_t now_ns = wall.now_ns();
    notifier.maybe_ping(exec.cycles(), now_ns);
    if (notifier.withheld() != withheld_reported) {
      withheld_reported = notifier.withheld();
      std::cerr << "rig: loop stalled at cycle " << exec.cycles() << ": watchdog ping withheld\n";
    }
    std::cerr.clear();  // a line dropped by a full stderr (rig/stderr_relay.h) set badbit
    if (take_status_request()) std::cerr << "rig: " << summary_line(exec) << "\n";  // SIGUSR1
    if (now_ns >= next_status_ns) {
      const std::string line = summary_line(exec);
      std::cerr << "rig: " << line << "\n";
      notifier.status(line);
      next_status_ns = now_ns + status_ns;
    }
  }
}

}  // namespace rig
