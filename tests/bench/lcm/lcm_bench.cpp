/// @file
/// Cost per RIG_STATE message on the non-RT dispatcher thread (a 2-unit, 6-wheel synthetic
/// vehicle, as tests/io/lcm/synthetic_snapshot.h builds it).

#include <benchmark/benchmark.h>

#include "io/lcm/lcm_publisher.h"
#include "io/lcm/snapshot_encoder.h"
#include "tests/io/lcm/synthetic_snapshot.h"

namespace {

rig::io::lcm::LcmSettings state_only(const std::string& url) {
  rig::io::lcm::LcmSettings settings;
  settings.url = url;
  settings.signals_rate_hz = 0;
  settings.status_rate_hz = 0;
  return settings;
}

void BM_EncodeState(benchmark::State& state) {
  rig::io::lcm::SnapshotEncoder encoder(state_only("memq://"));
  encoder.start(rig::io::RunInfo{});
  rig::io::Snapshot snapshot = rig::test::make_synthetic_snapshot(1, 0.001);
  rig::io::lcm::EncodedMessage out[3];
  std::size_t bytes = 0;
  for (auto _ : state) {
    ++snapshot.timing.cycle;
    benchmark::DoNotOptimize(encoder.encode(snapshot, 0, out));
    bytes = out[0].size;
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_EncodeState);

void BM_EncodeAllChannels(benchmark::State& state) {
  rig::io::lcm::LcmSettings settings;
  settings.state_rate_hz = settings.signals_rate_hz = settings.status_rate_hz = 1000;
  rig::io::lcm::SnapshotEncoder encoder(settings);
  encoder.start(rig::io::RunInfo{});
  rig::io::Snapshot snapshot = rig::test::make_synthetic_snapshot(1, 0.001);
  rig::io::lcm::EncodedMessage out[3];
  for (auto _ : state) {
    ++snapshot.timing.cycle;
    benchmark::DoNotOptimize(encoder.encode(snapshot, 0, out));
  }
}
BENCHMARK(BM_EncodeAllChannels);

void BM_EncodeAndPublishState_udpm(benchmark::State& state) {
  rig::io::lcm::LcmPublisher publisher(state_only(rig::io::lcm::kDefaultLcmUrl));
  publisher.start(rig::io::RunInfo{});
  if (!publisher.active()) {
    state.SkipWithError("LCM is not available here (no multicast route)");
    return;
  }
  rig::io::Snapshot snapshot = rig::test::make_synthetic_snapshot(1, 0.001);
  for (auto _ : state) {
    ++snapshot.timing.cycle;
    publisher.consume(snapshot, 0);
  }
  state.counters["send_failures"] = static_cast<double>(publisher.send_failures());
  publisher.stop();
}
BENCHMARK(BM_EncodeAndPublishState_udpm);

}  // namespace
