#include "rig/sweep/sweep_local.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <thread>
#include <vector>

#include "rig/signals.h"
#include "rig/sweep/process.h"
#include "rig/sweep/sweep_task.h"

namespace rig::sweep {
namespace {

using Clock = std::chrono::steady_clock;

/// A worker: a forked child running one run (its own process group).
pid_t start_worker(const Plan& plan, std::size_t index) {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);  // the child must not write the parent's buffers again
  const pid_t pid = fork();
  if (pid != 0) return pid;
  setpgid(0, 0);
  const int code = run_task(plan, index);
  std::fflush(nullptr);
  _exit(code < 0 ? 1 : code > 255 ? 255 : code);
}

void progress(std::size_t done, std::size_t total, double seconds) {
  std::fprintf(stderr, "rig sweep: %zu/%zu runs done, %.1f s\n", done, total, seconds);
}

}  // namespace

std::size_t run_local(const Plan& plan, int workers) {
  const std::size_t total = plan.runs.size();
  std::vector<pid_t> running;
  std::size_t next = 0, done = 0;
  const auto start = Clock::now();
  auto last_report = start;
  bool stopping = false;
  while (next < total || !running.empty()) {
    if (!stopping && stop_signal() != 0) {
      stopping = true;
      std::cerr << "rig sweep: stopping: " << running.size() << " runs asked to end, "
                << total - next << " not started\n";
      for (const pid_t pid : running) kill(-pid, SIGTERM);
    }
    while (!stopping && next < total && running.size() < static_cast<std::size_t>(workers)) {
      const pid_t pid = start_worker(plan, next++);
      if (pid > 0) running.push_back(pid);
    }
    int status = 0;
    const pid_t ended = waitpid(-1, &status, WNOHANG);
    if (ended > 0) {
      std::erase(running, ended);
      ++done;
    } else if (ended == 0 || running.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (stopping && running.empty()) break;
    if (Clock::now() - last_report > std::chrono::seconds(10)) {
      last_report = Clock::now();
      progress(done, total, std::chrono::duration<double>(last_report - start).count());
    }
  }
  progress(done, total, std::chrono::duration<double>(Clock::now() - start).count());
  return done;
}

}  // namespace rig::sweep
