/// @file
/// rig-lcm-feed: drives the LCM sinks the way the executive's dispatcher does, with synthetic
/// snapshots (tests/io/lcm/synthetic_snapshot.h), in real time or as fast as possible. For the
/// LCM integration tests, which must not depend on the executive.
///
///   rig-lcm-feed [--url URL|none] [--log FILE] [--duration S] [--period S] [--fast]
///                [--prefix P] [--state-rate HZ] [--status-rate HZ] [--signals-rate HZ]
///                [--loop-thread --summary-json FILE]
///
/// --loop-thread: a stand-in for the executive, until `rig run` can be measured: a SCHED_FIFO
/// (if granted) loop thread measures its wake-up lateness and hands each snapshot through a
/// lock-free ring to a dispatcher thread that runs the sinks; --summary-json writes the
/// lateness percentiles in the keys of `rig run --summary-json` (scripts/lcm-overhead --feed).

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <thread>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "io/lcm/lcm_sinks.h"
#include "tests/io/lcm/synthetic_snapshot.h"

namespace {

using Sinks = std::vector<std::unique_ptr<rig::io::SnapshotSink>>;

std::int64_t now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

timespec to_timespec(std::int64_t ns) {
  return timespec{static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
}

/// Single-producer single-consumer ring of snapshots; the producer never waits.
class SnapshotRing {
 public:
  explicit SnapshotRing(std::size_t capacity) : slots_(capacity) {}
  bool push(const rig::io::Snapshot& s) {
    const auto head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) == slots_.size()) return false;
    slots_[head % slots_.size()] = s;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }
  bool pop(rig::io::Snapshot& s) {
    const auto tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    s = slots_[tail % slots_.size()];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

 private:
  std::vector<rig::io::Snapshot> slots_;
  std::atomic<std::uint64_t> head_{0};
  std::atomic<std::uint64_t> tail_{0};
};

std::int64_t percentile(std::vector<std::int64_t> v, double p) {
  std::sort(v.begin(), v.end());
  auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size())));
  return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

/// The loop thread and the dispatcher thread of --loop-thread.
int run_threaded(Sinks& sinks, std::uint64_t cycles, double period_s,
                 const std::string& summary_json) {
  SnapshotRing ring(256);
  std::vector<std::int64_t> lateness(cycles, 0);
  std::atomic<bool> done{false};
  std::uint64_t dropped = 0, misses = 0;
  bool fifo = false;

  std::thread loop([&] {
    sched_param param{};
    param.sched_priority = 80;
    fifo = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
    const auto period_ns = static_cast<std::int64_t>(period_s * 1e9 + 0.5);
    std::int64_t deadline = now_ns() + period_ns;
    rig::io::Snapshot snapshot;
    for (std::uint64_t cycle = 0; cycle < cycles; ++cycle, deadline += period_ns) {
      const timespec t = to_timespec(deadline);
      clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &t, nullptr);
      const std::int64_t wake = now_ns();
      snapshot = rig::test::make_synthetic_snapshot(cycle, period_s);
      snapshot.timing.deadline_ns = deadline;
      snapshot.timing.wake_ns = wake;
      snapshot.timing.lateness_ns = wake - deadline;
      snapshot.timing.compute_ns = now_ns() - wake;
      snapshot.timing.deadline_miss = now_ns() > deadline + period_ns;
      lateness[cycle] = wake - deadline;
      if (snapshot.timing.deadline_miss) ++misses;
      if (!ring.push(snapshot)) ++dropped;
    }
    done.store(true, std::memory_order_release);
  });
  std::thread dispatcher([&] {
    rig::io::Snapshot s;
    for (;;) {
      if (ring.pop(s)) {
        for (auto& sink : sinks) sink->consume(s, 0);
        continue;
      }
      if (done.load(std::memory_order_acquire) && !ring.pop(s)) break;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  loop.join();
  dispatcher.join();

  const auto p50 = percentile(lateness, 0.5), p99 = percentile(lateness, 0.99),
             p999 = percentile(lateness, 0.999), max = percentile(lateness, 1.0);
  std::printf(
      "rig-lcm-feed: loop thread (%s): lateness p50 %.1f us, p99 %.1f us, p99.9 %.1f us, "
      "max %.1f us; %llu misses, %llu snapshots dropped\n",
      fifo ? "SCHED_FIFO 80" : "SCHED_OTHER", static_cast<double>(p50) / 1e3,
      static_cast<double>(p99) / 1e3, static_cast<double>(p999) / 1e3,
      static_cast<double>(max) / 1e3, static_cast<unsigned long long>(misses),
      static_cast<unsigned long long>(dropped));
  if (!summary_json.empty()) {
    std::ofstream(summary_json) << "{\"cycles\": " << cycles << ", \"deadline_misses\": " << misses
                                << ", \"snapshots_dropped\": " << dropped
                                << ", \"lateness_ns\": {\"p50\": " << p50 << ", \"p99\": " << p99
                                << ", \"p999\": " << p999 << ", \"max\": " << max << "}}\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  rig::io::lcm::LcmSettings settings;
  std::string url = settings.url;
  std::string log;
  double duration_s = 2.0;
  double period_s = 0.001;
  bool fast = false;
  bool loop_thread = false;
  std::string summary_json;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "rig-lcm-feed: %s needs a value\n", arg.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--url")
      url = value();
    else if (arg == "--log")
      log = value();
    else if (arg == "--duration")
      duration_s = std::atof(value().c_str());
    else if (arg == "--period")
      period_s = std::atof(value().c_str());
    else if (arg == "--fast")
      fast = true;
    else if (arg == "--loop-thread")
      loop_thread = true;
    else if (arg == "--summary-json")
      summary_json = value();
    else if (arg == "--prefix")
      settings.channel_prefix = value();
    else if (arg == "--state-rate")
      settings.state_rate_hz = std::atof(value().c_str());
    else if (arg == "--status-rate")
      settings.status_rate_hz = std::atof(value().c_str());
    else if (arg == "--signals-rate")
      settings.signals_rate_hz = std::atof(value().c_str());
    else {
      std::fprintf(stderr, "rig-lcm-feed: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  settings.url = url;

  Sinks sinks;
  if (url != "none") sinks.push_back(rig::io::lcm::make_lcm_publisher(settings));
  if (!log.empty()) sinks.push_back(rig::io::lcm::make_lcm_log_writer(log, settings));

  rig::io::RunInfo info;
  info.period_s = period_s;
  info.offline = fast;
  info.policy = "skip";
  for (auto& sink : sinks) sink->start(info);

  const auto cycles = static_cast<std::uint64_t>(duration_s / period_s + 0.5);
  if (loop_thread) {
    const int rc = run_threaded(sinks, cycles, period_s, summary_json);
    for (auto& sink : sinks) sink->stop();
    return rc;
  }
  const auto period_ns = static_cast<long long>(period_s * 1e9 + 0.5);
  timespec next{};
  clock_gettime(CLOCK_MONOTONIC, &next);
  for (std::uint64_t cycle = 0; cycle < cycles; ++cycle) {
    if (!fast) {
      clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
      next.tv_nsec += period_ns;
      while (next.tv_nsec >= 1'000'000'000) {
        next.tv_nsec -= 1'000'000'000;
        ++next.tv_sec;
      }
    }
    const rig::io::Snapshot snapshot = rig::test::make_synthetic_snapshot(cycle, period_s);
    for (auto& sink : sinks) sink->consume(snapshot, 0);
  }
  for (auto& sink : sinks) sink->stop();
  std::printf("rig-lcm-feed: fed %llu snapshots\n", static_cast<unsigned long long>(cycles));
  return 0;
}
