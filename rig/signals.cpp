#include "rig/signals.h"

#include <atomic>
#include <csignal>

#include "rig/executive.h"

namespace rig {
namespace {

std::atomic<Executive*> g_executive{nullptr};
volatile std::sig_atomic_t g_stop_signal = 0;
volatile std::sig_atomic_t g_status_requests = 0;
std::sig_atomic_t g_status_taken = 0;

extern "C" void on_stop_signal(int signo) {
  g_stop_signal = signo;
  if (Executive* e = g_executive.load()) e->request_stop();
}

extern "C" void on_status_signal(int) { g_status_requests = g_status_requests + 1; }

void handle(int signo, void (*handler)(int)) {
  struct sigaction sa {};
  sa.sa_handler = handler;
  sa.sa_flags = SA_RESTART;
  sigemptyset(&sa.sa_mask);
  sigaction(signo, &sa, nullptr);
}

}  // namespace

void install_signal_handlers() {
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) handle(s, on_stop_signal);
  handle(SIGUSR1, on_status_signal);
  handle(SIGPIPE, SIG_IGN);
  const sigset_t ours = rig_signals();
  // A mask inherited blocked (exec keeps it) would hold a stop signal back for the whole run;
  // one already pending is handled now, before anything else.
  sigprocmask(SIG_UNBLOCK, &ours, nullptr);
}

void set_signal_target(Executive* exec) {
  g_executive.store(exec);
  if (exec != nullptr && g_stop_signal != 0) exec->request_stop();
}

int stop_signal() { return g_stop_signal; }

bool take_status_request() {
  const std::sig_atomic_t now = g_status_requests;
  if (now == g_status_taken) return false;
  g_status_taken = now;
  return true;
}

}  // namespace rig
