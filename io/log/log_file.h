#pragma once
/// @file
/// The overrun/event log file: one JSON line per record it is handed. Runs on a non-RT thread
/// (the rig's dispatcher); it owns no ring and no thread.

#include <cstdint>
#include <cstdio>
#include <string>

#include "io/log/log_record.h"

namespace rig::io::log {

class LogFile {
 public:
  /// `path` empty: records are discarded (no file). Opens the file here; throws
  /// std::runtime_error if it cannot.
  explicit LogFile(const std::string& path);
  ~LogFile();
  LogFile(const LogFile&) = delete;
  LogFile& operator=(const LogFile&) = delete;

  void write(const LogRecord& record);
  /// Records that never reached the writer: {"event":"ring_overflow","lost":N}.
  void write_lost(std::uint64_t lost);
  void flush();
  void close();

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace rig::io::log
