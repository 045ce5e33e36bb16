// The OpenDRIVE reference line against closed-form geometry: an arc of radius R (circle through
// its centre), the clothoid (curvature linear in s; positions against its power series, and
// against Simpson's rule for a spiral that starts curved), paramPoly3 and poly3 (the parabola's
// arc length in closed form), the straight extensions, and allocation-free queries.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "model/road/gauss_legendre.h"
#include "model/road/opendrive_reference_line.h"
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

ReferencePose at(const OpenDriveReferenceLine& line, double s) {
  int element = -1;
  return line.pose(s, element);
}

TEST(GaussLegendre6, IsExactForPolynomialsUpToDegree11) {
  for (int n = 0; n <= 11; ++n) {
    const double got = gauss_legendre6(-0.5, 2.0, [n](double x) { return std::pow(x, n); });
    const double exact = (std::pow(2.0, n + 1) - std::pow(-0.5, n + 1)) / (n + 1);
    EXPECT_NEAR(got, exact, 1e-13 * std::max(1.0, std::abs(exact))) << "degree " << n;
  }
  // degree 12 is not exact: the rule is what it claims, no more
  const double got = gauss_legendre6(0.0, 1.0, [](double x) { return std::pow(x, 12); });
  EXPECT_GT(std::abs(got - 1.0 / 13.0), 1e-9);
}

TEST(OpenDriveReferenceLine, ArcOfRadiusRLiesOnItsCircle) {
  for (const double r : {50.0, -20.0}) {  // left and right turns
    const double x0 = 3.0, y0 = -4.0, h0 = 0.7;
    auto g = geometry(OpenDriveGeometryKind::kArc, 0, x0, y0, h0, 100.0);
    g.curvature_1pm = 1.0 / r;
    const OpenDriveReferenceLine line({g});
    // the centre lies R to the left of the start (right for R < 0)
    const double cx = x0 - r * std::sin(h0), cy = y0 + r * std::cos(h0);
    for (const double s : {0.0, 1e-7, 10.0, 33.3, 78.5, 100.0}) {
      const ReferencePose p = at(line, s);
      const double phi = h0 + s / r;
      EXPECT_NEAR(p.x_m, cx + r * std::sin(phi), 1e-12 * std::abs(r)) << r << " " << s;
      EXPECT_NEAR(p.y_m, cy - r * std::cos(phi), 1e-12 * std::abs(r));
      EXPECT_NEAR(p.hdg_rad, phi, 1e-14);
      EXPECT_DOUBLE_EQ(p.curvature_1pm, 1.0 / r);
      EXPECT_EQ(p.speed, 1.0);
    }
  }
}

/// The clothoid from curvature 0 at the origin, heading 0: theta = s^2 / (2 A^2); its power
/// series x = sum (-1)^n s^(4n+1) / ((4n+1) (2n)! (2A^2)^(2n)), y likewise with 4n+3, (2n+1)!.
std::pair<double, double> clothoid_series(double s, double a2) {
  double x = 0, y = 0, fact_even = 1, fact_odd = 1;
  for (int n = 0; n < 12; ++n) {
    if (n > 0) fact_even *= (2.0 * n - 1) * (2.0 * n);
    fact_odd = fact_even * (2.0 * n + 1);
    const double sign = n % 2 == 0 ? 1.0 : -1.0;
    x += sign * std::pow(s, 4 * n + 1) / ((4 * n + 1) * fact_even * std::pow(2 * a2, 2 * n));
    y += sign * std::pow(s, 4 * n + 3) / ((4 * n + 3) * fact_odd * std::pow(2 * a2, 2 * n + 1));
  }
  return {x, y};
}

TEST(OpenDriveReferenceLine, ClothoidFollowsItsPowerSeriesAndCurvatureIsLinearInS) {
  const double length = 60.0, k_end = 0.05;  // A^2 = L / k_end
  auto g = geometry(OpenDriveGeometryKind::kSpiral, 0, 0, 0, 0, length);
  g.curv_end_1pm = k_end;
  const OpenDriveReferenceLine line({g});
  for (double s = 0; s <= length; s += 2.5) {
    const ReferencePose p = at(line, s);
    const auto [x, y] = clothoid_series(s, length / k_end);
    EXPECT_NEAR(p.x_m, x, 1e-11) << s;
    EXPECT_NEAR(p.y_m, y, 1e-11) << s;
    EXPECT_NEAR(p.curvature_1pm, k_end * s / length, 1e-15);
    EXPECT_NEAR(p.hdg_rad, 0.5 * k_end * s * s / length, 1e-14);
  }
  // curvature is the heading's rate: a central difference of the heading
  for (const double s : {5.0, 30.0, 55.0}) {
    const double h = 1e-3;
    const double rate = (at(line, s + h).hdg_rad - at(line, s - h).hdg_rad) / (2 * h);
    EXPECT_NEAR(rate, at(line, s).curvature_1pm, 1e-9);
  }
}

