#include "rig/rt/log_histogram.h"

#include <bit>
#include <cmath>

namespace rig::rt {

int LogHistogram::bucket_of(std::int64_t value_ns) noexcept {
  if (value_ns < kSub) return value_ns < 0 ? 0 : static_cast<int>(value_ns);
  const auto v = static_cast<std::uint64_t>(value_ns);
  const int msb = 63 - std::countl_zero(v);  // >= kSubBits
  const int octave = msb - kSubBits + 1;
  const int sub = static_cast<int>((v >> (msb - kSubBits)) & (kSub - 1));
  const int bucket = octave * kSub + sub;
  return bucket < kBuckets ? bucket : kBuckets - 1;
}

std::int64_t LogHistogram::bucket_low(int bucket) noexcept {
  const int octave = bucket / kSub;
  const int sub = bucket % kSub;
  if (octave == 0) return sub;
  const int msb = octave + kSubBits - 1;
  return static_cast<std::int64_t>((std::uint64_t{1} << msb) +
                                   (static_cast<std::uint64_t>(sub) << (msb - kSubBits)));
}

std::int64_t LogHistogram::bucket_high(int bucket) noexcept {
  return bucket + 1 < kBuckets ? bucket_low(bucket + 1) - 1 : INT64_MAX;
}

void LogHistogram::add(std::int64_t value_ns) noexcept {
  if (value_ns < 0) value_ns = 0;
  auto& b = buckets_[static_cast<std::size_t>(bucket_of(value_ns))];
  // Single writer: load + store is enough and cheaper than a locked read-modify-write.
  b.store(b.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  count_.store(count_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  if (value_ns > max_.load(std::memory_order_relaxed))
    max_.store(value_ns, std::memory_order_relaxed);
}

std::int64_t LogHistogram::quantile(double q) const noexcept {
  const std::uint64_t n = count();
  if (n == 0) return 0;
  auto rank = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(n)));
  if (rank < 1) rank = 1;
  std::uint64_t seen = 0;
  for (int i = 0; i < kBuckets; ++i) {
    seen += bucket_count(i);
    if (seen >= rank) {
      const std::int64_t high = bucket_high(i);
      return high < max() ? high : max();
    }
  }
  return max();
}

std::vector<LogHistogram::Bin> LogHistogram::bins() const {
  std::vector<Bin> out;
  for (int i = 0; i < kBuckets; ++i) {
    if (const auto c = bucket_count(i); c != 0) out.push_back({bucket_low(i), bucket_high(i), c});
  }
  return out;
}

}  // namespace rig::rt
