// The OpenDRIVE surface: heights at known (x, y) against hand values (elevation and
// superelevation polynomials, OpenDRIVE's sign: positive superelevation falls to the right),
// the gradient against central differences, projection round trips (s, t) -> (x, y) -> (s, t)
// on every geometry kind, any hint giving the same answer (also on a closed circle, whose reach
// is 0), the ends (straight on, elevation held), placement, and allocation-free queries.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "model/road/opendrive_surface.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::road {
namespace {

OpenDriveGeometry geometry(OpenDriveGeometryKind kind, double s, double x, double y, double hdg,
                           double length) {
  OpenDriveGeometry g;
  g.kind = kind;
  g.s_m = s;
  g.x_m = x;
  g.y_m = y;
  g.hdg_rad = hdg;
  g.length_m = length;
  return g;
}

/// A straight road from (10, 5) at heading 0.3, 100 m, 5 % grade from 1 m, superelevation
/// 0.04 rad (the test file's road "2").
OpenDriveRoad tilted_road() {
  OpenDriveRoad road;
  road.id = "2";
  road.plan_view = {geometry(OpenDriveGeometryKind::kLine, 0, 10, 5, 0.3, 100)};
  road.elevation = {{0.0, 1.0, 0.05, 0.0, 0.0}};
  road.superelevation = {{0.0, 0.04, 0.0, 0.0, 0.0}};
  return road;
}

/// line - spiral - arc - spiral - paramPoly3 - poly3 - line (the test file's road "1"), with
/// cubic elevation and a superelevation ramp over the spirals.
OpenDriveRoad track() {
  OpenDriveRoad road;
  road.id = "1";
  auto s1 = geometry(OpenDriveGeometryKind::kSpiral, 40, 40, 0, 0, 30);
  s1.curv_end_1pm = 0.02;
  auto arc =
      geometry(OpenDriveGeometryKind::kArc, 70, 69.7311226663308, 2.9807694262868845, 0.3, 40);
  arc.curvature_1pm = 0.02;
  auto s2 =
      geometry(OpenDriveGeometryKind::kSpiral, 110, 99.5154803363356, 28.06778781128832, 1.1, 30);
  s2.curv_start_1pm = 0.02;
  auto pp3 = geometry(OpenDriveGeometryKind::kParamPoly3, 140, 107.5061927374407, 56.85968175204742,
                      1.4000000000000001, 30);
  pp3.bu = 1, pp3.cv = 0.001, pp3.dv = -0.00002, pp3.p_normalized = false;
  auto p3 = geometry(OpenDriveGeometryKind::kPoly3, 170, 112.25044512165208, 86.48436182314532,
                     1.4059999280015554, 25);
  p3.c = -0.001, p3.d = 0.00002;
  road.plan_view = {geometry(OpenDriveGeometryKind::kLine, 0, 0, 0, 0, 40),
                    s1,
                    arc,
                    s2,
                    pp3,
                    p3,
                    geometry(OpenDriveGeometryKind::kLine, 195, 116.65960821321191,
                             111.09221143386608, 1.3934983663773837, 30)};
  road.elevation = {
      {0, 0, 0, 0, 0}, {40, 0, 0, 0.0005, 0}, {100, 1.8, 0.06, -0.0005, 0}, {160, 3.6, 0, 0, 0}};
  road.superelevation = {{0, 0, 0, 0, 0},
                         {40, 0, 0.05 / 30, 0, 0},
                         {70, 0.05, 0, 0, 0},
                         {110, 0.05, -0.05 / 30, 0, 0},
                         {140, 0, 0, 0, 0}};
  return road;
}

TEST(OpenDriveSurface, TiltedRoadHeightsEqualHandValues) {
  const OpenDriveSurface surface(tilted_road(), Placement{});
  const double c = std::cos(0.3), s = std::sin(0.3), tan_phi = std::tan(0.04);
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{10, 5}, {40, 20}, {60, 15}, {35, 22}, {90, 30}}) {
    SurfaceHint hint;
    const double along = (x - 10) * c + (y - 5) * s;  // s
    const double left = -(x - 10) * s + (y - 5) * c;  // t
    const SurfaceHeight h = surface.height(x, y, hint);
    EXPECT_NEAR(h.z_m, 1.0 + 0.05 * along + left * tan_phi, 1e-12) << x << " " << y;
    // grad z = 0.05 T + tan(phi) n
    EXPECT_NEAR(h.dz_dx, 0.05 * c - tan_phi * s, 1e-12);
    EXPECT_NEAR(h.dz_dy, 0.05 * s + tan_phi * c, 1e-12);
  }
  // OpenDRIVE's sign: positive superelevation lifts the left (t > 0) and drops the right side
  SurfaceHint hint;
  const Eigen::Vector2d left = surface.position(50, 3), right = surface.position(50, -3);
  EXPECT_GT(surface.height(left.x(), left.y(), hint).z_m, 1.0 + 0.05 * 50);
  EXPECT_LT(surface.height(right.x(), right.y(), hint).z_m, 1.0 + 0.05 * 50);
}

