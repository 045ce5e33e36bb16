#include "io/log/log_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace rig::io::log {

LogFile::LogFile(const std::string& path) {
  if (path.empty()) return;
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr)
    throw std::runtime_error("cannot open overrun log '" + path + "': " + std::strerror(errno));
}

LogFile::~LogFile() { close(); }

void LogFile::write(const LogRecord& record) {
  if (file_ == nullptr) return;
  const std::string line = format_record(record);
  std::fputs(line.c_str(), file_);
  std::fputc('\n', file_);
}

void LogFile::write_lost(std::uint64_t lost) {
  if (file_ == nullptr) return;
  std::fprintf(file_, "{\"event\":\"ring_overflow\",\"lost\":%llu}\n",
               static_cast<unsigned long long>(lost));
}

void LogFile::flush() {
  if (file_ != nullptr) std::fflush(file_);
}

void LogFile::close() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  file_ = nullptr;
}

}  // namespace rig::io::log
