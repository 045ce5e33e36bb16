// The step-cost probe of scripts/step-instructions: N model steps in a steady cornering + driving
// state (every force law active) inside measured_steps(), so that
// `valgrind --tool=callgrind --toggle-collect=measured_steps*` counts exactly those instructions.
//   rig_step_cost vehicle FILE | combination FILE  [STEPS=1000]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/config/combination_file.h"
#include "io/config/strict_table.h"
#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/vehicle/vehicle_model.h"

namespace {

using rig::model::Signal;
using rig::model::Signals;

Signals inputs() {
  Signals s;
  for (std::size_t i = 0; i < rig::model::index(rig::model::kFirstOutput); ++i) s.valid[i] = true;
  s[Signal::kGearRequest] = 99;
  s[Signal::kThrottlePedal] = 0.3;
  s[Signal::kSteeringWheelAngleCmd] = 0.5;
  return s;
}

rig::model::combination::CombinationParams load_combination(const std::string& file) {
  const toml::table doc = rig::io::config::load_toml_file(file);
  rig::io::config::StrictTable top(doc, file, "top level");
  rig::io::config::StrictTable m = top.table("model");
  (void)m.string("kind");
  const auto settings = rig::io::config::read_combination_model(m);
  rig::model::combination::CombinationParams p;
  p.units = settings.units;
  p.joints = settings.joints;
  p.newton = rig::model::combination::default_combination_newton_params();
  return p;
}

}  // namespace

/// The measured region (not inlined, so that callgrind can toggle on it).
__attribute__((noinline)) void measured_steps(rig::model::SteppedModel& m, Signals& s, int n) {
  for (int k = 0; k < n; ++k) (void)m.step(s);
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: rig_step_cost vehicle|combination FILE [STEPS]\n");
    return 2;
  }
  const std::string kind = argv[1];
  const int n = argc > 3 ? std::atoi(argv[3]) : 1000;
  Signals s = inputs();
  auto run = [&](auto& m) {
    m.set_forward_speed(15);
    for (int k = 0; k < 2000; ++k) (void)m.step(s);  // into a steady turn
    measured_steps(m, s, n);
    std::printf("t = %.3f s\n", m.time_s());
  };
  if (kind == "vehicle") {
    rig::model::vehicle::VehicleModel m(rig::io::config::load_vehicle_file(argv[2]), 1e-3);
    run(m);
  } else {
    rig::model::combination::Combination m(load_combination(argv[2]), 1e-3);
    run(m);
  }
  return 0;
}