TEST(OpenDriveSurface, HeightsOnTheTrackFollowThePolynomials) {
  const OpenDriveSurface surface(track(), Placement{});
  // (s, t) -> the hand value e(s) + t tan(phi(s)) at the road point (x, y)
  struct Case {
    double s, t, z;
  };
  const double tan05 = std::tan(0.05);
  const std::vector<Case> cases{
      {20, 2, 0.0},                                      // flat, level
      {55, -1.5, 0.0005 * 225 - 1.5 * std::tan(0.025)},  // parabola, superelevation ramp
      {90, 3, 0.0005 * 2500 + 3 * tan05},                // on the arc
      {130, -2, 1.8 + 0.06 * 30 - 0.0005 * 900 - 2 * std::tan(0.05 - 0.05 / 30 * 20)},
      {150, 1, 1.8 + 0.06 * 50 - 0.0005 * 2500},  // paramPoly3
      {180, -3, 3.6},                             // poly3
      {210, 2.5, 3.6}};
  for (const Case& c : cases) {
    const Eigen::Vector2d p = surface.position(c.s, c.t);
    SurfaceHint hint;
    EXPECT_NEAR(surface.height(p.x(), p.y(), hint).z_m, c.z, 1e-9) << "s = " << c.s;
  }
}

TEST(OpenDriveSurface, GradientMatchesCentralDifferences) {
  const OpenDriveSurface surface(track(), Placement{});
  for (const double s : {20.0, 55.0, 90.0, 125.0, 150.0, 180.0}) {
    for (const double t : {-3.0, 0.5, 4.0}) {
      const Eigen::Vector2d p = surface.position(s, t);
      SurfaceHint hint;
      const SurfaceHeight h = surface.height(p.x(), p.y(), hint);
      const double d = 1e-5;
      const double zx = (surface.height(p.x() + d, p.y(), hint).z_m -
                         surface.height(p.x() - d, p.y(), hint).z_m) /
                        (2 * d);
      const double zy = (surface.height(p.x(), p.y() + d, hint).z_m -
                         surface.height(p.x(), p.y() - d, hint).z_m) /
                        (2 * d);
      EXPECT_NEAR(h.dz_dx, zx, 2e-7) << s << " " << t;
      EXPECT_NEAR(h.dz_dy, zy, 2e-7) << s << " " << t;
    }
  }
}

TEST(OpenDriveSurface, ProjectionRoundTripsOnEveryGeometry) {
  const OpenDriveSurface surface(track(), Placement{});
  SurfaceHint rolling;  // one probe rolling along, as a wheel does
  for (double s = -20; s <= 245; s += 0.37) {
    for (const double t : {-6.0, -1.0, 0.0, 2.5, 7.0}) {
      const Eigen::Vector2d p = surface.position(s, t);
      SurfaceHint fresh;
      for (SurfaceHint* hint : {&rolling, &fresh}) {
        const Station st = surface.station(p.x(), p.y(), *hint);
        ASSERT_TRUE(st.found);
        EXPECT_NEAR(st.s_m, s, 1e-8) << "s = " << s << ", t = " << t;
        EXPECT_NEAR(st.t_m, t, 1e-8) << "s = " << s << ", t = " << t;
      }
    }
  }
}

TEST(OpenDriveSurface, RollingProbeFindsItsStationExactly) {
  // a wheel's probe at 30 m/s and 1 ms: the one-step shortcuts (the osculating circle's foot,
  // its clothoid correction) must be as exact as Newton run to convergence
  const OpenDriveSurface surface(track(), Placement{});
  for (const double t : {-6.0, 0.5, 6.0}) {
    SurfaceHint hint;
    double worst_s = 0, worst_t = 0;
    for (double s = -5; s <= 230; s += 0.03) {
      const Eigen::Vector2d p = surface.position(s, t);
      const Station st = surface.station(p.x(), p.y(), hint);
      worst_s = std::max(worst_s, std::abs(st.s_m - s));
      worst_t = std::max(worst_t, std::abs(st.t_m - t));
    }
    EXPECT_LT(worst_s, 1e-9) << "t = " << t;
    EXPECT_LT(worst_t, 1e-9) << "t = " << t;
  }
}

TEST(OpenDriveSurface, GeometriesJoinWithoutGapOrKink) {
  const OpenDriveRoad road = track();
  const OpenDriveReferenceLine line(road.plan_view);
  for (std::size_t i = 1; i < road.plan_view.size(); ++i) {
    const double s = road.plan_view[i].s_m;
    int element = -1;
    const ReferencePose before = line.pose(s - 1e-9, element);
    const ReferencePose after = line.pose(s, element);
    EXPECT_NEAR(after.x_m, before.x_m, 1e-8) << "at s = " << s;
    EXPECT_NEAR(after.y_m, before.y_m, 1e-8) << "at s = " << s;
    EXPECT_NEAR(after.hdg_rad, before.hdg_rad, 1e-9) << "at s = " << s;
  }
}

