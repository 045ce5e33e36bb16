#include "io/systemd/notifier.h"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace rig::io::systemd {
namespace {

/// A notify socket bound at an abstract address, as systemd's; `fill` leaves its queue full.
class NotifySocket {
 public:
  explicit NotifySocket(bool fill) {
    name_ = "@rig-notifier-test-" + std::to_string(::getpid()) + (fill ? "-full" : "");
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::memcpy(addr.sun_path + 1, name_.data() + 1, name_.size() - 1);
    const auto len = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + name_.size());
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    EXPECT_EQ(::bind(fd_, reinterpret_cast<const sockaddr*>(&addr), len), 0);
    if (fill) {
      const int filler = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
      EXPECT_EQ(::connect(filler, reinterpret_cast<const sockaddr*>(&addr), len), 0);
      while (::send(filler, "X=1", 3, 0) == 3) {
      }
      ::close(filler);
    }
    ::setenv("NOTIFY_SOCKET", name_.c_str(), 1);
  }
  ~NotifySocket() {
    ::unsetenv("NOTIFY_SOCKET");
    ::close(fd_);
  }
  NotifySocket(const NotifySocket&) = delete;
  NotifySocket& operator=(const NotifySocket&) = delete;
  std::string receive() {
    char buf[256];
    const ssize_t n = ::recv(fd_, buf, sizeof buf, MSG_DONTWAIT);
    return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "";
  }

 private:
  std::string name_;
  int fd_ = -1;
};

TEST(SystemdNotifier, SendsToAnAbstractSocket) {
  NotifySocket socket(false);
  SystemdNotifier notifier;
  notifier.ready();
  notifier.status("cycles 1");
  notifier.stopping();
  EXPECT_EQ(socket.receive(), "READY=1");
  EXPECT_EQ(socket.receive(), "STATUS=cycles 1");
  EXPECT_EQ(socket.receive(), "STOPPING=1");
  EXPECT_EQ(notifier.dropped(), 0u);
}

// A socket nobody reads blocked sd_notify forever: now each message is dropped after a bounded
// wait (returning at all is the test) and counted.
TEST(SystemdNotifier, AFullSocketDropsAndCountsInsteadOfBlocking) {
  NotifySocket socket(true);
  SystemdNotifier notifier;
  notifier.ready();
  for (int i = 0; i < 100; ++i) notifier.status("cycles " + std::to_string(i));
  notifier.stopping();
  EXPECT_EQ(notifier.dropped(), 102u);
  EXPECT_EQ(socket.receive(), "X=1");  // what filled it is still there, nothing of ours
}

}  // namespace
}  // namespace rig::io::systemd
