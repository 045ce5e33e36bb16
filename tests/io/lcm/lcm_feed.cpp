/// @file
/// rig-lcm-feed: drives the LCM sinks the way the executive's dispatcher does, with synthetic
/// snapshots (tests/io/lcm/synthetic_snapshot.h), in real time or as fast as possible. For the
/// LCM integration tests, which must not depend on the executive.
///
///   rig-lcm-feed [--url URL|none] [--log FILE] [--duration S] [--period S] [--fast]
///                [--prefix P] [--state-rate HZ] [--status-rate HZ] [--signals-rate HZ]

#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "io/lcm/lcm_sinks.h"
#include "tests/io/lcm/synthetic_snapshot.h"

int main(int argc, char** argv) {
  rig::io::LcmSettings settings;
  std::string url = settings.url;
  std::string log;
  double duration_s = 2.0;
  double period_s = 0.001;
  bool fast = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "rig-lcm-feed: %s needs a value\n", arg.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--url") url = value();
    else if (arg == "--log") log = value();
    else if (arg == "--duration") duration_s = std::atof(value().c_str());
    else if (arg == "--period") period_s = std::atof(value().c_str());
    else if (arg == "--fast") fast = true;
    else if (arg == "--prefix") settings.channel_prefix = value();
    else if (arg == "--state-rate") settings.state_rate_hz = std::atof(value().c_str());
    else if (arg == "--status-rate") settings.status_rate_hz = std::atof(value().c_str());
    else if (arg == "--signals-rate") settings.signals_rate_hz = std::atof(value().c_str());
    else {
      std::fprintf(stderr, "rig-lcm-feed: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  settings.url = url;

  std::vector<std::unique_ptr<rig::io::SnapshotSink>> sinks;
  if (url != "none") sinks.push_back(rig::io::make_lcm_publisher(settings));
  if (!log.empty()) sinks.push_back(rig::io::make_lcm_log_writer(log, settings));

  rig::io::RunInfo info;
  info.period_s = period_s;
  info.offline = fast;
  info.policy = "skip";
  for (auto& sink : sinks) sink->start(info);

  const auto cycles = static_cast<std::uint64_t>(duration_s / period_s + 0.5);
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
