// The cost of the one TMeasy law per evaluation, as the vehicle calls it: the characteristic at
// a wheel load (once per contact and step), slip and f(s) (eqs. 14-17), and the deflection
// dynamics with the limited forces (eqs. 22-26).
#include <benchmark/benchmark.h>

#include "model/tire/tmeasy_tire.h"

namespace {

using rig::model::tire::TireKinematics;
namespace tire = rig::model::tire;

const TireKinematics kCornering{20.0, -0.6, 68.0, 0.3};  // cornering while driving
constexpr double kLoad = 4100.0;

void BM_TireCharacteristic(benchmark::State& state) {
  const tire::TmeasyParams p = tire::default_215_55_r18();
  double load = kLoad;
  for (auto _ : state) {
    benchmark::DoNotOptimize(load);
    benchmark::DoNotOptimize(tire::characteristic_at(p, load, 1.0));
  }
}
BENCHMARK(BM_TireCharacteristic);

void BM_TireSlip(benchmark::State& state) {
  const tire::TmeasyParams p = tire::default_215_55_r18();
  const tire::TireCharacteristic c = tire::characteristic_at(p, kLoad, 1.0);
  TireKinematics k = kCornering;
  for (auto _ : state) {
    benchmark::DoNotOptimize(k);
    benchmark::DoNotOptimize(tire::slip_of(c, k, p.velocity_floor_mps));
  }
}
BENCHMARK(BM_TireSlip);

void BM_TireForces(benchmark::State& state) {
  const tire::TmeasyParams p = tire::default_215_55_r18();
  const tire::TireCharacteristic c = tire::characteristic_at(p, kLoad, 1.0);
  const tire::TireSlip slip = tire::slip_of(c, kCornering, p.velocity_floor_mps);
  Eigen::Vector2d s(0.002, 0.003);
  for (auto _ : state) {
    benchmark::DoNotOptimize(s);
    benchmark::DoNotOptimize(tire::tire_forces(p, c, kCornering, slip, s));
    s(0) += 1e-12;  // keep the call from being hoisted
  }
}
BENCHMARK(BM_TireForces);

}  // namespace

BENCHMARK_MAIN();
