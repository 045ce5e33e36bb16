#pragma once
/// @file
/// Helpers for the tests that need vcan0/vcan1 (run inside the VM by scripts/with-vcan): skip
/// when the kernel has no CAN, unless RIG_VCAN_REQUIRED=1 (set by the VM driver) turns that into
/// a failure; child processes (candump, cangen, virtual-ecu) with line-wise output.

#include <gtest/gtest.h>

#include <sys/types.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rig::test {

/// Empty if vcan0 and vcan1 are usable, else why not.
std::string vcan_unavailable_reason();
bool vcan_required();

#define RIG_REQUIRE_VCAN()                                                      \
  do {                                                                          \
    const std::string rig_why = ::rig::test::vcan_unavailable_reason();         \
    if (!rig_why.empty()) {                                                     \
      if (::rig::test::vcan_required()) FAIL() << "vcan required: " << rig_why; \
      GTEST_SKIP() << rig_why << " (run through scripts/with-vcan)";            \
    }                                                                           \
  } while (0)

std::int64_t monotonic_ns();
std::int64_t realtime_ns();
void sleep_ms(int ms);
/// Runs a shell command, returns its exit status.
int sh(const std::string& command);
/// The repository root (from the RIG_SOURCE_DIR compile definition).
std::string source_dir();

/// A child process running `/bin/sh -c "exec command"` with its stdout captured line by line.
class Child {
 public:
  explicit Child(const std::string& command);
  ~Child();
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  /// Reads what is available now; complete lines are appended to lines().
  void poll();
  /// Polls until `pred(line)` holds for a new line or `timeout_ms` passes; true if it held.
  bool wait_for_line(const std::function<bool(const std::string&)>& pred, int timeout_ms);
  /// Waits for exit (up to timeout_ms, then SIGKILL); returns the exit status or -1.
  int wait(int timeout_ms);
  /// True once the child has exited (non-blocking; never kills).
  bool exited();
  /// SIGTERM then wait.
  int terminate();
  [[nodiscard]] const std::vector<std::string>& lines() const { return lines_; }
  [[nodiscard]] pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string partial_;
  std::vector<std::string> lines_;
  std::size_t checked_ = 0;
  int status_ = -1;
  bool exited_ = false;
};

}  // namespace rig::test
