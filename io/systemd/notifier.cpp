#include "io/systemd/notifier.h"

#include <systemd/sd-daemon.h>

namespace rig::io::systemd {

SystemdNotifier::SystemdNotifier() {
  std::uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0) watchdog_ns_ = static_cast<std::int64_t>(usec) * 1000;
}

void SystemdNotifier::ready() { sd_notify(0, "READY=1"); }
void SystemdNotifier::stopping() { sd_notify(0, "STOPPING=1"); }
void SystemdNotifier::status(const std::string& text) { sd_notify(0, ("STATUS=" + text).c_str()); }

bool SystemdNotifier::maybe_ping(std::uint64_t loop_cycles, std::int64_t now_ns) {
  if (watchdog_ns_ <= 0) return false;
  if (now_ns - last_ping_ns_ < ping_interval_ns()) return false;
  if (loop_cycles == last_cycles_) {
    // The loop is stalled: withhold the ping (count each stalled interval once).
    if (!withholding_) ++withheld_;
    withholding_ = true;
    return false;
  }
  withholding_ = false;
  last_cycles_ = loop_cycles;
  last_ping_ns_ = now_ns;
  sd_notify(0, "WATCHDOG=1");
  return true;
}

}  // namespace rig::io::systemd
