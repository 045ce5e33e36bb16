#include "io/lcm/lcm_log_writer.h"

#include <lcm/eventlog.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace rig::io::lcm {

LcmLogWriter::LcmLogWriter(const std::string& path, LcmSettings settings)
    : encoder_(std::move(settings)), path_(path) {
  errno = 0;
  log_ = lcm_eventlog_create(path.c_str(), "w");
  if (log_ == nullptr) {
    throw std::runtime_error("cannot write LCM log " + path + ": " +
                             (errno != 0 ? std::strerror(errno) : "lcm_eventlog_create failed"));
  }
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
    if (lcm_eventlog_write_event(log_, &event) != 0) {
      if (!write_failed_) {
        std::fprintf(stderr, "rig: writing LCM log %s failed (%s); the log is incomplete\n",
                     path_.c_str(), std::strerror(errno));
        write_failed_ = true;
      }
      continue;
    }
    ++events_written_;
  }
}

void LcmLogWriter::stop() {
  if (log_ != nullptr) {
    lcm_eventlog_destroy(log_);  // flushes and closes
    log_ = nullptr;
  }
}

}  // namespace rig::io::lcm
