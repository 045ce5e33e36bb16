// The query-cost probe (callgrind, repeatable whatever the machine's load): N queries of a probe
// rolling along the Belgian block at v = 0.7 m, 8.3 mm apart, there and back, keeping its hint,
// inside measured_queries(), so that
//   valgrind --tool=callgrind --toggle-collect='measured_queries*' road_query_cost [N]
// counts exactly those instructions (divide by N; the first query, without a hint, searches).
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "io/config/crg_file.h"
#include "model/road/crg_surface.h"

namespace road = rig::model::road;

/// The measured region (not inlined, so that callgrind can toggle on it).
__attribute__((noinline)) double measured_queries(const road::CrgSurface& s,
                                                  const std::vector<double>& xy, long n) {
  road::SurfaceHint hint;
  double sum = 0;
  const long points = static_cast<long>(xy.size() / 2);
  for (long k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(2 * (k % points));
    sum += s.height(xy[i], xy[i + 1], hint).z_m;
  }
  return sum;
}

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 100000;
  const road::CrgSurface s(rig::io::config::load_crg_file(RIG_BELGIAN_BLOCK));
  std::vector<double> xy;
  for (double u = s.u_first_m(); u <= s.u_last_m(); u += 0.0083) {
    double x = 0;
    double y = 0;
    s.world_point(u, 0.7, x, y);
    xy.push_back(x);
    xy.push_back(y);
  }
  for (std::size_t i = xy.size(); i >= 2; i -= 2) {  // and back
    xy.push_back(xy[i - 2]);
    xy.push_back(xy[i - 1]);
  }
  std::printf("%ld queries, sum of heights %.6f m\n", n, measured_queries(s, xy, n));
  return 0;
}
