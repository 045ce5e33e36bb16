#include "tests/bench/rig/rack_answer_path.h"

#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>

#include "io/can/bridge/can_settings.h"
#include "io/can/mapping/checksum.h"
#include "rig/model_factory.h"

namespace rig::bench {
namespace {

namespace mapping = io::can::mapping;

mapping::CanConfig load_can(const RigConfig& config) {
  if (!config.can) throw std::runtime_error(config.file.string() + ": no [can] section");
  return io::can::bridge::load_can_files(*config.can);
}

const io::can::dbc::SignalDef& signal_of(const io::can::dbc::MessageDef& m, const char* name) {
  const io::can::dbc::SignalDef* s = m.find_signal(name);
  if (s == nullptr) throw std::runtime_error(m.name + " has no signal " + name);
  return *s;
}

}  // namespace

RackAnswerPath::RackAnswerPath(const std::filesystem::path& config_file, std::size_t cycles,
                               RackSine sine)
    : config_(load_config(config_file)),
      can_(load_can(config_)),
      model_(make_model(config_)),
      driver_(make_driver(config_)),
      rx_(can_),
      tx_(can_),
      period_ns_(std::llround(config_.rig.period_s * 1e9)) {
  signals_.source = config_.routing.source;
  build_frames(cycles, sine);
  rx_.reset(0, rx_signals_);  // CanBridge::start at the loop's first cycle
  tx_.start(0);
}

/// What the bench's rack sends in cycle k: position and speed, then counter and CRC-8 SAE J1850
/// over bytes 0..6 into byte 7 (config/can/rack-bench.toml).
void RackAnswerPath::build_frames(std::size_t cycles, RackSine sine) {
  const io::can::dbc::MessageDef* m = can_.database.find_message("RACK_Position");
  if (m == nullptr) throw std::runtime_error(config_.file.string() + ": no RACK_Position");
  rx_id_ = m->id;
  rx_extended_ = m->extended;
  const io::can::dbc::SignalCodec position(signal_of(*m, "RackPositionMeasured"));
  const io::can::dbc::SignalCodec speed(signal_of(*m, "RackSpeedMeasured"));
  const io::can::dbc::SignalCodec counter(signal_of(*m, "RP_Counter"));
  const double w = 2 * std::numbers::pi * sine.frequency_hz;
  frames_.resize(cycles);
  for (std::size_t k = 0; k < cycles; ++k) {
    Frame& f = frames_[k];
    const double t = static_cast<double>(k + 1) * config_.rig.period_s;  // the cycle's end
    position.encode(sine.amplitude_m * std::sin(w * t), f.data());
    speed.encode(sine.amplitude_m * w * std::cos(w * t), f.data());
    counter.insert_raw(k % 16, f.data());
    f[7] = mapping::crc8_sae_j1850(f.data(), 7);
  }
}

std::size_t RackAnswerPath::answer(std::size_t k) noexcept {
  const std::int64_t now_ns = static_cast<std::int64_t>(k + 1) * period_ns_;  // lock-step grid
  // inputs: CanBridge::receive
  last_rx_ = rx_.on_frame(rx_id_, rx_extended_, mapping::FrameFormat::kClassic, frames_[k].data(),
                          frames_[k].size(), now_ns, rx_signals_, counters_);
  rx_.check_timeouts(now_ns, rx_signals_, counters_);
  for (std::size_t i = 0; i < model::kSlotCount; ++i) {
    if (!config_.routing.can_inputs[i]) continue;
    signals_.value[i] = rx_signals_.value[i];
    signals_.valid[i] = rx_signals_.valid[i];
  }
  // driver and model: Executive::cycle
  if (driver_) driver_->update(model_->time_s(), signals_);
  (void)model_->step(signals_);
  model_->fill_report(report_);
  report_.valid = 1;
  // outputs: CanBridge::transmit
  const io::signals::CycleView view{signals_, report_};
  return tx_.due_frames(now_ns, view, std::span<mapping::TxFrame>(tx_frames_), counters_);
}

}  // namespace rig::bench
