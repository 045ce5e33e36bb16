#pragma once
/// @file
/// systemd integration (the sd_notify protocol): READY=1, STATUS=, WATCHDOG=1 only while the
/// loop makes progress, STOPPING=1. Without NOTIFY_SOCKET every call is a no-op. Non-RT thread
/// only.
///
/// The socket is non-blocking: a notify socket that is not read (its queue full: 10 datagrams by
/// default, net.unix.max_dgram_qlen) never holds the rig. STATUS= and WATCHDOG=1 wait at most
/// kWait_ns for room (none while the socket has been found full), READY=1 and STOPPING=1 at
/// most kFinalWait_ns; what does not fit is dropped and counted (dropped()).

#include <cstdint>
#include <string>

namespace rig::io::systemd {

class SystemdNotifier {
 public:
  /// The longest STATUS= or WATCHDOG=1 waits for a full notify socket (a slow reader).
  static constexpr std::int64_t kWait_ns = 20'000'000;
  /// The longest READY=1 or STOPPING=1 waits.
  static constexpr std::int64_t kFinalWait_ns = 500'000'000;

  /// Reads NOTIFY_SOCKET (a path or "@abstract") and WATCHDOG_USEC (sd_watchdog_enabled).
  SystemdNotifier();
  ~SystemdNotifier();
  SystemdNotifier(const SystemdNotifier&) = delete;
  SystemdNotifier& operator=(const SystemdNotifier&) = delete;

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
  /// Messages that did not fit into a full notify socket (or whose send failed).
  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_; }
  /// NOTIFY_SOCKET as given ("" if none).
  [[nodiscard]] const std::string& socket_name() const noexcept { return socket_name_; }

 private:
  /// Sends one datagram; on a full socket waits up to `wait_ns` (0: drops it at once).
  void send(const std::string& message, std::int64_t wait_ns);

  int fd_ = -1;
  std::string socket_name_;
  std::uint64_t dropped_ = 0;
  bool full_ = false;  ///< the last send found the socket full: STATUS/WATCHDOG do not wait
  std::int64_t watchdog_ns_ = 0;
  std::int64_t last_ping_ns_ = 0;
  std::uint64_t last_cycles_ = 0;
  std::uint64_t withheld_ = 0;
  bool withholding_ = false;
};

}  // namespace rig::io::systemd
