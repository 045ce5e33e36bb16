// One OpenDRIVE road query (x, y) -> (z, dz/dx, dz/dy): a probe rolling along the test track
// (tests/io/config/opendrive/test_track.xodr: line, clothoids, arc, paramPoly3, poly3) at
// 30 m/s and 1 ms per query, 1 m left of the reference line, with its hint (the contact's case);
// the same without a hint (the global search through the sample grid); the straight road; the
// track with four obstacles laid on it; and friction zones.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <vector>

#include "io/config/opendrive_file.h"
#include "model/road/friction_zones.h"
#include "model/road/layered_surface.h"
#include "model/road/obstacles.h"

namespace {

using namespace rig::model::road;

const std::filesystem::path kTrack =
    std::filesystem::path(RIG_SOURCE_DIR) / "tests/io/config/opendrive/test_track.xodr";

std::shared_ptr<const OpenDriveSurface> road(const char* id) {
  return rig::io::config::make_opendrive_surface(rig::io::config::load_opendrive_file(kTrack), id,
                                                 {});
}

/// Points 0.03 m apart (30 m/s at 1 ms) along the road from s0 to s1, t = 1 m.
std::vector<Eigen::Vector2d> rolling_points(const OpenDriveSurface& surface, double s1_m,
                                            double s0_m = 0) {
  std::vector<Eigen::Vector2d> out;
  for (double s = s0_m; s < s1_m; s += 0.03) out.push_back(surface.position(s, 1.0));
  return out;
}

void query(benchmark::State& state, const Surface& surface,
           const std::vector<Eigen::Vector2d>& points, bool keep_hint) {
  SurfaceHint hint;
  std::size_t i = 0;
  for (auto _ : state) {
    if (!keep_hint) hint = SurfaceHint{};
    const Eigen::Vector2d& p = points[i];
    benchmark::DoNotOptimize(surface.height(p.x(), p.y(), hint));
    if (++i == points.size()) i = 0;
  }
}

void BM_OpenDriveTrackRolling(benchmark::State& state) {
  const auto surface = road("1");
  query(state, *surface, rolling_points(*surface, 225), true);
  state.SetLabel("track, hint kept (a rolling wheel's probe)");
}
BENCHMARK(BM_OpenDriveTrackRolling);

/// One geometry of the track at a time: line, clothoid, arc, paramPoly3, poly3.
void BM_OpenDriveGeometry(benchmark::State& state) {
  struct Piece {
    const char* name;
    double s0, s1;
  };
  static constexpr Piece kPieces[] = {{"line", 2, 38},
                                      {"spiral", 42, 68},
                                      {"arc", 72, 108},
                                      {"paramPoly3", 142, 168},
                                      {"poly3", 172, 193}};
  const Piece& piece = kPieces[state.range(0)];
  const auto surface = road("1");
  query(state, *surface, rolling_points(*surface, piece.s1, piece.s0), true);
  state.SetLabel(piece.name);
}
BENCHMARK(BM_OpenDriveGeometry)->DenseRange(0, 4);

void BM_OpenDriveTrackNoHint(benchmark::State& state) {
  const auto surface = road("1");
  query(state, *surface, rolling_points(*surface, 225), false);
  state.SetLabel("track, no hint (global search)");
}
BENCHMARK(BM_OpenDriveTrackNoHint);

void BM_OpenDriveStraightRolling(benchmark::State& state) {
  const auto surface = road("2");
  query(state, *surface, rolling_points(*surface, 100), true);
  state.SetLabel("straight road, hint kept");
}
BENCHMARK(BM_OpenDriveStraightRolling);

void BM_OpenDriveTrackWithObstacles(benchmark::State& state) {
  const auto base = road("1");
  std::vector<Obstacle> list;
  for (int k = 0; k < 4; ++k) {
    ObstacleParams p;
    p.kind = k % 2 == 0 ? ObstacleKind::kCleat : ObstacleKind::kBump;
    p.s_m = 10.0 + 5.0 * k;
    p.length_m = k % 2 == 0 ? 0.02 : 1.0;
    p.width_m = 4.0;
    p.height_m = 0.02;
    list.emplace_back(p);
  }
  const auto layered = with_overlay(base, std::make_shared<const Obstacles>(std::move(list)));
  query(state, *layered, rolling_points(*base, 225), true);
  state.SetLabel("track + 4 obstacles, hint kept");
}
BENCHMARK(BM_OpenDriveTrackWithObstacles);

void BM_FrictionZones(benchmark::State& state) {
  const double inf = std::numeric_limits<double>::infinity();
  FrictionZone split, jump, patch;
  split.mu = 0.2;
  split.rectangle = {0, 0, 0, -inf, inf, -inf, 0};
  jump.mu = 0.5;
  jump.rectangle = {0, 0, 0, 50, inf, -inf, inf};
  patch.mu = 0.1;
  patch.is_polygon = true;
  patch.polygon = {{10, 14, 14, 10}, {-2, -2, 2, 2}};
  const FrictionZones zones({split, jump, patch});
  double x = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(zones.mu(x, 0.5, 1.0));
    x = x > 100 ? 0 : x + 0.03;
  }
  state.SetLabel("3 zones (split, jump, polygon patch)");
}
BENCHMARK(BM_FrictionZones);

}  // namespace

BENCHMARK_MAIN();
