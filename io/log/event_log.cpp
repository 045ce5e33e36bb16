#include "io/log/event_log.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <span>
#include <stdexcept>

namespace rig::io::log {
namespace {

void copy_into(std::span<char> out, std::string_view text) noexcept {
  const std::size_t n = std::min(out.size() - 1, text.size());
  std::memcpy(out.data(), text.data(), n);
  out[n] = '\0';
}

std::string iso8601(std::int64_t realtime_ns) {
  const time_t secs = static_cast<time_t>(realtime_ns / 1'000'000'000);
  tm utc{};
  gmtime_r(&secs, &utc);
  char buf[64];
  const std::size_t n = std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &utc);
  char frac[32];
  std::snprintf(frac, sizeof frac, ".%09lldZ", static_cast<long long>(realtime_ns % 1'000'000'000));
  return std::string(buf, n) + frac;
}

std::string escape(const char* text) {
  std::string out;
  for (const char* p = text; *p != '\0'; ++p) {
    const char c = *p;
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

constexpr std::array<const char*, kPhaseCount> kPhaseNames{"inputs", "driver", "model", "outputs",
                                                           "handoff"};
}  // namespace

std::string format_record(const LogRecord& r) {
  char buf[1024];
  std::string line = "{\"time\":\"" + iso8601(r.realtime_ns) +
                     "\",\"monotonic_ns\":" + std::to_string(r.monotonic_ns);
  if (r.kind == LogRecord::Kind::kEvent) {
    line += ",\"event\":\"" + escape(r.name.data()) + "\",\"detail\":\"" + escape(r.detail.data()) +
            "\"}";
    return line;
  }
  const CycleTiming& t = r.timing;
  std::snprintf(
      buf, sizeof buf,
      ",\"event\":\"deadline_miss\",\"cycle\":%llu,\"sim_time_s\":%.9f,\"deadline_ns\":%lld,"
      "\"lateness_ns\":%lld,\"phase_ns\":{",
      static_cast<unsigned long long>(t.cycle), t.sim_time_s, static_cast<long long>(t.deadline_ns),
      static_cast<long long>(t.lateness_ns));
  line += buf;
  for (std::size_t i = 0; i < kPhaseCount; ++i) {
    std::snprintf(buf, sizeof buf, "%s\"%s\":%lld", i == 0 ? "" : ",", kPhaseNames[i],
                  static_cast<long long>(t.phase_ns[i]));
    line += buf;
  }
  std::snprintf(
      buf, sizeof buf,
      "},\"compute_ns\":%lld,\"total_ns\":%lld,\"consecutive_misses\":%u,\"action\":\"%s\"}",
      static_cast<long long>(t.compute_ns), static_cast<long long>(t.lateness_ns + t.compute_ns),
      t.consecutive_misses, escape(r.name.data()).c_str());
  line += buf;
  return line;
}

EventLog::EventLog(const std::string& path, std::size_t capacity) : ring_(capacity) {
  if (!path.empty()) {
    file_ = std::fopen(path.c_str(), "w");
    if (file_ == nullptr)
      throw std::runtime_error("cannot open overrun log '" + path + "': " + std::strerror(errno));
  }
}

EventLog::~EventLog() {
  if (running_.load() || file_ != nullptr) stop();
}

void EventLog::push(const LogRecord& record) noexcept {
  if (!ring_.push(record)) lost_.fetch_add(1, std::memory_order_relaxed);
}

void EventLog::miss(std::int64_t realtime_ns, std::int64_t monotonic_ns, const CycleTiming& timing,
                    std::string_view action) noexcept {
  LogRecord* slot = ring_.claim();
  if (slot == nullptr) {
    lost_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  slot->kind = LogRecord::Kind::kMiss;
  slot->realtime_ns = realtime_ns;
  slot->monotonic_ns = monotonic_ns;
  slot->timing = timing;
  copy_into(slot->name, action);
  slot->detail[0] = '\0';
  ring_.commit();
}

void EventLog::event(std::int64_t realtime_ns, std::int64_t monotonic_ns, std::string_view name,
                     std::string_view detail) noexcept {
  LogRecord* slot = ring_.claim();
  if (slot == nullptr) {
    lost_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  slot->kind = LogRecord::Kind::kEvent;
  slot->realtime_ns = realtime_ns;
  slot->monotonic_ns = monotonic_ns;
  copy_into(slot->name, name);
  copy_into(slot->detail, detail);
  ring_.commit();
}

void EventLog::drain() {
  while (const LogRecord* r = ring_.front()) {
    if (file_ != nullptr) {
      const std::string line = format_record(*r);
      std::fputs(line.c_str(), file_);
      std::fputc('\n', file_);
    }
    ring_.release();
    written_.fetch_add(1);
  }
  const std::uint64_t lost = lost_.load();
  if (lost != lost_reported_) {
    if (file_ != nullptr) {
      std::fprintf(file_, "{\"event\":\"ring_overflow\",\"lost\":%llu}\n",
                   static_cast<unsigned long long>(lost - lost_reported_));
    }
    lost_reported_ = lost;
  }
  if (file_ != nullptr) std::fflush(file_);
}

void EventLog::start() {
  running_ = true;
  writer_ = std::thread([this] {
    while (running_.load()) {
      drain();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
}

void EventLog::stop() {
  running_ = false;
  if (writer_.joinable()) writer_.join();
  drain();
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
}

}  // namespace rig::io::log
