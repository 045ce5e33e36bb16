#include "rig/stderr_relay.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <iostream>
#include <mutex>
#include <thread>

#include "rig/signals.h"

namespace rig {

struct StderrRelay::Shared {
  int read_fd = -1;
  int real_stderr = -1;
  std::mutex mutex;
  std::condition_variable done_cv;
  bool done = false;
};

namespace {

constexpr int kPipeBytes = 1 << 20;

/// Copies the pipe to the real stderr until the pipe's write end is closed.
void copy_until_closed(int from, int to) {
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(from, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    for (ssize_t done = 0; done < n;) {
      const ssize_t w = ::write(to, buf + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) break;  // the real stderr is gone: drop the rest of this piece
      done += w;
    }
  }
}

}  // namespace

StderrRelay::StderrRelay() {
  if (::fcntl(2, F_GETFD) < 0) return;  // no stderr at all: the pipe must not become fd 2
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return;
  (void)::fcntl(fds[1], F_SETPIPE_SZ, kPipeBytes);  // best effort: 64 KiB otherwise
  const int real = ::fcntl(2, F_DUPFD_CLOEXEC, 3);
  if (real < 0 || ::fcntl(fds[1], F_SETFL, O_NONBLOCK) != 0 || ::dup2(fds[1], 2) < 0) {
    for (const int fd : {fds[0], fds[1], real})
      if (fd >= 0) ::close(fd);
    return;
  }
  ::close(fds[1]);  // fd 2 is the only write end now
  shared_ = new Shared;
  shared_->read_fd = fds[0];
  shared_->real_stderr = real;
  start_thread([s = shared_] {
    copy_until_closed(s->read_fd, s->real_stderr);
    const std::lock_guard<std::mutex> lock(s->mutex);
    s->done = true;
    s->done_cv.notify_all();
  }).detach();
}

StderrRelay::~StderrRelay() {
  if (shared_ == nullptr) return;
  std::cerr.flush();
  // Close the pipe's write end (fd 2 becomes /dev/null): the copy ends after what is left.
  const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null_fd >= 0) {
    ::dup2(null_fd, 2);
    ::close(null_fd);
  }
  std::unique_lock<std::mutex> lock(shared_->mutex);
  const bool done = shared_->done_cv.wait_for(lock, std::chrono::nanoseconds(kFinishWait_ns),
                                              [this] { return shared_->done; });
  if (!done) return;  // the real stderr is not read: leave the thread (and Shared) to the exit
  lock.unlock();
  ::dup2(shared_->real_stderr, 2);
  ::close(shared_->real_stderr);
  ::close(shared_->read_fd);
  delete shared_;
  std::cerr.clear();  // a write refused while the pipe was full set badbit
}

}  // namespace rig
