#pragma once
/// @file
/// The rig's in-process answer to a rack frame (issue 15 item 6: "wall-clock latency is a
/// benchmark, not a test"), assembled from a run configuration with the rig's own pieces, in
/// the order of one Executive cycle (rig/executive.cpp) and CanBridge's receive / transmit
/// (io/can/bridge/can_bridge.cpp), without the socket:
///
///   RxProcessor::on_frame (RACK_Position: CRC-8, alive counter, decode, clamp, SI)
///   -> check_timeouts, the inputs routed to CAN copied into the loop's signals
///   -> the driver (the table holding throttle and gear)
///   -> the model's step (config/rack-in-the-loop.toml: the sedan, its rack prescribed)
///   -> fill_report -> TxScheduler::due_frames (RIG_TieRodForces: counter, CRC-8)
///
/// The rack's frames are what a bench sends: the rack on a sine, counter k mod 16, CRC-8 over
/// bytes 0..6, built at construction (nothing allocates in answer()).

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "io/can/mapping/rx_processor.h"
#include "io/can/mapping/tx_scheduler.h"
#include "model/report.h"
#include "model/signals.h"
#include "model/stepped_model.h"
#include "rig/config.h"
#include "rig/driver/driver.h"

namespace rig::bench {

/// The rack's motion in the bench's frames: u = A sin(2 pi f t), u' its derivative.
struct RackSine {
  double amplitude_m = 0.004;  ///< ~0.5 rad at the steering wheel (i_SB 8 mm/rad)
  double frequency_hz = 1.0;   ///< a weave at the configuration's 80 km/h
};

class RackAnswerPath {
 public:
  using Frame = std::array<std::uint8_t, 8>;

  /// Loads `config_file` as `rig run` does (load_config, make_model, make_driver, the [can]
  /// files) and builds `cycles` rack frames. Throws what those throw (bad configuration).
  RackAnswerPath(const std::filesystem::path& config_file, std::size_t cycles, RackSine sine = {});

  [[nodiscard]] std::size_t cycles() const noexcept { return frames_.size(); }

  /// Cycle `k` (< cycles(), in order from 0): the rack's frame k in, one step, the answers out.
  /// Returns the number of frames encoded (1: the tie-rod forces are due every cycle).
  std::size_t answer(std::size_t k) noexcept;

  /// The last cycle's first encoded frame.
  [[nodiscard]] const io::can::mapping::TxFrame& answer_frame() const noexcept {
    return tx_frames_[0];
  }
  /// RxProcessor's verdict on the last frame (kAccepted for every frame built here).
  [[nodiscard]] io::can::mapping::RxResult last_rx() const noexcept { return last_rx_; }
  [[nodiscard]] const model::ModelReport& report() const noexcept { return report_; }
  [[nodiscard]] const model::Signals& signals() const noexcept { return signals_; }
  [[nodiscard]] const io::can::mapping::CanConfig& can() const noexcept { return can_; }
  [[nodiscard]] const io::IoCounters& counters() const noexcept { return counters_; }

 private:
  void build_frames(std::size_t cycles, RackSine sine);

  RigConfig config_;
  io::can::mapping::CanConfig can_;
  std::unique_ptr<model::SteppedModel> model_;
  std::unique_ptr<driver::Driver> driver_;
  io::can::mapping::RxProcessor rx_;
  io::can::mapping::TxScheduler tx_;
  std::uint32_t rx_id_ = 0;
  bool rx_extended_ = false;
  std::int64_t period_ns_ = 1'000'000;
  std::vector<Frame> frames_;
  model::Signals rx_signals_{};  // what the RX engine writes (CanBridge's copy)
  model::Signals signals_{};     // the loop's signals
  model::ModelReport report_{};
  io::IoCounters counters_{};
  io::can::mapping::RxResult last_rx_ = io::can::mapping::RxResult::kAccepted;
  std::array<io::can::mapping::TxFrame, 4> tx_frames_{};
};

}  // namespace rig::bench
