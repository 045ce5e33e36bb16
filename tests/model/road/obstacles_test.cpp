// Obstacles against their stated shapes (model/road/obstacles.h): heights and gradients at known
// points, exact edges of the rectangular cleat and pothole, the ramp's trapezoid, the haversine
// bump and whole sine waves, a rotated line, sums of overlapping obstacles, and the layered
// surface that adds them to a base.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "model/road/layered_surface.h"
#include "model/road/obstacles.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::road {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

ObstacleParams along_x(ObstacleKind kind, double s, double length, double height) {
  ObstacleParams p;
  p.kind = kind;
  p.s_m = s;
  p.length_m = length;
  p.width_m = kInf;
  p.height_m = height;
  return p;
}

SurfaceHeight at(const Obstacle& o, double x, double y) { return o.height(x, y); }

TEST(Obstacle, CleatIsARectangularBlockWithExactEdges) {
  auto p = along_x(ObstacleKind::kCleat, 10.0, 0.02, 0.02);
  p.width_m = 2.0;
  const Obstacle cleat(p);
  EXPECT_EQ(at(cleat, 10.0, 0.0).z_m, 0.02);  // on the leading wall: on top
  EXPECT_EQ(at(cleat, 10.01, 0.7).z_m, 0.02);
  EXPECT_EQ(at(cleat, 10.02, 0.0).z_m, 0.02);       // the trailing wall (closed interval)
  EXPECT_EQ(at(cleat, 10.0 - 1e-9, 0.0).z_m, 0.0);  // just before it
  EXPECT_EQ(at(cleat, 10.02 + 1e-9, 0.0).z_m, 0.0);
  EXPECT_EQ(at(cleat, 10.01, 1.0).z_m, 0.02);  // the side wall at |b| = width / 2
  EXPECT_EQ(at(cleat, 10.01, -1.0 - 1e-9).z_m, 0.0);
  // vertical faces have no gradient: 0 on top and beside
  for (const double x : {9.99, 10.0, 10.01, 10.02, 10.03}) {
    EXPECT_EQ(at(cleat, x, 0.0).dz_dx, 0.0);
    EXPECT_EQ(at(cleat, x, 0.0).dz_dy, 0.0);
  }
}

TEST(Obstacle, PotholeIsARectangularHole) {
  auto p = along_x(ObstacleKind::kPothole, 5.0, 0.5, -0.05);
  p.y_m = 1.0;
  p.width_m = 0.5;
  const Obstacle hole(p);
  EXPECT_EQ(at(hole, 5.25, 1.0).z_m, -0.05);
  EXPECT_EQ(at(hole, 5.0, 1.25).z_m, -0.05);  // a corner: on the walls is in
  EXPECT_EQ(at(hole, 5.25, 1.26).z_m, 0.0);
  EXPECT_EQ(at(hole, 5.51, 1.0).z_m, 0.0);
}

TEST(Obstacle, RampIsATrapezoidAlongItsRotatedLine) {
  // up over 1 m, flat, down over 0.5 m; 0.1 m high; the line from (2, 3) at heading 0.5
  ObstacleParams p = along_x(ObstacleKind::kRamp, 4.0, 3.0, 0.1);
  p.x_m = 2, p.y_m = 3, p.heading_rad = 0.5, p.rise_m = 1.0, p.fall_m = 0.5;
  const Obstacle ramp(p);
  const double c = std::cos(0.5), s = std::sin(0.5);
  auto point = [&](double a, double b) { return std::pair{2 + a * c - b * s, 3 + a * s + b * c}; };
  struct Case {
    double r, z, slope;
  };
  for (const Case& k : {Case{0.5, 0.05, 0.1}, Case{0.0, 0.0, 0.1}, Case{1.0, 0.1, 0.0},
                        Case{2.0, 0.1, 0.0}, Case{2.75, 0.05, -0.2}, Case{3.0, 0.0, -0.2}}) {
    const auto [x, y] = point(4.0 + k.r, 0.3);
    const SurfaceHeight h = at(ramp, x, y);
    EXPECT_NEAR(h.z_m, k.z, 1e-12) << "r = " << k.r;
    EXPECT_NEAR(h.dz_dx, k.slope * c, 1e-12) << "r = " << k.r;
    EXPECT_NEAR(h.dz_dy, k.slope * s, 1e-12) << "r = " << k.r;
  }
  const auto [x, y] = point(3.99, 0.0);
  EXPECT_EQ(at(ramp, x, y).z_m, 0.0);
}

TEST(Obstacle, BumpIsOneHaversineHump) {
  const Obstacle bump(along_x(ObstacleKind::kBump, 1.0, 2.0, 0.08));
  // z = h/2 (1 - cos(2 pi r / L)), dz/dr = h pi / L sin(2 pi r / L)
  for (const double r : {0.0, 0.3, 0.5, 1.0, 1.7, 2.0}) {
    const SurfaceHeight h = at(bump, 1.0 + r, 5.0);
    EXPECT_NEAR(h.z_m, 0.04 * (1 - std::cos(kPi * r)), 1e-15) << r;
    EXPECT_NEAR(h.dz_dx, 0.08 * kPi / 2 * std::sin(kPi * r), 1e-15) << r;
    EXPECT_EQ(h.dz_dy, 0.0);
  }
  EXPECT_NEAR(at(bump, 2.0, 0).z_m, 0.08, 1e-15);  // the crest
}

