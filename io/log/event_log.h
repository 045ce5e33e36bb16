#pragma once
/// @file
/// The overrun/event log: one JSON line per deadline miss or event, written by a non-RT thread
/// that the RT loop feeds through a lock-free SPSC ring of fixed-size records. A full ring drops
/// the record and counts it; the writer then writes the number lost, so nothing is lost silently.

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <thread>

#include "io/snapshot.h"
#include "rig/spsc_ring.h"

namespace rig::io::log {

/// One log entry, plain data (copied through the ring).
struct LogRecord {
  enum class Kind : std::uint8_t { kMiss, kEvent };
  Kind kind = Kind::kEvent;
  std::int64_t realtime_ns = 0;    ///< CLOCK_REALTIME
  std::int64_t monotonic_ns = 0;   ///< CLOCK_MONOTONIC
  CycleTiming timing{};            ///< kMiss: the late cycle
  std::array<char, 24> name{};     ///< kEvent: event name; kMiss: the policy's action
  std::array<char, 160> detail{};  ///< kEvent: free text (JSON-escaped on output)
};

/// Formats one record as a JSON line (no newline). Exposed for tests.
std::string format_record(const LogRecord& record);

class EventLog {
 public:
  /// `path` empty: records are counted and discarded (no file). Opens the file here; throws
  /// std::runtime_error if it cannot.
  explicit EventLog(const std::string& path, std::size_t capacity = 4096);
  ~EventLog();
  EventLog(const EventLog&) = delete;
  EventLog& operator=(const EventLog&) = delete;

  /// Producer side (one thread at a time): never blocks or allocates.
  void miss(std::int64_t realtime_ns, std::int64_t monotonic_ns, const CycleTiming& timing,
            std::string_view action) noexcept;
  void event(std::int64_t realtime_ns, std::int64_t monotonic_ns, std::string_view name,
             std::string_view detail) noexcept;

  /// Starts the writer thread.
  void start();
  /// Drains everything, writes the lost count if any, flushes and closes.
  void stop();

  [[nodiscard]] std::uint64_t lost() const noexcept { return lost_.load(); }
  [[nodiscard]] std::uint64_t written() const noexcept { return written_.load(); }

 private:
  void push(const LogRecord& record) noexcept;
  void drain();

  SpscRing<LogRecord> ring_;
  std::FILE* file_ = nullptr;
  std::thread writer_;
  std::atomic<bool> running_{false};
  std::atomic<std::uint64_t> lost_{0};
  std::uint64_t lost_reported_ = 0;
  std::atomic<std::uint64_t> written_{0};
};

}  // namespace rig::io::log
