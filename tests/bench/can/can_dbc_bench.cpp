/// @file
/// ns per message of the DBC codec and the CAN mapping engines, on the example database.

#include <benchmark/benchmark.h>

#include <array>
#include <string>
#include <vector>

#include "tests/support/legacy_cycle.h"
#include "io/can/dbc/dbc_parser.h"
#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/rx_processor.h"
#include "io/can/mapping/tx_scheduler.h"

namespace {

namespace can = rig::io::can::mapping;
namespace dbc = rig::io::can::dbc;

const can::CanConfig& config() {
  static const can::CanConfig c =
      can::load_can_config(std::string(RIG_CAN_CONFIG_DIR) + "/steering-bench.toml");
  return c;
}

/// Decodes every signal of one message (arg = index in the DBC).
void BM_DecodeMessage(benchmark::State& state) {
  const dbc::MessageDef& m = config().database.messages[static_cast<std::size_t>(state.range(0))];
  const dbc::MessageCodec codec(m);
  std::array<std::uint8_t, 64> frame{};
  for (std::size_t i = 0; i < frame.size(); ++i) frame[i] = static_cast<std::uint8_t>(i * 37 + 11);
  std::vector<double> physical(m.signals.size());
  bool present[64];
  for (auto _ : state) {
    benchmark::DoNotOptimize(frame);
    codec.decode(frame.data(), m.length_bytes, physical,
                 std::span<bool>(present, m.signals.size()));
    benchmark::DoNotOptimize(physical.data());
  }
  state.SetLabel(m.name + " (" + std::to_string(m.signals.size()) + " signals)");
}

/// Encodes every signal of one message.
void BM_EncodeMessage(benchmark::State& state) {
  const dbc::MessageDef& m = config().database.messages[static_cast<std::size_t>(state.range(0))];
  const dbc::MessageCodec codec(m);
  std::vector<double> physical(m.signals.size(), 1.0);
  std::array<std::uint8_t, 64> frame{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(physical.data());
    codec.encode(physical, frame.data());
    benchmark::DoNotOptimize(frame);
  }
  state.SetLabel(m.name + " (" + std::to_string(m.signals.size()) + " signals)");
}

/// One received EPS_Status frame: lookup, CRC-8, counter, decode, clamp, convert.
void BM_RxOnFrame(benchmark::State& state) {
  can::RxProcessor rx(config());
  rig::model::Signals signals;
  rig::io::IoCounters counters;
  rx.reset(0, signals);
  const dbc::MessageDef& m = *config().database.find_message("EPS_Status");
  const dbc::SignalCodec counter(*m.find_signal("EPS_Counter"));
  std::array<std::uint8_t, 8> frame{0x10, 0x02, 0, 0, 0, 0, 0, 0};
  std::uint32_t k = 0;
  std::int64_t t = 0;
  for (auto _ : state) {
    counter.insert_raw(k, frame.data());
    frame[7] = can::crc8_sae_j1850(frame.data(), 7);
    k = (k + 1) % 16;
    t += 10'000'000;
    benchmark::DoNotOptimize(rx.on_frame(0x200, false, can::FrameFormat::kClassic, frame.data(), 8,
                                         t, signals, counters));
  }
  if (counters.checksum_failures + counters.counter_failures != 0) state.SkipWithError("rejected");
}

/// One sent RIG_SteeringWheel frame: convert, clamp, encode, counter, CRC-8.
void BM_TxEncode(benchmark::State& state) {
  can::TxScheduler tx(config());
  rig::model::Signals signals;
  rig::io::IoCounters counters;
  signals[rig::model::Signal::kSteeringWheelAngle] = 0.3;
  can::TxFrame frame;
  rig::test::LegacyCycle legacy;
  for (auto _ : state) {
    tx.encode(0, legacy.view(signals), frame, counters);
    benchmark::DoNotOptimize(frame);
  }
}

BENCHMARK(BM_DecodeMessage)->DenseRange(0, 7);
BENCHMARK(BM_EncodeMessage)->DenseRange(0, 7);
BENCHMARK(BM_RxOnFrame);
BENCHMARK(BM_TxEncode);

}  // namespace
