// The cost of one road query (model/road/surface.h) as a wheel's probe makes it: the probe rolls
// along the ASAM Belgian block (1001 x 341 cells of 1 cm, on its curved reference line; the copy
// repaired in the build tree) by 8.3 mm a query (30 km/h at 1 ms), keeping its hint, so that a
// query costs a cell step. For comparison: the same without a hint (a search over the reference
// line), an ISO 8608 class C grid and the tilted plane.
#include <benchmark/benchmark.h>

#include <vector>

#include "io/config/crg_file.h"
#include "model/road/crg_surface.h"
#include "model/road/iso8608.h"
#include "model/road/plane_surface.h"

namespace {

namespace road = rig::model::road;

/// Points along the grid at lateral position v, 8.3 mm apart, there and back again.
std::vector<std::pair<double, double>> track(const road::CrgSurface& s, double v) {
  std::vector<std::pair<double, double>> p;
  for (double u = s.u_first_m(); u <= s.u_last_m(); u += 0.0083) {
    double x = 0;
    double y = 0;
    s.world_point(u, v, x, y);
    p.emplace_back(x, y);
  }
  const std::size_t n = p.size();
  for (std::size_t i = n; i-- > 0;) p.push_back(p[i]);
  return p;
}

void rolling(benchmark::State& state, const road::CrgSurface& s, bool keep_hint) {
  const auto points = track(s, 0.7);
  road::SurfaceHint hint;
  std::size_t i = 0;
  for (auto _ : state) {
    if (!keep_hint) hint = {};
    const auto& [x, y] = points[i];
    benchmark::DoNotOptimize(s.height(x, y, hint));
    if (++i == points.size()) i = 0;
  }
}

const road::CrgSurface& belgian_block() {
  static const road::CrgSurface s(rig::io::config::load_crg_file(RIG_BELGIAN_BLOCK));
  return s;
}

void BM_BelgianBlockRollingProbe(benchmark::State& state) { rolling(state, belgian_block(), true); }
BENCHMARK(BM_BelgianBlockRollingProbe);

void BM_BelgianBlockNoHint(benchmark::State& state) { rolling(state, belgian_block(), false); }
BENCHMARK(BM_BelgianBlockNoHint);

void BM_Iso8608RollingProbe(benchmark::State& state) {
  road::Iso8608Params p;
  p.length_m = 200;
  static const road::CrgSurface s(road::generate_iso8608(p));
  rolling(state, s, true);
}
BENCHMARK(BM_Iso8608RollingProbe);

void BM_TiltedPlane(benchmark::State& state) {
  const road::PlaneSurface s(0.1, 0.02);
  road::SurfaceHint hint;
  double x = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.height(x, 0.5, hint));
    x += 0.0083;
  }
}
BENCHMARK(BM_TiltedPlane);

}  // namespace

BENCHMARK_MAIN();
