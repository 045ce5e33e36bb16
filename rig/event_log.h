#pragma once
/// @file
/// The overrun/event log as the loop sees it: fixed-size records into a lock-free ring, never
/// blocking; the dispatcher drains them into io::log::LogFile. A full ring drops the record and
/// counts it; the writer then writes the number lost, so nothing is lost silently.

#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/log/log_file.h"
#include "io/log/log_record.h"
#include "rig/rt/spsc_ring.h"

namespace rig {

class EventLog {
 public:
  /// `path` empty: records are counted and discarded (no file). Opens the file here (an earlier
  /// one kept as NAME.1 .. NAME.keep); throws io::log::OutputFileError if it cannot.
  explicit EventLog(const std::string& path, std::size_t capacity = 4096, int keep = 10);
  ~EventLog();
  EventLog(const EventLog&) = delete;
  EventLog& operator=(const EventLog&) = delete;

  /// Producer side (one thread at a time): never blocks or allocates.
  void miss(std::int64_t realtime_ns, std::int64_t monotonic_ns, const io::CycleTiming& timing,
            std::string_view action) noexcept;
  void event(std::int64_t realtime_ns, std::int64_t monotonic_ns, std::string_view name,
             std::string_view detail) noexcept;

  /// Consumer side (one thread at a time: the dispatcher while it runs, then the owner): writes
  /// the pending records and the lost count if it grew, flushes if anything was written.
  void drain();
  /// Drains everything and closes the file.
  void stop();

  [[nodiscard]] std::uint64_t lost() const noexcept { return lost_.load(); }
  /// The file's failed writes (a full disk): lines lost there, and the first error.
  [[nodiscard]] std::uint64_t write_failures() const noexcept { return file_.write_failures(); }
  [[nodiscard]] const std::string& write_error() const noexcept { return file_.write_error(); }

 private:
  /// Claims a slot and fills its header, or counts the record as lost (nullptr).
  io::log::LogRecord* begin(io::log::LogRecord::Kind kind, std::int64_t realtime_ns,
                            std::int64_t monotonic_ns) noexcept;

  rt::SpscRing<io::log::LogRecord> ring_;
  io::log::LogFile file_;
  std::atomic<std::uint64_t> lost_{0};
  std::uint64_t lost_reported_ = 0;
};

}  // namespace rig
