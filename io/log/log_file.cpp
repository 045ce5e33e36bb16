#include "io/log/log_file.h"

#include <sys/types.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/log/output_file.h"

namespace rig::io::log {

LogFile::LogFile(const std::string& path, int keep) : path_(path) {
  if (path.empty()) return;
  fd_ = open_output_file({"--overrun-log", path}, keep);
}

LogFile::~LogFile() { close(); }

void LogFile::write_line(std::string_view line) {
  if (fd_ < 0) return;
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (write_error_.empty()) write_error_ = n < 0 ? std::strerror(errno) : "short write";
      ++write_failures_;
      // Cut the partial line off again: the file ends after its last whole line.
      if (done > 0 && ::ftruncate(fd_, static_cast<off_t>(good_bytes_)) == 0)
        (void)::lseek(fd_, static_cast<off_t>(good_bytes_), SEEK_SET);
      return;
    }
    done += static_cast<std::size_t>(n);
  }
  good_bytes_ += line.size();
}

void LogFile::write(const LogRecord& record) { write_line(format_record(record) + "\n"); }

void LogFile::write_lost(std::uint64_t lost) {
  char line[96];
  std::snprintf(line, sizeof line, "{\"event\":\"ring_overflow\",\"lost\":%llu}\n",
                static_cast<unsigned long long>(lost));
  write_line(line);
}

void LogFile::flush() {}  // every line is written at once (no user-space buffer)

void LogFile::close() {
  if (fd_ < 0) return;
  if (::close(fd_) != 0 && errno != EINTR && write_error_.empty()) {
    write_error_ = std::strerror(errno);
    ++write_failures_;
  }
  fd_ = -1;
}

}  // namespace rig::io::log
