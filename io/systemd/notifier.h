#pragma once
/// @file
/// systemd integration (sd_notify): READY=1, STATUS=, WATCHDOG=1 only while the loop makes
/// progress, STOPPING=1. Without NOTIFY_SOCKET every call is a no-op. Non-RT thread only.

#include <cstdint>
#include <string>

namespace rig::io::systemd {

class SystemdNotifier {
 public:
  /// Reads NOTIFY_SOCKET and WATCHDOG_USEC (sd_watchdog_enabled).
  SystemdNotifier();

  void ready();
  void status(const std::string& text);
  void stopping();

  /// Watchdog period requested by the service manager [ns], 0 if none.
  [[nodiscard]] std::int64_t watchdog_ns() const noexcept { return watchdog_ns_; }
  /// Interval at which pings are due: half the watchdog period.
  [[nodiscard]] std::int64_t ping_interval_ns() const noexcept { return watchdog_ns_ / 2; }

  /// Call often (at least every ping_interval/2). Sends WATCHDOG=1 when a ping is due AND
  /// `loop_cycles` advanced since the last ping; a stalled loop therefore stops the pings and
  /// systemd restarts the service. Returns true if a ping was sent.
  bool maybe_ping(std::uint64_t loop_cycles, std::int64_t now_ns);
  /// Pings withheld so far because the loop had not advanced.
  [[nodiscard]] std::uint64_t withheld() const noexcept { return withheld_; }

 private:
  std::int64_t watchdog_ns_ = 0;
  std::int64_t last_ping_ns_ = 0;
  std::uint64_t last_cycles_ = 0;
  std::uint64_t withheld_ = 0;
  bool withholding_ = false;
};

}  // namespace rig::io::systemd
