#include "tests/io/can/vcan/vcan_support.h"

#include <fcntl.h>
#include <net/if.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "io/can/transport/socket_can_transport.h"

extern char** environ;

namespace rig::test {

std::string vcan_unavailable_reason() {
  std::string why;
  if (!io::can::transport::can_sockets_available(&why)) return why;
  for (const char* name : {"vcan0", "vcan1"}) {
    if (if_nametoindex(name) == 0) return std::string("no interface ") + name;
  }
  return {};
}

bool vcan_required() {
  const char* v = std::getenv("RIG_VCAN_REQUIRED");
  return v != nullptr && std::string(v) == "1";
}

std::int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

std::int64_t realtime_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

void sleep_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

int sh(const std::string& command) {
  const int st = std::system(command.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

std::string source_dir() { return RIG_SOURCE_DIR; }

Child::Child(const std::string& command) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  // exec: the pid is the command itself, so terminate() reaches it.
  const std::string line = "exec " + command;
  const char* argv[] = {"/bin/sh", "-c", line.c_str(), nullptr};
  if (posix_spawn(&pid_, "/bin/sh", &actions, nullptr, const_cast<char**>(argv), environ) != 0) {
    pid_ = -1;
  }
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  fd_ = fds[0];
  fcntl(fd_, F_SETFL, O_NONBLOCK);
}

Child::~Child() {
  if (pid_ > 0 && !exited_) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (fd_ >= 0) close(fd_);
}

void Child::poll() {
  char buf[4096];
  for (;;) {
    const ssize_t n = read(fd_, buf, sizeof(buf));
    if (n <= 0) break;
    partial_.append(buf, static_cast<std::size_t>(n));
  }
  std::size_t pos = 0;
  for (std::size_t nl; (nl = partial_.find('\n', pos)) != std::string::npos; pos = nl + 1) {
    lines_.push_back(partial_.substr(pos, nl - pos));
  }
  partial_.erase(0, pos);
}

bool Child::wait_for_line(const std::function<bool(const std::string&)>& pred, int timeout_ms) {
  const std::int64_t end = monotonic_ns() + std::int64_t{timeout_ms} * 1'000'000;
  for (;;) {
    poll();
    for (; checked_ < lines_.size(); ++checked_) {
      if (pred(lines_[checked_])) {
        ++checked_;
        return true;
      }
    }
    if (monotonic_ns() > end) return false;
    sleep_ms(2);
  }
}

int Child::wait(int timeout_ms) {
  if (exited_) return status_;
  const std::int64_t end = monotonic_ns() + std::int64_t{timeout_ms} * 1'000'000;
  int st = 0;
  for (;;) {
    poll();
    const pid_t r = waitpid(pid_, &st, WNOHANG);
    if (r == pid_) break;
    if (monotonic_ns() > end) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &st, 0);
      break;
    }
    sleep_ms(5);
  }
  poll();
  exited_ = true;
  status_ = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return status_;
}

bool Child::exited() {
  if (exited_) return true;
  poll();
  int st = 0;
  if (waitpid(pid_, &st, WNOHANG) != pid_) return false;
  poll();
  exited_ = true;
  status_ = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return true;
}

int Child::terminate() {
  if (!exited_) kill(pid_, SIGTERM);
  return wait(5000);
}

}  // namespace rig::test
