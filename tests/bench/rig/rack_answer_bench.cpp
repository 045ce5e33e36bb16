/// @file
/// Rack-in-the-loop answer latency (issue 15 item 6: "wall-clock latency is a benchmark, not a
/// test"): from a received RACK_Position frame to the encoded RIG_TieRodForces frame, in process
/// (rack_answer_path.h: RX decode with counter and CRC-8, the sedan-rack-in-the-loop step, TX
/// encode). Each answer is timed on CLOCK_MONOTONIC (manual time); the counters give the
/// per-answer median, p99 and maximum over the run's 20 s of simulated weave.
///   build/bin/rack_answer_bench [--benchmark_repetitions=5]

#include <algorithm>
#include <chrono>
#include <vector>

#include <benchmark/benchmark.h>

#include "tests/bench/rig/rack_answer_path.h"

namespace {

/// The q-quantile (0..1) of `ns` (reorders it).
double quantile(std::vector<double>& ns, double q) {
  const auto i = static_cast<std::ptrdiff_t>(q * static_cast<double>(ns.size() - 1));
  std::nth_element(ns.begin(), ns.begin() + i, ns.end());
  return ns[static_cast<std::size_t>(i)];
}

void BM_RackAnswer(benchmark::State& state) {
  const auto cycles = static_cast<std::size_t>(state.max_iterations);
  rig::bench::RackAnswerPath path(RIG_SOURCE_DIR "/config/rack-in-the-loop.toml", cycles);
  std::vector<double> ns;
  ns.reserve(cycles);
  std::size_t k = 0, unanswered = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t sent = path.answer(k++);
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(path.answer_frame());
    const std::chrono::duration<double> dt = t1 - t0;
    state.SetIterationTime(dt.count());
    ns.push_back(dt.count() * 1e9);
    unanswered += sent == 1 ? 0 : 1;
  }
  if (unanswered != 0 || path.counters().checksum_failures + path.counters().counter_failures != 0)
    state.SkipWithError("a rack frame was rejected or not answered");
  state.counters["p50_ns"] = quantile(ns, 0.5);
  state.counters["p99_ns"] = quantile(ns, 0.99);
  state.counters["max_ns"] = *std::max_element(ns.begin(), ns.end());
}
BENCHMARK(BM_RackAnswer)->Iterations(20000)->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
