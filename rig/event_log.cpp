#include "rig/event_log.h"

#include <algorithm>
#include <cstring>
#include <span>

namespace rig {
namespace {

void copy_into(std::span<char> out, std::string_view text) noexcept {
  const std::size_t n = std::min(out.size() - 1, text.size());
  std::memcpy(out.data(), text.data(), n);
  out[n] = '\0';
}

}  // namespace

EventLog::EventLog(const std::string& path, std::size_t capacity, int keep)
    : ring_(capacity), file_(path, keep) {}

EventLog::~EventLog() { stop(); }

io::log::LogRecord* EventLog::begin(io::log::LogRecord::Kind kind, std::int64_t realtime_ns,
                                    std::int64_t monotonic_ns) noexcept {
  io::log::LogRecord* slot = ring_.claim();
  if (slot == nullptr) {
    lost_.fetch_add(1, std::memory_order_relaxed);
    return nullptr;
  }
  slot->kind = kind;
  slot->realtime_ns = realtime_ns;
  slot->monotonic_ns = monotonic_ns;
  return slot;
}

void EventLog::miss(std::int64_t realtime_ns, std::int64_t monotonic_ns,
                    const io::CycleTiming& timing, std::string_view action) noexcept {
  io::log::LogRecord* slot = begin(io::log::LogRecord::Kind::kMiss, realtime_ns, monotonic_ns);
  if (slot == nullptr) return;
  slot->timing = timing;
  copy_into(slot->name, action);
  slot->detail[0] = '\0';
  ring_.commit();
}

void EventLog::event(std::int64_t realtime_ns, std::int64_t monotonic_ns, std::string_view name,
                     std::string_view detail) noexcept {
  io::log::LogRecord* slot = begin(io::log::LogRecord::Kind::kEvent, realtime_ns, monotonic_ns);
  if (slot == nullptr) return;
  copy_into(slot->name, name);
  copy_into(slot->detail, detail);
  ring_.commit();
}

void EventLog::drain() {
  bool wrote = false;
  while (const io::log::LogRecord* r = ring_.front()) {
    file_.write(*r);
    ring_.release();
    wrote = true;
  }
  const std::uint64_t lost = lost_.load();
  if (lost != lost_reported_) {
    file_.write_lost(lost - lost_reported_);
    lost_reported_ = lost;
    wrote = true;
  }
  if (wrote) file_.flush();
}

void EventLog::stop() {
  drain();
  file_.close();
}

}  // namespace rig
