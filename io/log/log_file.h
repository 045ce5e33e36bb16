#pragma once
/// @file
/// The overrun/event log file: one JSON line per record it is handed. Runs on a non-RT thread
/// (the rig's dispatcher); it owns no ring and no thread.
///
/// Every line is written at once; a line that does not fit (a full disk, an I/O error) is cut
/// off again (the file ends after the last whole line), counted and its error kept, so that a
/// failed write is never silent and never leaves half a line.

#include <cstdint>
#include <string>
#include <string_view>

#include "io/log/log_record.h"

namespace rig::io::log {

class LogFile {
 public:
  /// `path` empty: records are discarded (no file). Opens the file here (io/log/output_file.h:
  /// an earlier file is kept as NAME.1 .. NAME.keep); throws OutputFileError if it cannot.
  explicit LogFile(const std::string& path, int keep = 10);
  ~LogFile();
  LogFile(const LogFile&) = delete;
  LogFile& operator=(const LogFile&) = delete;

  void write(const LogRecord& record);
  /// Records that never reached the writer: {"event":"ring_overflow","lost":N}.
  void write_lost(std::uint64_t lost);
  void flush();
  void close();

  /// Lines that could not be written (each removed again).
  [[nodiscard]] std::uint64_t write_failures() const noexcept { return write_failures_; }
  /// The error of the first failed write ("" if none).
  [[nodiscard]] const std::string& write_error() const noexcept { return write_error_; }
  [[nodiscard]] const std::string& path() const noexcept { return path_; }

 private:
  void write_line(std::string_view line);

  std::string path_;
  int fd_ = -1;
  std::uint64_t good_bytes_ = 0;  ///< the file's length after the last whole line
  std::uint64_t write_failures_ = 0;
  std::string write_error_;
};

}  // namespace rig::io::log
