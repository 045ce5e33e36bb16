// One full vehicle step (eq. 8 over all blocks) of the sedan and the 6x4 truck, in a steady
// cornering + driving state so that every force law is active; and an offline 20 s run.
#include <cmath>

#include <benchmark/benchmark.h>

#include "io/config/vehicle_file.h"
#include "model/road/crg_surface.h"
#include "model/vehicle/vehicle_model.h"
#ifdef RIG_BELGIAN_BLOCK
#include "io/config/crg_file.h"
#endif
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
/// Differentials (issue 17 item 6): the all-wheel-drive sedan (viscous centre, limited-slip
/// rear, open front) and the 6x4 tractor with and without its modelled tandem differentials.
void BM_Sedan4x4Step(benchmark::State& state) {
  step_bench(state, RIG_SOURCE_DIR "/config/vehicles/sedan-4x4.toml");
}
void BM_Tractor6x4Step(benchmark::State& state) {
  step_bench(state, RIG_SOURCE_DIR "/config/vehicles/tractor-6x4.toml");
}
void BM_Tractor6x4DiffStep(benchmark::State& state) {
  step_bench(state, RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-diff.toml");
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

/// The road's cost (issue 16): the sedan straight at 5 m/s, on the plane or over a surface. The
/// Belgian block is 10 m long, so every 1000 steps the car is put back at its start (untimed):
/// the same 1200 steps as scripts/step-instructions' callgrind count, again and again.
void road_bench(benchmark::State& state, std::shared_ptr<const rig::model::road::Surface> road) {
  using rig::test::kRoadBenchSteps;
  using rig::test::kRoadBenchWarmSteps;
  rig::model::vehicle::VehicleParams p =
      rig::io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  p.road.surface = std::move(road);
  rig::model::vehicle::VehicleModel m(p, 1e-3);
  Signals s = rig::test::straight_inputs();
  int left = 0;
  for (auto _ : state) {
    if (left == 0) {
      state.PauseTiming();
      m.reset(0, 0, 0);
      m.set_forward_speed(rig::test::kRoadBenchSpeedMps);
      for (int k = 0; k < kRoadBenchWarmSteps; ++k) (void)m.step(s);
      left = kRoadBenchSteps;
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(m.step(s));
    --left;
  }
}

void BM_SedanStepStraightPlane(benchmark::State& state) { road_bench(state, nullptr); }
BENCHMARK(BM_SedanStepStraightPlane);

#ifdef RIG_BELGIAN_BLOCK
/// Over ASAM's Belgian block (OpenCRG, 1 cm grid): at most 1.4x the plane (issue 16).
void BM_SedanStepStraightBelgianBlock(benchmark::State& state) {
  rig::model::road::Placement at;
  at.given = true;
  at.x_m = rig::test::kRoadBenchBlockX;
  road_bench(state, std::make_shared<rig::model::road::CrgSurface>(
                        rig::io::config::load_crg_file(RIG_BELGIAN_BLOCK), at));
}
BENCHMARK(BM_SedanStepStraightBelgianBlock);
#endif

BENCHMARK(BM_SedanStep);
BENCHMARK(BM_SedanStepEnhancedSteering);
BENCHMARK(BM_TruckStep);
BENCHMARK(BM_Sedan4x4Step);
BENCHMARK(BM_Tractor6x4Step);
BENCHMARK(BM_Tractor6x4DiffStep);
BENCHMARK(BM_Sedan20sOffline)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
