// rig/signals.h: the rig's threads start with its signals blocked, so that the handlers run on
// the main thread only (never on the real-time loop, whose sleep a signal would cut short).
#include "rig/signals.h"

#include <pthread.h>

#include <csignal>

#include <gtest/gtest.h>

namespace rig {
namespace {

bool blocked_here(int signo) {
  sigset_t now;
  pthread_sigmask(SIG_BLOCK, nullptr, &now);
  return sigismember(&now, signo) == 1;
}

TEST(Signals, ThreadsStartWithTheRigSignalsBlockedAndTheCallerKeepsItsMask) {
  ASSERT_FALSE(blocked_here(SIGTERM));
  bool in_thread[4] = {};
  std::thread t = start_thread([&] {
    int k = 0;
    for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGUSR1}) in_thread[k++] = blocked_here(s);
  });
  t.join();
  for (const bool b : in_thread) EXPECT_TRUE(b);
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGUSR1}) EXPECT_FALSE(blocked_here(s)) << s;
  EXPECT_FALSE(blocked_here(SIGPIPE));
}

}  // namespace
}  // namespace rig
