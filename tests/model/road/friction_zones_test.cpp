// Friction zones: points inside, outside and on the border of rectangles along a line (mu-split,
// mu-jump, a rotated patch) and of a concave polygon; later zones win where they overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "model/road/friction_zones.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::road {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

FrictionZone rectangle(double mu, double x, double y, double heading, double s_from, double s_to,
                       double v_from, double v_to) {
  FrictionZone z;
  z.mu = mu;
  z.rectangle = {x, y, heading, s_from, s_to, v_from, v_to};
  return z;
}

FrictionZone polygon(double mu, std::vector<double> x, std::vector<double> y) {
  FrictionZone z;
  z.mu = mu;
  z.is_polygon = true;
  z.polygon = {std::move(x), std::move(y)};
  return z;
}

TEST(FrictionZones, MuSplitCoversTheRightHalfOnly) {
  const FrictionZones zones({rectangle(0.2, 0, 0, 0, -kInf, kInf, -kInf, 0.0)});
  EXPECT_EQ(zones.mu(5, -1, 1.0), 0.2);
  EXPECT_EQ(zones.mu(-500, -0.01, 1.0), 0.2);
  EXPECT_EQ(zones.mu(5, 0.0, 1.0), 0.2);  // the border belongs to the zone
  EXPECT_EQ(zones.mu(5, 0.01, 1.0), 1.0);
}

TEST(FrictionZones, MuJumpStartsAtItsStation) {
  const FrictionZones zones({rectangle(0.3, 0, 0, 0, 50.0, kInf, -kInf, kInf)});
  EXPECT_EQ(zones.mu(49.999, 3, 0.9), 0.9);
  EXPECT_EQ(zones.mu(50.0, 3, 0.9), 0.3);
  EXPECT_EQ(zones.mu(1e6, -40, 0.9), 0.3);
}

TEST(FrictionZones, RotatedPatchIsItsRectangleAlongTheLine) {
  const double h = std::numbers::pi / 4, c = std::cos(h), s = std::sin(h);
  const FrictionZones zones({rectangle(0.5, 10, 10, h, 0, 4, -1, 1)});
  auto point = [&](double a, double b) {
    return std::pair{10 + a * c - b * s, 10 + a * s + b * c};
  };
  for (const auto& [a, b, inside] :
       {std::tuple{2.0, 0.0, true}, std::tuple{3.9, 0.9, true}, std::tuple{2.0, 1.1, false},
        std::tuple{4.1, 0.0, false}, std::tuple{-0.1, 0.0, false}, std::tuple{0.1, -0.9, true}}) {
    const auto [x, y] = point(a, b);
    EXPECT_EQ(zones.mu(x, y, 1.0), inside ? 0.5 : 1.0) << a << " " << b;
  }
}

TEST(FrictionZones, ConcavePolygonByTheEvenOddRuleWithItsEdgesInside) {
  // an L: (0,0) (4,0) (4,1) (1,1) (1,3) (0,3)
  const FrictionZones zones({polygon(0.1, {0, 4, 4, 1, 1, 0}, {0, 0, 1, 1, 3, 3})});
  EXPECT_EQ(zones.mu(0.5, 2.0, 1.0), 0.1);  // in the upright
  EXPECT_EQ(zones.mu(3.0, 0.5, 1.0), 0.1);  // in the foot
  EXPECT_EQ(zones.mu(2.0, 2.0, 1.0), 1.0);  // in the notch: outside
  EXPECT_EQ(zones.mu(2.0, 1.0, 1.0), 0.1);  // on an edge
  EXPECT_EQ(zones.mu(1.0, 2.0, 1.0), 0.1);  // on the inner edge
  EXPECT_EQ(zones.mu(4.0, 0.0, 1.0), 0.1);  // a corner
  EXPECT_EQ(zones.mu(4.001, 0.5, 1.0), 1.0);
  EXPECT_EQ(zones.mu(-1, 0.5, 1.0), 1.0);
}

TEST(FrictionZones, TheLaterZoneWinsWhereTheyOverlap) {
  const FrictionZone square = polygon(0.3, {0, 2, 2, 0}, {0, 0, 2, 2});
  const FrictionZone strip = rectangle(0.8, 0, 1, 0, -kInf, kInf, -0.5, 0.5);
  const FrictionZones a({square, strip});
  const FrictionZones b({strip, square});
  EXPECT_EQ(a.mu(1, 1, 1.0), 0.8);
  EXPECT_EQ(b.mu(1, 1, 1.0), 0.3);
  EXPECT_EQ(a.mu(1, 0.2, 1.0), 0.3);  // only the square
  EXPECT_EQ(b.mu(5, 1, 1.0), 0.8);    // only the strip
  EXPECT_EQ(a.mu(5, 5, 0.7), 0.7);    // neither
}

TEST(FrictionZones, RefusesWhatIsNoZone) {
  EXPECT_THROW(FrictionZones({rectangle(-0.1, 0, 0, 0, 0, 1, 0, 1)}), std::invalid_argument);
  EXPECT_THROW(FrictionZones({rectangle(0.5, 0, 0, 0, 1, 1, 0, 1)}), std::invalid_argument);
  EXPECT_THROW(FrictionZones({rectangle(0.5, 0, 0, 0, std::nan(""), 1, 0, 1)}),
               std::invalid_argument);
  EXPECT_THROW(FrictionZones({polygon(0.5, {0, 1}, {0, 1})}), std::invalid_argument);
}

TEST(FrictionZones, QueriesAllocateNothing) {
  const FrictionZones zones({polygon(0.1, {0, 4, 4, 1, 1, 0}, {0, 0, 1, 1, 3, 3}),
                             rectangle(0.2, 0, 0, 0, -kInf, kInf, -kInf, 0.0)});
  double sum = 0;
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 1000; ++i) sum += zones.mu(i * 0.01, 1.0 - i * 0.002, 1.0);
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_GT(sum, 0);
}

}  // namespace
}  // namespace rig::model::road