TEST(OpenDriveReferenceLine, SpiralStartingCurvedMatchesSimpsonsRule) {
  const double x0 = -5, y0 = 7, h0 = -1.2, k0 = -0.03, k1 = 0.04, length = 45;
  auto g = geometry(OpenDriveGeometryKind::kSpiral, 10.0, x0, y0, h0, length);
  g.curv_start_1pm = k0;
  g.curv_end_1pm = k1;
  const OpenDriveReferenceLine line({g});
  for (const double ds : {7.3, 22.0, 45.0}) {
    // Simpson's rule with 20000 intervals (error ~1e-14 here): an independent integration
    const int n = 20000;
    const double h = ds / n;
    double sx = 0, sy = 0;
    for (int i = 0; i <= n; ++i) {
      const double s = i * h;
      const double th = h0 + k0 * s + 0.5 * (k1 - k0) / length * s * s;
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sx += w * std::cos(th);
      sy += w * std::sin(th);
    }
    const ReferencePose p = at(line, 10.0 + ds);
    EXPECT_NEAR(p.x_m, x0 + sx * h / 3, 1e-10) << ds;
    EXPECT_NEAR(p.y_m, y0 + sy * h / 3, 1e-10) << ds;
    EXPECT_NEAR(p.curvature_1pm, k0 + (k1 - k0) * ds / length, 1e-15);
  }
}

TEST(OpenDriveReferenceLine, ParamPoly3IsTheRotatedCubicInBothPRanges) {
  // u = 2 + p - 0.01 p^2, v = 0.5 + 0.03 p^2 - 0.0004 p^3 (arcLength) and the same curve with
  // p normalized over the length: the positions agree at p = ds and p = ds / length
  const double length = 20, h0 = 0.4;
  auto g = geometry(OpenDriveGeometryKind::kParamPoly3, 0, 1, 2, h0, length);
  g.au = 2, g.bu = 1, g.cu = -0.01, g.du = 0;
  g.av = 0.5, g.bv = 0, g.cv = 0.03, g.dv = -0.0004;
  g.p_normalized = false;
  auto n = g;  // normalized: coefficients scaled by length^k
  n.p_normalized = true;
  n.bu *= length, n.cu *= length * length, n.du *= std::pow(length, 3);
  n.bv *= length, n.cv *= length * length, n.dv *= std::pow(length, 3);
  const OpenDriveReferenceLine arc_length({g});
  const OpenDriveReferenceLine normalized({n});
  for (const double p : {0.0, 4.0, 13.0, 20.0}) {
    const double u = 2 + p - 0.01 * p * p, v = 0.5 + 0.03 * p * p - 0.0004 * p * p * p;
    const double du = 1 - 0.02 * p, dv = 0.06 * p - 0.0012 * p * p;
    const double ddu = -0.02, ddv = 0.06 - 0.0024 * p;
    const ReferencePose a = at(arc_length, p);
    EXPECT_NEAR(a.x_m, 1 + u * std::cos(h0) - v * std::sin(h0), 1e-12);
    EXPECT_NEAR(a.y_m, 2 + u * std::sin(h0) + v * std::cos(h0), 1e-12);
    EXPECT_NEAR(a.hdg_rad, h0 + std::atan2(dv, du), 1e-14);
    EXPECT_NEAR(a.curvature_1pm, (du * ddv - dv * ddu) / std::pow(du * du + dv * dv, 1.5), 1e-14);
    EXPECT_NEAR(a.speed, std::hypot(du, dv), 1e-14);
    const ReferencePose b = at(normalized, p);
    EXPECT_NEAR(b.x_m, a.x_m, 1e-11);
    EXPECT_NEAR(b.y_m, a.y_m, 1e-11);
    EXPECT_NEAR(b.hdg_rad, a.hdg_rad, 1e-13);
    EXPECT_NEAR(b.curvature_1pm, a.curvature_1pm, 1e-13);
    EXPECT_NEAR(b.speed, a.speed, 1e-13);
  }
}

