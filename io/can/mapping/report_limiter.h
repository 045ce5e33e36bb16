#pragma once
/// @file
/// Rate limit of a repeated event (e.g. a signal clamped to its DBC range): the first occurrence
/// is reported at once, later ones at most once per interval, each report with the number of
/// occurrences since the previous one, so a flood costs one log line a second and loses no count.
/// Plain data, allocation-free, noexcept (RT thread).

#include <cstdint>

namespace rig::io::can::mapping {

class ReportLimiter {
 public:
  static constexpr std::int64_t kDefaultIntervalNs = 1'000'000'000;

  explicit ReportLimiter(std::int64_t interval_ns = kDefaultIntervalNs) noexcept
      : interval_ns_(interval_ns) {}

  /// One occurrence.
  void count() noexcept { ++pending_; }

  /// The number of occurrences to report at `now_ns` (0: none due), and marks them reported.
  std::uint64_t take_due(std::int64_t now_ns) noexcept {
    if (pending_ == 0) return 0;
    if (reported_once_ && now_ns - last_report_ns_ < interval_ns_) return 0;
    const std::uint64_t n = pending_;
    pending_ = 0;
    reported_once_ = true;
    last_report_ns_ = now_ns;
    return n;
  }

  /// Occurrences counted but not reported yet.
  [[nodiscard]] std::uint64_t pending() const noexcept { return pending_; }

 private:
  std::int64_t interval_ns_;
  std::int64_t last_report_ns_ = 0;
  std::uint64_t pending_ = 0;
  bool reported_once_ = false;
};

/// One rate-limited report of values clamped to a signal's DBC range (or non-finite), from the
/// RX engine (a received value) or the TX engine (a model value to be sent).
struct OutOfRangeReport {
  const char* direction = "rx";  ///< "rx" or "tx"
  const char* message = "";      ///< DBC message name
  const char* signal = "";       ///< DBC signal name
  double received = 0.0;         ///< the last value out of range (physical, DBC units; may be NaN)
  double minimum = 0.0;          ///< the DBC range it was clamped to
  double maximum = 0.0;
  std::uint64_t count = 0;  ///< occurrences since the previous report of this signal
};

}  // namespace rig::io::can::mapping
