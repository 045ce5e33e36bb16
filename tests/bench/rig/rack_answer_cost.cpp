/// @file
/// The rack-answer probe for callgrind (scripts/step-instructions): N answers of the
/// rack-in-the-loop path (rack_answer_path.h: RACK_Position in, the step, RIG_TieRodForces out)
/// inside measured_answers(), after 2000 cycles of the weave, so that
/// `valgrind --tool=callgrind --toggle-collect=measured_answers*` counts exactly those
/// instructions. Checks each answer: the rack frame accepted, one frame sent, its CRC-8 and its
/// forces those of the model's report (to the DBC's 1 N); exit 1 if not.
///   rig_rack_answer_cost [ANSWERS=1000] [CONFIG=config/rack-in-the-loop.toml]

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/checksum.h"
#include "tests/bench/rig/rack_answer_path.h"

namespace {

constexpr std::size_t kWarmUp = 2000;

/// The answer's forces and CRC agree with the model's report; prints the first disagreement.
bool answer_ok(const rig::bench::RackAnswerPath& path, std::size_t sent) {
  namespace dbc = rig::io::can::dbc;
  const dbc::MessageDef& m = *path.can().database.find_message("RIG_TieRodForces");
  const auto& f = path.answer_frame();
  const double left = dbc::SignalCodec(*m.find_signal("TieRodForceLeft")).decode(f.data.data());
  const double right = dbc::SignalCodec(*m.find_signal("TieRodForceRight")).decode(f.data.data());
  const auto& s = path.report().steering;
  const bool ok = path.last_rx() == rig::io::can::mapping::RxResult::kAccepted && sent == 1 &&
                  f.id == m.id &&
                  f.data[7] == rig::io::can::mapping::crc8_sae_j1850(f.data.data(), 7) &&
                  std::abs(left - s.tie_rod_force_left_n) <= 0.5 &&
                  std::abs(right - s.tie_rod_force_right_n) <= 0.5;
  if (!ok)
    std::fprintf(stderr, "answer: rx %d, %zu sent, left %g (model %g), right %g (model %g)\n",
                 static_cast<int>(path.last_rx()), sent, left, s.tie_rod_force_left_n, right,
                 s.tie_rod_force_right_n);
  return ok;
}

}  // namespace

/// The measured region (not inlined, so that callgrind can toggle on it).
__attribute__((noinline)) std::size_t measured_answers(rig::bench::RackAnswerPath& path,
                                                       std::size_t first, std::size_t n) {
  std::size_t sent = 0;
  for (std::size_t k = first; k < first + n; ++k) sent += path.answer(k);
  return sent;
}

int main(int argc, char** argv) {
  const auto n = static_cast<std::size_t>(argc > 1 ? std::atol(argv[1]) : 1000);
  const std::string config =
      argc > 2 ? argv[2] : std::string(RIG_SOURCE_DIR) + "/config/rack-in-the-loop.toml";
  rig::bench::RackAnswerPath path(config, kWarmUp + n);
  for (std::size_t k = 0; k < kWarmUp; ++k) {
    if (!answer_ok(path, path.answer(k))) return 1;
  }
  const std::size_t sent = measured_answers(path, kWarmUp, n);
  if (sent != n || !answer_ok(path, 1)) return 1;
  const auto& s = path.report().steering;
  std::printf("t = %.3f s, rack %.6f m, tie rods %.1f / %.1f N, %zu answers\n",
              path.report().time_s, s.rack_travel_m, s.tie_rod_force_left_n,
              s.tie_rod_force_right_n, sent);
  return 0;
}