TEST(OpenDriveReferenceLine, Poly3ParabolaIsWalkedByItsArcLength) {
  // v = c u^2: arc length s(u) = u sqrt(1 + 4c^2u^2) / 2 + asinh(2cu) / (4c)
  const double c = 0.02, h0 = -0.3, x0 = 4, y0 = 1;
  auto g = geometry(OpenDriveGeometryKind::kPoly3, 5.0, x0, y0, h0, 30.0);
  g.c = c;
  const OpenDriveReferenceLine line({g});
  for (const double u : {0.0, 3.0, 11.5, 24.0}) {
    const double s = 0.5 * u * std::sqrt(1 + 4 * c * c * u * u) + std::asinh(2 * c * u) / (4 * c);
    const ReferencePose p = at(line, 5.0 + s);
    const double v = c * u * u;
    EXPECT_NEAR(p.x_m, x0 + u * std::cos(h0) - v * std::sin(h0), 1e-10) << u;
    EXPECT_NEAR(p.y_m, y0 + u * std::sin(h0) + v * std::cos(h0), 1e-10) << u;
    EXPECT_NEAR(p.hdg_rad, h0 + std::atan(2 * c * u), 1e-11);
    EXPECT_NEAR(p.curvature_1pm, 2 * c / std::pow(1 + 4 * c * c * u * u, 1.5), 1e-11);
  }
}

TEST(OpenDriveReferenceLine, RunsOnStraightBeforeItsStartAndAfterItsEnd) {
  auto g = geometry(OpenDriveGeometryKind::kArc, 0, 0, 0, 0.5, 10.0);
  g.curvature_1pm = 0.1;
  const OpenDriveReferenceLine line({g});
  const ReferencePose before = at(line, -3.0);
  EXPECT_NEAR(before.x_m, -3.0 * std::cos(0.5), 1e-14);
  EXPECT_NEAR(before.y_m, -3.0 * std::sin(0.5), 1e-14);
  EXPECT_EQ(before.hdg_rad, 0.5);
  EXPECT_EQ(before.curvature_1pm, 0.0);
  const ReferencePose end = at(line, 10.0);
  const ReferencePose after = at(line, 14.0);
  EXPECT_NEAR(end.hdg_rad, 1.5, 1e-14);
  EXPECT_NEAR(after.x_m, end.x_m + 4.0 * std::cos(1.5), 1e-12);
  EXPECT_NEAR(after.y_m, end.y_m + 4.0 * std::sin(1.5), 1e-12);
  EXPECT_NEAR(after.hdg_rad, 1.5, 1e-14);
  EXPECT_EQ(after.curvature_1pm, 0.0);
}

TEST(OpenDriveReferenceLine, RefusesWhatIsNoPlanView) {
  EXPECT_THROW(OpenDriveReferenceLine({}), std::invalid_argument);
  auto g = geometry(OpenDriveGeometryKind::kLine, 0, 0, 0, 0, 0.0);
  EXPECT_THROW(OpenDriveReferenceLine({g}), std::invalid_argument);  // nothing of positive length
  g.length_m = 1;
  g.x_m = std::nan("");
  EXPECT_THROW(OpenDriveReferenceLine({g}), std::invalid_argument);
  auto a = geometry(OpenDriveGeometryKind::kLine, 5, 0, 0, 0, 1);
  auto b = geometry(OpenDriveGeometryKind::kLine, 4, 0, 0, 0, 1);
  EXPECT_THROW(OpenDriveReferenceLine({a, b}), std::invalid_argument);
}

TEST(OpenDriveReferenceLine, QueriesAllocateNothing) {
  auto a = geometry(OpenDriveGeometryKind::kSpiral, 0, 0, 0, 0, 30);
  a.curv_end_1pm = 0.02;
  auto b = geometry(OpenDriveGeometryKind::kPoly3, 30, 30, 1, 0.3, 20);
  b.c = 0.001;
  const OpenDriveReferenceLine line({a, b});
  double sum = 0;
  int element = -1;
  const rig::test::AllocationCounter counter;
  for (int i = -10; i < 70; ++i) sum += line.pose(i * 0.9, element).x_m;
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::road
