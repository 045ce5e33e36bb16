#include "io/lcm/lcm_log_writer.h"

#include <lcm/eventlog.h>

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "io/log/output_file.h"

namespace rig::io::lcm {

LcmLogWriter::LcmLogWriter(const std::string& path, LcmSettings settings, int keep)
    : encoder_(std::move(settings)), path_(path) {
  const int fd = log::open_output_file({"--lcm-log", path}, keep);
  // lcm_eventlog_create would fopen (follow a link, truncate): build its public struct around
  // our descriptor instead; lcm_eventlog_destroy fcloses and frees it as its own.
  std::FILE* f = ::fdopen(fd, "wb");
  log_ =
      f != nullptr ? static_cast<lcm_eventlog_t*>(std::calloc(1, sizeof(lcm_eventlog_t))) : nullptr;
  if (log_ == nullptr) {
    const int error = errno;
    if (f != nullptr)
      std::fclose(f);
    else
      ::close(fd);
    throw log::OutputFileError("--lcm-log " + path + ": " + std::strerror(error));
  }
  log_->f = f;
}

void LcmLogWriter::failed(int error) {
  if (write_failures_++ == 0) {
    write_error_ = error != 0 ? std::strerror(error) : "write failed";
    std::fprintf(stderr, "rig: writing LCM log %s failed (%s); the log is incomplete\n",
                 path_.c_str(), write_error_.c_str());
  }
}

WriteFailures LcmLogWriter::write_failures() const {
  if (write_failures_ == 0) return {};
  return {write_failures_, "LCM log " + path_ + ": " + write_error_};
}

LcmLogWriter::~LcmLogWriter() {
  if (log_ != nullptr) lcm_eventlog_destroy(log_);
}

void LcmLogWriter::start(const RunInfo& info) {
  encoder_.start(info);
  start_utime_us_ = std::chrono::duration_cast<std::chrono::microseconds>(
                        std::chrono::system_clock::now().time_since_epoch())
                        .count();
}

void LcmLogWriter::consume(const Snapshot& snapshot, std::uint64_t dropped_before) {
  if (log_ == nullptr) return;
  EncodedMessage messages[3];
  const std::size_t n = encoder_.encode(snapshot, dropped_before, messages);
  const std::int64_t utime = start_utime_us_ + std::llround(snapshot.timing.sim_time_s * 1.0e6);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& m = messages[i];
    lcm_eventlog_event_t event{};
    event.timestamp = utime;
    event.channellen = static_cast<std::int32_t>(m.channel->size());
    event.datalen = static_cast<std::int32_t>(m.size);
    event.channel = const_cast<char*>(m.channel->c_str());
    event.data = const_cast<std::uint8_t*>(m.data);
    errno = 0;
    if (lcm_eventlog_write_event(log_, &event) != 0) {
      failed(errno);
      continue;
    }
    ++events_written_;
  }
}

void LcmLogWriter::stop() {
  if (log_ == nullptr) return;
  // What is still buffered can fail too (a full disk shows at the flush): count it.
  errno = 0;
  if (std::fflush(log_->f) != 0 || std::ferror(log_->f) != 0) failed(errno);
  errno = 0;
  if (std::fclose(log_->f) != 0) failed(errno);
  std::free(log_);  // what lcm_eventlog_destroy does after fclose
  log_ = nullptr;
}

}  // namespace rig::io::lcm
