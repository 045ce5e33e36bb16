#pragma once
/// @file
/// An allocation-free log-scale histogram of non-negative nanosecond values: 16 buckets per
/// octave (relative resolution 1/16 = 6.25 %), from 0 to 2^40 ns. One writer (the RT loop) adds
/// with relaxed atomics; readers on other threads see a slightly stale but valid picture.

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace rig::rt {

class LogHistogram {
 public:
  static constexpr int kSubBits = 4;  ///< 2^4 = 16 sub-buckets per octave
  static constexpr int kSub = 1 << kSubBits;
  static constexpr int kOctaves = 41;  ///< values up to 2^40 ns (~18 min)
  static constexpr int kBuckets = kSub * kOctaves;

  /// Bucket of a value (values < 16 ns have one bucket per ns).
  static int bucket_of(std::int64_t value_ns) noexcept;
  /// Smallest and largest value of a bucket.
  static std::int64_t bucket_low(int bucket) noexcept;
  static std::int64_t bucket_high(int bucket) noexcept;

  /// Single writer: records one value (negative values count as 0).
  void add(std::int64_t value_ns) noexcept;

  [[nodiscard]] std::uint64_t count() const noexcept {
    return count_.load(std::memory_order_relaxed);
  }
  [[nodiscard]] std::int64_t max() const noexcept { return max_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::uint64_t bucket_count(int bucket) const noexcept {
    return buckets_[static_cast<std::size_t>(bucket)].load(std::memory_order_relaxed);
  }
  /// The q-quantile (0 < q <= 1): the upper bound of the bucket holding the ceil(q n)-th value,
  /// never above the exact maximum. 0 when empty.
  [[nodiscard]] std::int64_t quantile(double q) const noexcept;

  /// Non-empty buckets as {low_ns, high_ns, count} (for the summary; not for the RT thread).
  struct Bin {
    std::int64_t low_ns;
    std::int64_t high_ns;
    std::uint64_t count;
  };
  [[nodiscard]] std::vector<Bin> bins() const;

 private:
  std::array<std::atomic<std::uint64_t>, kBuckets> buckets_{};
  std::atomic<std::uint64_t> count_{0};
  std::atomic<std::int64_t> max_{0};
};

}  // namespace rig::rt
