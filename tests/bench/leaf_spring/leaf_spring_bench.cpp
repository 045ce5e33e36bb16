// One evaluation of the five-link leaf spring as the rigid axle's step calls it: warm-started
// from the last step's solution, the seat moving along the 1 ms load history (bounce, pothole,
// tramp, wind-up) about the van's static pose; and, for scale, a cold evaluation from the free
// leaf's state at a pose 1 mm away.
#include <benchmark/benchmark.h>

#include <Eigen/LU>

#include "model/vehicle/leaf_spring/leaf_spring.h"
#include "tests/model/vehicle/leaf_spring/load_history.h"
#include "tests/model/vehicle/leaf_spring/van_leaf_params.h"

namespace {

namespace ls = rig::model::vehicle::leaf_spring;

ls::SeatPose static_pose(const ls::LeafSpring& leaf, ls::LeafState& s) {
  ls::SeatPose q = ls::SeatPose::Zero();
  for (int k = 0; k < 50; ++k) {  // Newton on the element's partials to the static load
    const ls::LeafForces f = leaf.evaluate(q, s);
    q -= f.d_on_axle_d_seat.lu().solve(f.on_axle +
                                       Eigen::Vector3d(0.0, rig::test::kVanLeafStaticLoadN, 0.0));
  }
  return q;
}

void BM_LeafSpringWarmStep(benchmark::State& state) {
  const ls::LeafSpring leaf(rig::test::van_rear_leaf());
  ls::LeafState s = leaf.free_state();
  const ls::SeatPose stat = static_pose(leaf, s);
  int step = 0;
  long iterations = 0;
  for (auto _ : state) {
    const ls::LeafForces f = leaf.evaluate(rig::test::leaf_history_pose(stat, step), s);
    benchmark::DoNotOptimize(f.on_axle);
    iterations += f.iterations;
    step = (step + 1) % 10000;
  }
  state.counters["newton_iterations"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_LeafSpringWarmStep);

void BM_LeafSpringAtRest(benchmark::State& state) {  // converged already: one assembly, no solve
  const ls::LeafSpring leaf(rig::test::van_rear_leaf());
  ls::LeafState s = leaf.free_state();
  const ls::SeatPose stat = static_pose(leaf, s);
  for (auto _ : state) benchmark::DoNotOptimize(leaf.evaluate(stat, s).on_axle);
}
BENCHMARK(BM_LeafSpringAtRest);

}  // namespace

BENCHMARK_MAIN();
