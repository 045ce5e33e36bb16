#pragma once
/// @file
/// Loop timing over the last second, for the percentiles on RIG_STATUS.

#include <cstdint>
#include <vector>

namespace rig::io::lcm {

/// Percentiles of one window (nearest rank). All zero if the window is empty.
struct TimingPercentiles {
  std::int32_t cycles = 0;
  std::int32_t misses = 0;
  std::int64_t lateness_p50_ns = 0;
  std::int64_t lateness_p99_ns = 0;
  std::int64_t lateness_p999_ns = 0;
  std::int64_t lateness_max_ns = 0;
  std::int64_t compute_p50_ns = 0;
  std::int64_t compute_p99_ns = 0;
  std::int64_t compute_max_ns = 0;
};

/// A ring of the last `capacity` cycles' lateness and compute time. Storage is allocated by
/// reset() only; push() and percentiles() never allocate.
class TimingWindow {
 public:
  /// Empties the window and sizes it to `capacity` cycles (at least 1).
  void reset(std::size_t capacity);
  void push(std::int64_t lateness_ns, std::int64_t compute_ns, bool deadline_miss);
  [[nodiscard]] std::size_t size() const { return count_; }
  /// Percentiles over the cycles in the window. Not const: sorts a scratch copy.
  TimingPercentiles percentiles();

 private:
  std::vector<std::int64_t> lateness_ns_;
  std::vector<std::int64_t> compute_ns_;
  std::vector<std::uint8_t> miss_;
  std::vector<std::int64_t> scratch_;
  std::size_t next_ = 0;
  std::size_t count_ = 0;
};

/// Nearest-rank percentile (p in [0, 1]) of `values`, reordering them. `values` must not be
/// empty.
std::int64_t nearest_rank_percentile(std::vector<std::int64_t>& values, std::size_t count,
                                     double p);

}  // namespace rig::io::lcm
