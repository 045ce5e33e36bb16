// Instruction counts of OpenDRIVE queries: N rolling queries (0.03 m apart, t = 1 m, the hint
// kept) on the test track from s0 to s1. Run under callgrind with N and with 0; the difference
// over N is the cost of one query (model/road/RESULTS.md):
//   valgrind --tool=callgrind --callgrind-out-file=/dev/null opendrive_query_loop N S0 S1
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "io/config/opendrive_file.h"

int main(int argc, char** argv) {
  using namespace rig::model::road;
  if (argc != 4) {
    std::fprintf(stderr, "usage: opendrive_query_loop N S0 S1\n");
    return 2;
  }
  const long n = std::atol(argv[1]);
  const double s0 = std::atof(argv[2]), s1 = std::atof(argv[3]);
  const auto file = rig::io::config::load_opendrive_file(
      std::filesystem::path(RIG_SOURCE_DIR) / "tests/io/config/opendrive/test_track.xodr");
  const auto surface = rig::io::config::make_opendrive_surface(file, "1", {});
  std::vector<Eigen::Vector2d> points;
  for (double s = s0; s < s1; s += 0.03) points.push_back(surface->position(s, 1.0));
  SurfaceHint hint;
  double sum = 0;
  for (long i = 0; i < n; ++i) {
    const Eigen::Vector2d& p = points[static_cast<std::size_t>(i) % points.size()];
    sum += surface->height(p.x(), p.y(), hint).z_m;
  }
  std::printf("%.17g\n", sum);
  return 0;
}
