#include "io/systemd/notifier.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <systemd/sd-daemon.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace rig::io::systemd {
namespace {

std::int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

/// A non-blocking datagram socket connected to NOTIFY_SOCKET, or -1.
int connect_notify_socket(const std::string& name) {
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  if (name.empty() || name.size() >= sizeof addr.sun_path) return -1;
  std::memcpy(addr.sun_path, name.data(), name.size());
  if (name[0] == '@') addr.sun_path[0] = '\0';  // an abstract socket
  const auto len = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + name.size());
  const int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) return -1;
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&addr), len) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

SystemdNotifier::SystemdNotifier() {
  std::uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0) watchdog_ns_ = static_cast<std::int64_t>(usec) * 1000;
  if (const char* name = std::getenv("NOTIFY_SOCKET"); name != nullptr) {
    socket_name_ = name;
    fd_ = connect_notify_socket(socket_name_);
  }
}

SystemdNotifier::~SystemdNotifier() {
  if (fd_ >= 0) ::close(fd_);
}

void SystemdNotifier::send(const std::string& message, std::int64_t wait_ns) {
  if (socket_name_.empty()) return;
  const std::int64_t give_up_ns = steady_ns() + wait_ns;
  while (fd_ >= 0) {
    if (::send(fd_, message.data(), message.size(), MSG_DONTWAIT | MSG_NOSIGNAL) >= 0) {
      full_ = false;
      return;
    }
    if (errno == EINTR) continue;
    const std::int64_t left_ns = give_up_ns - steady_ns();
    if ((errno != EAGAIN && errno != EWOULDBLOCK) || left_ns <= 0) break;
    pollfd p{fd_, POLLOUT, 0};
    if (::poll(&p, 1, static_cast<int>(left_ns / 1'000'000) + 1) <= 0) break;
  }
  full_ = true;
  ++dropped_;
}

void SystemdNotifier::ready() { send("READY=1", kFinalWait_ns); }
void SystemdNotifier::stopping() { send("STOPPING=1", kFinalWait_ns); }
void SystemdNotifier::status(const std::string& text) {
  send("STATUS=" + text, full_ ? 0 : kWait_ns);
}

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
  send("WATCHDOG=1", full_ ? 0 : kWait_ns);
  return true;
}

}  // namespace rig::io::systemd
