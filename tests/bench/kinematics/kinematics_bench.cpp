// Eq. (29) lookup cost: all five functions of one wheel with partials d/dz, d/du, bilinear and
// bicubic, on a 21 x 21 grid.
#include <benchmark/benchmark.h>

#include "model/kinematics/wheel_kinematics.h"

namespace {

using namespace rig::model::kinematics;

void BM_WheelKinematics(benchmark::State& state) {
  const auto method = static_cast<Interpolation>(state.range(0));
  SuspensionGeometry g;
  g.steering_arm_m = 0.15;
  const WheelKinematics k =
      generate_wheel_kinematics(g, Grid2D{-0.1, 0.01, 21, -0.08, 0.008, 21}, method);
  double z = -0.05, u = 0.013;
  for (auto _ : state) {
    benchmark::DoNotOptimize(z);
    benchmark::DoNotOptimize(k.evaluate(z, u));
    z += 1e-9;
  }
  state.SetLabel(method == Interpolation::kBicubic ? "bicubic, 5 functions"
                                                   : "bilinear, 5 functions");
}
BENCHMARK(BM_WheelKinematics)
    ->Arg(static_cast<int>(Interpolation::kBilinear))
    ->Arg(static_cast<int>(Interpolation::kBicubic));

void BM_SingleTable(benchmark::State& state) {
  const auto method = static_cast<Interpolation>(state.range(0));
  const WheelKinematics k = generate_wheel_kinematics(
      SuspensionGeometry{}, Grid2D{-0.1, 0.01, 21, -0.08, 0.008, 21}, method);
  const WheelPose p = k.evaluate(0, 0);
  (void)p;
  std::vector<double> v(21 * 21, 1.0);
  const KinematicTable t(Grid2D{-0.1, 0.01, 21, -0.08, 0.008, 21}, v);
  double z = 0.031, u = -0.02;
  for (auto _ : state) {
    benchmark::DoNotOptimize(z);
    benchmark::DoNotOptimize(t.evaluate(z, u, method));
  }
}
BENCHMARK(BM_SingleTable)
    ->Arg(static_cast<int>(Interpolation::kBilinear))
    ->Arg(static_cast<int>(Interpolation::kBicubic));

}  // namespace

BENCHMARK_MAIN();
