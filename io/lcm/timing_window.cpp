#include "io/lcm/timing_window.h"

#include <algorithm>
#include <cmath>

namespace rig::io::lcm {

void TimingWindow::reset(std::size_t capacity) {
  capacity = std::max<std::size_t>(capacity, 1);
  lateness_ns_.assign(capacity, 0);
  compute_ns_.assign(capacity, 0);
  miss_.assign(capacity, 0);
  scratch_.assign(capacity, 0);
  next_ = 0;
  count_ = 0;
}

void TimingWindow::push(std::int64_t lateness_ns, std::int64_t compute_ns, bool deadline_miss) {
  if (lateness_ns_.empty()) reset(1);
  lateness_ns_[next_] = lateness_ns;
  compute_ns_[next_] = compute_ns;
  miss_[next_] = deadline_miss ? 1 : 0;
  next_ = (next_ + 1) % lateness_ns_.size();
  count_ = std::min(count_ + 1, lateness_ns_.size());
}

std::int64_t nearest_rank_percentile(std::vector<std::int64_t>& values, std::size_t count,
                                     double p) {
  // Nearest rank: the smallest value with at least p * count values at or below it.
  auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(count)));
  rank = std::clamp<std::size_t>(rank, 1, count);
  const auto nth = values.begin() + static_cast<std::ptrdiff_t>(rank - 1);
  std::nth_element(values.begin(), nth, values.begin() + static_cast<std::ptrdiff_t>(count));
  return *nth;
}

TimingPercentiles TimingWindow::percentiles() {
  TimingPercentiles out;
  if (count_ == 0) return out;
  out.cycles = static_cast<std::int32_t>(count_);
  for (std::size_t i = 0; i < count_; ++i) out.misses += miss_[i];

  std::copy_n(lateness_ns_.begin(), count_, scratch_.begin());
  out.lateness_p50_ns = nearest_rank_percentile(scratch_, count_, 0.50);
  out.lateness_p99_ns = nearest_rank_percentile(scratch_, count_, 0.99);
  out.lateness_p999_ns = nearest_rank_percentile(scratch_, count_, 0.999);
  out.lateness_max_ns = nearest_rank_percentile(scratch_, count_, 1.0);

  std::copy_n(compute_ns_.begin(), count_, scratch_.begin());
  out.compute_p50_ns = nearest_rank_percentile(scratch_, count_, 0.50);
  out.compute_p99_ns = nearest_rank_percentile(scratch_, count_, 0.99);
  out.compute_max_ns = nearest_rank_percentile(scratch_, count_, 1.0);
  return out;
}

}  // namespace rig::io::lcm
