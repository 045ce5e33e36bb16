/// Overhead of one executive cycle without a real model: clock reads, driver table lookup, the
/// snapshot handoff (Signals + ModelReport copy into the ring) and the statistics, on a virtual
/// clock (no sleeping). Reported per cycle.

#include <benchmark/benchmark.h>

#include "rig/driver/table_driver.h"
#include "rig/event_log.h"
#include "rig/executive.h"
#include "rig/rt/clock.h"

namespace {

/// A model whose step does nothing but advance time: isolates the executive's own cost.
class NullModel final : public rig::model::SteppedModel {
 public:
  [[nodiscard]] double step_size_s() const noexcept override { return 0.001; }
  [[nodiscard]] double time_s() const noexcept override { return static_cast<double>(n_) * 0.001; }
  rig::model::StepStatus step(rig::model::Signals& s) noexcept override {
    ++n_;
    s.set(rig::model::Signal::kVehicleSpeed, 1.0);
    return rig::model::StepStatus::kOk;
  }
  void fill_report(rig::model::ModelReport& r) const noexcept override { r.time_s = time_s(); }

 private:
  std::uint64_t n_ = 0;
};

void BM_ExecutiveCycle(benchmark::State& state) {
  constexpr std::int64_t kBatch = 200;  // fewer than the ring's slots: nothing is dropped
  rig::driver::TableDriverParams table;
  table.columns = {rig::model::index(rig::model::Signal::kThrottlePedal)};
  table.times_s = {0.0, 1e6};
  table.values = {0.0, 1.0};
  rig::driver::TableDriver driver(table);  // feeds its one column
  rig::Executive::Sources sources{};
  sources[rig::model::index(rig::model::Signal::kThrottlePedal)] =
      rig::model::SignalSource::kDriver;
  rig::EventLog log("");
  while (state.KeepRunningBatch(kBatch)) {
    state.PauseTiming();
    NullModel model;
    rig::rt::VirtualClock clock;
    rig::ExecutiveParams p;
    p.duration_s = static_cast<double>(kBatch) * 0.001;
    rig::Executive exec(p, clock, model, &driver, {}, {}, log, sources);
    state.ResumeTiming();
    benchmark::DoNotOptimize(exec.run_loop());
    state.PauseTiming();
    if (exec.cycles() != static_cast<std::uint64_t>(kBatch))
      state.SkipWithError("wrong cycle count");
    state.ResumeTiming();
  }
}
BENCHMARK(BM_ExecutiveCycle)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
