#pragma once
/// @file
/// A stderr that never holds the rig: during `rig run`, file descriptor 2 is the write end of a
/// pipe of the rig's own (non-blocking, 1 MiB where the kernel allows), and one thread copies it
/// to the real stderr. A reader that does not drain the real stderr (an undrained pipe, a
/// stopped terminal) then blocks only that thread; what does not fit into the pipe is dropped
/// (a write returns EAGAIN), and the main thread, the dispatcher and the loop run on. At the end
/// the relay waits a bounded time for the copy to finish, then leaves it. stdio's stderr,
/// std::cerr and libraries' messages all go through it (it works on the descriptor).

#include <cstdint>

namespace rig {

class StderrRelay {
 public:
  /// How long the end waits for what is still in the pipe to reach the real stderr.
  static constexpr std::int64_t kFinishWait_ns = 1'000'000'000;

  /// Puts the relay in place (if it cannot, stderr stays as it was).
  StderrRelay();
  /// Waits at most kFinishWait_ns for the copy, then restores fd 2 if the copy finished.
  ~StderrRelay();
  StderrRelay(const StderrRelay&) = delete;
  StderrRelay& operator=(const StderrRelay&) = delete;

 private:
  struct Shared;
  Shared* shared_ = nullptr;  ///< left to the copying thread if it is still blocked at the end
};

}  // namespace rig