TEST(Obstacle, SineIsWholeWavesWithoutStepAtEitherEnd) {
  auto p = along_x(ObstacleKind::kSine, 0.0, 6.0, 0.04);
  p.wavelength_m = 2.0;
  const Obstacle sine(p);
  EXPECT_NEAR(at(sine, 0.5, 0).z_m, 0.02, 1e-15);
  EXPECT_NEAR(at(sine, 3.0, 0).z_m, 0.04, 1e-15);  // a crest (1.5 waves in)
  EXPECT_NEAR(at(sine, 4.0, 0).z_m, 0.0, 1e-15);   // a trough
  EXPECT_NEAR(at(sine, 6.0, 0).z_m, 0.0, 1e-15);   // the end meets the road
  EXPECT_NEAR(at(sine, 4.5, 0).dz_dx, 0.02 * kPi, 1e-15);
  p.length_m = 5.0;  // 2.5 waves would end on a step
  EXPECT_THROW((Obstacle(p)), std::invalid_argument);
}

TEST(Obstacle, GradientsOfTheSmoothShapesMatchCentralDifferences) {
  ObstacleParams bump = along_x(ObstacleKind::kBump, 1.0, 3.0, 0.1);
  bump.heading_rad = -0.8, bump.x_m = 1, bump.y_m = -2;
  ObstacleParams sine = along_x(ObstacleKind::kSine, 0.0, 8.0, 0.05);
  sine.heading_rad = 2.0, sine.wavelength_m = 4.0;
  for (const auto& p : {bump, sine}) {
    const Obstacle o(p);
    for (const double a : {0.4, 1.3, 2.2, 2.9}) {
      const double x = p.x_m + (p.s_m + a) * std::cos(p.heading_rad) + 0.2;
      const double y = p.y_m + (p.s_m + a) * std::sin(p.heading_rad) - 0.1;
      const double d = 1e-6;
      const SurfaceHeight h = o.height(x, y);
      EXPECT_NEAR(h.dz_dx, (o.height(x + d, y).z_m - o.height(x - d, y).z_m) / (2 * d), 1e-8);
      EXPECT_NEAR(h.dz_dy, (o.height(x, y + d).z_m - o.height(x, y - d).z_m) / (2 * d), 1e-8);
    }
  }
}

TEST(Obstacle, RefusesImpossibleShapes) {
  EXPECT_THROW(Obstacle(along_x(ObstacleKind::kCleat, 0, 0.02, -0.02)), std::invalid_argument);
  EXPECT_THROW(Obstacle(along_x(ObstacleKind::kPothole, 0, 0.5, 0.05)), std::invalid_argument);
  EXPECT_THROW(Obstacle(along_x(ObstacleKind::kBump, 0, 0.0, 0.05)), std::invalid_argument);
  EXPECT_THROW(Obstacle(along_x(ObstacleKind::kBump, 0, 1.0, 0.0)), std::invalid_argument);
  auto ramp = along_x(ObstacleKind::kRamp, 0, 1.0, 0.05);
  ramp.rise_m = 0.8, ramp.fall_m = 0.3;
  EXPECT_THROW((Obstacle(ramp)), std::invalid_argument);
  auto nan = along_x(ObstacleKind::kBump, std::nan(""), 1.0, 0.05);
  EXPECT_THROW((Obstacle(nan)), std::invalid_argument);
}

/// A test base: the plane z = 1 + 0.1 x.
class Incline final : public Surface {
 public:
  SurfaceHeight height(double x_m, double, SurfaceHint& hint) const noexcept override {
    hint.s_m = x_m;  // shows that the caller's hint reaches the base
    return {1 + 0.1 * x_m, 0.1, 0};
  }
};

TEST(LayeredSurface, ObstaclesAddTheirHeightsAndGradientsToTheBase) {
  std::vector<Obstacle> list{Obstacle(along_x(ObstacleKind::kBump, 0.0, 2.0, 0.1)),
                             Obstacle(along_x(ObstacleKind::kCleat, 0.5, 0.1, 0.02))};
  const auto obstacles = std::make_shared<const Obstacles>(std::move(list));
  const auto base = std::make_shared<const Incline>();
  const auto layered = with_overlay(base, obstacles);
  SurfaceHint hint;
  const SurfaceHeight h = layered->height(0.5, 0.0, hint);  // on the bump's flank and the cleat
  EXPECT_NEAR(h.z_m, 1.05 + 0.05 + 0.02, 1e-15);
  EXPECT_NEAR(h.dz_dx, 0.1 + 0.1 * kPi / 2, 1e-15);
  EXPECT_EQ(hint.s_m, 0.5);
  EXPECT_NEAR(layered->height(3.0, 0.0, hint).z_m, 1.3, 1e-15);  // past both
  // no base: on the plane z = 0
  EXPECT_NEAR(with_overlay(nullptr, obstacles)->height(1.0, 0, hint).z_m, 0.1, 1e-15);
  // no overlay: the base itself; neither: null (today's plane)
  EXPECT_EQ(with_overlay(base, nullptr), base);
  EXPECT_EQ(with_overlay(nullptr, nullptr), nullptr);
}

TEST(LayeredSurface, QueriesAllocateNothing) {
  std::vector<Obstacle> list{Obstacle(along_x(ObstacleKind::kBump, 0.0, 2.0, 0.1))};
  const auto layered =
      with_overlay(std::make_shared<const Incline>(), std::make_shared<const Obstacles>(list));
  SurfaceHint hint;
  double sum = 0;
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 1000; ++i) sum += layered->height(i * 0.003, 0, hint).z_m;
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::road