TEST(OpenDriveSurface, ClosedCircleAnswersTheSameForAnyHint) {
  // a full circle of radius 10 around (0, 10): start and end meet, so its reach is 0 and every
  // query searches globally; the nearest point is still the circle's radial foot
  OpenDriveRoad road;
  auto g = geometry(OpenDriveGeometryKind::kArc, 0, 0, 0, 0, 2 * std::numbers::pi * 10);
  g.curvature_1pm = 0.1;
  road.plan_view = {g};
  road.elevation = {{0, 0, 0.01, 0, 0}};
  const OpenDriveSurface surface(road, Placement{});
  EXPECT_LT(surface.projection().reach_m(), 0.5);
  // (angles 1..5.3 rad: nearer the bottom the straight extensions, tangent there, are nearer)
  for (double angle = 1.0; angle < 5.3; angle += 0.3) {
    for (const double r : {7.0, 10.0, 12.5}) {
      const double x = r * std::sin(angle), y = 10 - r * std::cos(angle);
      SurfaceHint a, b;
      b.i = 1;
      b.s_m = 31.0;  // a hint far off
      const Station sa = surface.station(x, y, a), sb = surface.station(x, y, b);
      EXPECT_NEAR(sa.s_m, 10 * angle, 1e-8) << angle << " " << r;
      EXPECT_NEAR(sa.t_m, 10 - r, 1e-8);
      EXPECT_NEAR(sb.s_m, sa.s_m, 1e-9);
      EXPECT_NEAR(surface.height(x, y, a).z_m, 0.01 * 10 * angle, 1e-9);
    }
  }
}

TEST(OpenDriveSurface, OffTheEndsRunsOnStraightWithTheEndHeightHeld) {
  const OpenDriveSurface surface(tilted_road(), Placement{});
  const double c = std::cos(0.3), s = std::sin(0.3), tan_phi = std::tan(0.04);
  for (const double along : {-30.0, 130.0}) {
    const double t = 1.5;
    const double x = 10 + along * c - t * s, y = 5 + along * s + t * c;
    SurfaceHint hint;
    const Station st = surface.station(x, y, hint);
    EXPECT_NEAR(st.s_m, along, 1e-9);
    EXPECT_NEAR(st.t_m, t, 1e-9);
    const double held = along < 0 ? 1.0 : 1.0 + 0.05 * 100;
    const SurfaceHeight h = surface.height(x, y, hint);
    EXPECT_NEAR(h.z_m, held + t * tan_phi, 1e-12);
    // the grade is gone (held), the superelevation stays
    EXPECT_NEAR(h.dz_dx, -tan_phi * s, 1e-12);
    EXPECT_NEAR(h.dz_dy, tan_phi * c, 1e-12);
  }
}

TEST(OpenDriveSurface, PlacementPutsTheReferencePointAtItsPlace) {
  Placement placement;
  placement.given = true;
  placement.u_m = 20;  // s = 20, t = -1.75 of road "2" ...
  placement.v_m = -1.75;
  placement.x_m = 0;  // ... at the origin of the road frame, heading along +x, at z = 0
  placement.y_m = 0;
  placement.z_m = 0;
  placement.heading_rad = 0;
  const OpenDriveSurface surface(tilted_road(), placement);
  SurfaceHint hint;
  const SurfaceHeight at = surface.height(0, 0, hint);
  EXPECT_NEAR(at.z_m, 0.0, 1e-12);
  EXPECT_NEAR(at.dz_dx, 0.05, 1e-12);            // the grade now climbs along +x
  EXPECT_NEAR(at.dz_dy, std::tan(0.04), 1e-12);  // and the left is +y
  const Station st = surface.station(10, 2, hint);
  EXPECT_NEAR(st.s_m, 30, 1e-9);
  EXPECT_NEAR(st.t_m, 0.25, 1e-9);
  EXPECT_NEAR(surface.height(10, 2, hint).z_m, 0.05 * 10 + 2 * std::tan(0.04), 1e-12);
}

TEST(OpenDriveSurface, NonFinitePointGivesNaNNeverAHang) {
  const OpenDriveSurface surface(track(), Placement{});
  SurfaceHint hint;
  EXPECT_TRUE(std::isnan(surface.height(std::nan(""), 1, hint).z_m));
  EXPECT_TRUE(std::isnan(surface.height(1, INFINITY, hint).z_m));
  // far away still answers (straight extensions)
  EXPECT_TRUE(std::isfinite(surface.height(-1e5, 3e5, hint).z_m));
}

TEST(OpenDriveSurface, QueriesAllocateNothing) {
  const OpenDriveSurface surface(track(), Placement{});
  SurfaceHint hint;
  double sum = 0;
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2d p = surface.position(i * 0.11, 1.0);
    sum += surface.height(p.x(), p.y(), hint).z_m;
    SurfaceHint cold;
    sum += surface.height(p.x() + 3, p.y(), cold).z_m;
  }
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::road
