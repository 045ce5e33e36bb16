// Benchmarks of the model core: a quarter-car step, a pendulum DAE step, and M_VI factorization
// dense vs arrowhead. The CPU time of the pendulum DAE against the CVODE reference is in
// cvode_reference_bench.cpp (built where SUNDIALS is).
#include <memory>

#include <benchmark/benchmark.h>

#include "model/paper/coupled_pendulums.h"
#include "model/paper/quarter_car.h"
#include "model/solver/arrowhead_factorization.h"
#include "model/solver/dense_factorization.h"

namespace {

using rig::model::paper::CoupledPendulums;
using rig::model::paper::paper_maneuver_inputs;
using rig::model::paper::QuarterCar;

void BM_QuarterCarStep(benchmark::State& state) {
  constexpr double h = 1e-3;
  auto car = std::make_unique<QuarterCar>();
  long k = 0;
  for (auto _ : state) {
    car->step(h, paper_maneuver_inputs(static_cast<double>(k) * h));
    benchmark::DoNotOptimize(car->speed_mps());
    if (++k == 20000) {  // the whole maneuver, then again
      state.PauseTiming();
      car = std::make_unique<QuarterCar>();
      k = 0;
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_QuarterCarStep);

void BM_PendulumDaeStep(benchmark::State& state) {
  constexpr double h = 1e-3;
  auto p = std::make_unique<CoupledPendulums>();
  long k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(p->step(h));
    if (++k == 5000) {
      state.PauseTiming();
      p = std::make_unique<CoupledPendulums>();
      k = 0;
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_PendulumDaeStep);

// Factorization + one solve of a vehicle-sized M_VI (eqs. 30-31): body 6 DOF, two axles of
// 10 DOF each (hub travels, spins, compliant axle states), dense LU vs the arrowhead form.
Eigen::MatrixXd vehicle_like_matrix(const rig::model::solver::ArrowheadPartition& p) {
  const Eigen::Index n = p.total_size();
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
  a.diagonal().array() += static_cast<double>(n);
  Eigen::Index o1 = p.body_size;
  for (std::size_t i = 0; i < p.leaf_sizes.size(); ++i) {
    Eigen::Index o2 = p.body_size;
    for (std::size_t j = 0; j < p.leaf_sizes.size(); ++j) {
      if (i != j) a.block(o1, o2, p.leaf_sizes[i], p.leaf_sizes[j]).setZero();
      o2 += p.leaf_sizes[j];
    }
    o1 += p.leaf_sizes[i];
  }
  return a;
}

void BM_MviDense26(benchmark::State& state) {
  const rig::model::solver::ArrowheadPartition p{6, {10, 10}};
  const Eigen::MatrixXd a = vehicle_like_matrix(p);
  rig::model::solver::DenseFactorization<Eigen::Dynamic> f(p.total_size());
  const Eigen::VectorXd b = Eigen::VectorXd::Random(p.total_size());
  Eigen::VectorXd x(p.total_size());
  for (auto _ : state) {
    f.compute(a);
    f.solve(b, x);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_MviDense26);

void BM_MviArrowhead26(benchmark::State& state) {
  const rig::model::solver::ArrowheadPartition p{6, {10, 10}};
  const Eigen::MatrixXd a = vehicle_like_matrix(p);
  rig::model::solver::ArrowheadFactorization f(p);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(p.total_size());
  Eigen::VectorXd x(p.total_size());
  for (auto _ : state) {
    f.compute(a);
    f.solve(b, x);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_MviArrowhead26);

}  // namespace

BENCHMARK_MAIN();
