// One full vehicle step (eq. 8 over all blocks) of the sedan and the 6x4 truck, in a steady
// cornering + driving state so that every force law is active; and an offline 20 s run.
#include <cmath>

#include <benchmark/benchmark.h>

#include "io/config/vehicle_file.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/bench_inputs.h"

namespace {

using rig::model::Signal;
using rig::model::Signals;

void step_bench(
    benchmark::State& state, const char* file,
    rig::model::vehicle::SteeringModel steering = rig::model::vehicle::SteeringModel::kSimple) {
  rig::model::vehicle::VehicleParams p = rig::io::config::load_vehicle_file(file);
  if (steering != rig::model::vehicle::SteeringModel::kSimple) p.steering.model = steering;
  rig::model::vehicle::VehicleModel m(p, 1e-3);
  Signals s = rig::test::cornering_inputs();
  m.set_forward_speed(15);
  for (int k = 0; k < 2000; ++k) (void)m.step(s);  // into a steady turn
  for (auto _ : state) {
    benchmark::DoNotOptimize(m.step(s));
  }
}

void BM_SedanStep(benchmark::State& state) {
  step_bench(state, RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}
/// The same step with the enhanced steering (issue 15: at most 1.3x the simple model's step).
void BM_SedanStepEnhancedSteering(benchmark::State& state) {
  step_bench(state, RIG_SOURCE_DIR "/config/vehicles/sedan.toml",
             rig::model::vehicle::SteeringModel::kEnhanced);
}
void BM_TruckStep(benchmark::State& state) {
  step_bench(state, RIG_SOURCE_DIR "/config/vehicles/truck-3axle.toml");
}

/// 20 s of a double-lane-change-like steering input at 60 km/h, offline (wall time per run).
void BM_Sedan20sOffline(benchmark::State& state) {
  const auto params =
      rig::io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  for (auto _ : state) {
    rig::model::vehicle::VehicleModel m(params, 1e-3);
    Signals s = rig::test::cornering_inputs();
    m.set_forward_speed(60 / 3.6);
    for (int k = 0; k < 20000; ++k) {
      const double t = k * 1e-3;
      s[Signal::kSteeringWheelAngleCmd] =
          (t > 2 && t < 6) ? 1.0 * std::sin(M_PI * (t - 2) / 2) : 0.0;
      benchmark::DoNotOptimize(m.step(s));
    }
  }
}

BENCHMARK(BM_SedanStep);
BENCHMARK(BM_SedanStepEnhancedSteering);
BENCHMARK(BM_TruckStep);
BENCHMARK(BM_Sedan20sOffline)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
