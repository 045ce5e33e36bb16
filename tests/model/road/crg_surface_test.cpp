// The OpenCRG surface against closed forms: heights at grid nodes are the grid's, between nodes
// the bilinear value; a reference line of constant curvature (heading rising by alpha per
// cross section) has its points at Lagrange's sum sum_k cos(k alpha) and its cross sections
// along the chord normals; slope integrates to z_ref, banking adds b v; the border modes, NaN
// modes and placement do what OpenCRG's options and modifiers say; the gradient is the surface's
// own; any hint gives the same answer; a query allocates nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "model/road/crg_surface.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::road {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// nu x nv grid, du apart, v given; z_ij = 0.01 sin(1.3 i) + 0.02 cos(0.7 j) + 0.001 i j.
CrgData grid(int nu, double du, std::vector<double> v) {
  CrgData d;
  d.u_increment_m = du;
  d.v_m = std::move(v);
  const auto nv = d.v_m.size();
  d.z_m.resize(static_cast<std::size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i) {
    for (std::size_t j = 0; j < nv; ++j) {
      d.z_m[static_cast<std::size_t>(i) * nv + j] = static_cast<float>(
          0.01 * std::sin(1.3 * i) + 0.02 * std::cos(0.7 * static_cast<double>(j)) +
          0.001 * i * static_cast<double>(j));
    }
  }
  return d;
}

double z_at(const CrgData& d, int i, std::size_t j) {
  return d.z_m[static_cast<std::size_t>(i) * d.nv() + j];
}

/// Central differences of the surface's height.
void expect_gradient_matches(const Surface& s, double x, double y, double tolerance) {
  SurfaceHint hint;
  const SurfaceHeight h = s.height(x, y, hint);
  const double e = 1e-6;
  SurfaceHint h2;
  const double dx = (s.height(x + e, y, h2).z_m - s.height(x - e, y, h2).z_m) / (2 * e);
  const double dy = (s.height(x, y + e, h2).z_m - s.height(x, y - e, h2).z_m) / (2 * e);
  EXPECT_NEAR(h.dz_dx, dx, tolerance) << "at " << x << ", " << y;
  EXPECT_NEAR(h.dz_dy, dy, tolerance) << "at " << x << ", " << y;
}

TEST(CrgSurface, StraightGridNodesAndBilinearBetweenThem) {
  const CrgData d = grid(6, 0.5, {-1.0, -0.5, 0.0, 0.5, 1.0});
  const CrgSurface s(d);
  SurfaceHint hint;
  for (int i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j < 5; ++j) {
      const double v = d.v_m[j];
      EXPECT_NEAR(s.height(0.5 * i, v, hint).z_m, z_at(d, i, j), 1e-15) << i << " " << j;
    }
  }
  // inside cell (2, 1) at fractions a along u, b along v
  const double a = 0.3;
  const double b = 0.8;
  const double expected = (1 - a) * (1 - b) * z_at(d, 2, 1) + a * (1 - b) * z_at(d, 3, 1) +
                          (1 - a) * b * z_at(d, 2, 2) + a * b * z_at(d, 3, 2);
  const SurfaceHeight h = s.height(0.5 * (2 + a), -0.5 + 0.5 * b, hint);
  EXPECT_NEAR(h.z_m, expected, 1e-15);
  // dz/du of the bilinear: ((1 - b)(z10 - z00) + b (z11 - z01)) / du
  const double dz_du =
      ((1 - b) * (z_at(d, 3, 1) - z_at(d, 2, 1)) + b * (z_at(d, 3, 2) - z_at(d, 2, 2))) / 0.5;
  EXPECT_NEAR(h.dz_dx, dz_du, 1e-14);
  expect_gradient_matches(s, 1.13, 0.37, 1e-8);
}

TEST(CrgSurface, VariableVSpacingFindsEachCellFromAnyHint) {
  const CrgData d = grid(4, 1.0, {-1.5, -1.25, -1.0, 0.0, 1.0, 1.25, 1.5});
  const CrgSurface s(d);
  for (std::size_t j = 0; j + 1 < d.nv(); ++j) {
    const double b = 0.25;
    const double v = d.v_m[j] + b * (d.v_m[j + 1] - d.v_m[j]);
    const double expected = (1 - b) * z_at(d, 1, j) + b * z_at(d, 1, j + 1);
    for (int start : {-1, 0, 5}) {
      SurfaceHint hint;
      hint.j = start;
      EXPECT_NEAR(s.height(1.0, v, hint).z_m, expected, 1e-15) << j << " from " << start;
      EXPECT_EQ(hint.j, static_cast<int>(j));
    }
  }
}

/// A reference line of constant curvature: heading phi_i = i alpha (i >= 1; entry 0 unused).
CrgData arc(int nu, double du, double alpha) {
  CrgData d = grid(nu, du, {-1.5, -0.5, 0.5, 1.5});
  d.heading_rad.assign(static_cast<std::size_t>(nu), kNaN);
  for (int i = 1; i < nu; ++i) d.heading_rad[static_cast<std::size_t>(i)] = i * alpha;
  return d;
}

TEST(CrgSurface, ArcPointsAndCrossSectionsAreWhereClosedFormsPutThem) {
  const double alpha = 0.05;
  const double du = 1.0;
  const CrgData d = arc(30, du, alpha);
  const CrgSurface s(d);
  SurfaceHint hint;
  for (int i = 1; i < 29; ++i) {
    // P_i = du sum_{k=1..i} (cos k alpha, sin k alpha) (Lagrange's trigonometric identities)
    const double q = du * std::sin(i * alpha / 2) / std::sin(alpha / 2);
    const double px = q * std::cos((i + 1) * alpha / 2);
    const double py = q * std::sin((i + 1) * alpha / 2);
    double x = 0;
    double y = 0;
    s.world_point(i * du, 0.0, x, y);
    EXPECT_NEAR(x, px, 1e-12);
    EXPECT_NEAR(y, py, 1e-12);
    // the cross section runs along the chord normal, angle (i + 1/2) alpha; v is the distance
    // from the segments, so the point at v lies v / cos(alpha / 2) along it
    for (std::size_t j = 0; j < 4; ++j) {
      const double w = d.v_m[j] / std::cos(alpha / 2);
      const double nx = -std::sin((i + 0.5) * alpha);
      const double ny = std::cos((i + 0.5) * alpha);
      EXPECT_NEAR(s.height(px + w * nx, py + w * ny, hint).z_m, z_at(d, i, j), 1e-12)
          << i << " " << j;
    }
    EXPECT_NEAR(s.reference_line().heading_rad(i * du + 0.5), (i + 1) * alpha, 1e-12);
  }
  expect_gradient_matches(s, 10.3, 2.1, 1e-7);
}

TEST(CrgSurface, LocateInvertsTheUvMapInsideEverySegment) {
  const CrgData d = arc(30, 2.0, -0.04);
  const CrgSurface s(d);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 58.0);
  std::uniform_real_distribution<double> v(-1.5, 1.5);
  for (int n = 0; n < 200; ++n) {
    const double uu = u(rng);
    const double vv = v(rng);
    double x = 0;
    double y = 0;
    s.world_point(uu, vv, x, y);
    int segment = -1;
    const CrgStation st = s.reference_line().locate(x, y, segment);
    EXPECT_NEAR(st.u_m, uu, 1e-10);
    EXPECT_NEAR(st.v_m, vv, 1e-10);
  }
}

TEST(CrgSurface, ARoadThatBendsBackFindsItsGridBeyondItsEnd) {
  // a 344-degree loop: the straight continuation beyond its end runs across its start
  const CrgData d = arc(24, 10.0, 0.26);
  const CrgSurface s(d);
  for (int i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < d.nv(); ++j) {
      double x = 0;
      double y = 0;
      s.world_point(10.0 * i, d.v_m[j], x, y);
      SurfaceHint from_the_end;
      from_the_end.i = 22;  // a wheel that has just left the grid's end
      EXPECT_NEAR(s.height(x, y, from_the_end).z_m, z_at(d, i, j), 1e-12) << i << " " << j;
      SurfaceHint none;
      EXPECT_NEAR(s.height(x, y, none).z_m, z_at(d, i, j), 1e-12) << i << " " << j;
    }
  }
}

TEST(CrgSurface, AnyHintGivesTheSameHeight) {
  const CrgData d = arc(40, 1.0, 0.03);
  const CrgSurface s(d);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5.0, 45.0);
  std::uniform_real_distribution<double> v(-2.0, 2.0);
  std::uniform_int_distribution<int> start(-1, 45);
  SurfaceHint rolling;
  for (int n = 0; n < 500; ++n) {
    double x = 0;
    double y = 0;
    s.world_point(u(rng), v(rng), x, y);
    SurfaceHint fresh;
    const SurfaceHeight a = s.height(x, y, fresh);
    SurfaceHint other;
    other.i = start(rng);
    other.j = start(rng);
    const SurfaceHeight b = s.height(x, y, other);
    const SurfaceHeight c = s.height(x, y, rolling);
    EXPECT_NEAR(a.z_m, b.z_m, 1e-13);
    EXPECT_NEAR(a.z_m, c.z_m, 1e-13);
    EXPECT_NEAR(a.dz_dx, b.dz_dx, 1e-10);
    EXPECT_NEAR(a.dz_dy, c.dz_dy, 1e-10);
  }
}

TEST(CrgSurface, SlopeIntegratesAndBankingTiltsAcross) {
  CrgData d = grid(5, 2.0, {-1.0, 1.0});
  std::fill(d.z_m.begin(), d.z_m.end(), 0.0f);
  d.start_z_m = 0.5;
  d.slope = {kNaN, 0.02, 0.04, -0.01, 0.0};  // entry i: from i-1 to i
  d.banking = {0.0, 0.05, 0.05, 0.1, 0.1};
  const CrgSurface s(d);
  SurfaceHint hint;
  // z_ref: 0.5, 0.54, 0.62, 0.60, 0.60; at u = 3 (half into the second step) 0.58
  const double bank = 0.05;
  const SurfaceHeight h = s.height(3.0, 0.4, hint);
  EXPECT_NEAR(h.z_m, 0.58 + bank * 0.4, 1e-14);
  EXPECT_NEAR(h.dz_dx, 0.04, 1e-14);
  EXPECT_NEAR(h.dz_dy, bank, 1e-14);
  // banking beyond the grid's side acts on the side's v (OpenCRG clamps v for it)
  EXPECT_NEAR(s.height(3.0, 1.7, hint).z_m, 0.58 + bank * 1.0, 1e-14);
  // a given end height takes the closure error, spread linearly over u
  d.end_z_m = 0.8;
  const CrgSurface closed(d);
  EXPECT_NEAR(closed.height(8.0, 0.0, hint).z_m, 0.8, 1e-14);
  EXPECT_NEAR(closed.height(4.0, 0.0, hint).z_m, 0.62 + 0.1, 1e-14);
}

TEST(CrgSurface, BorderModesBeyondTheEndsAndSides) {
  CrgData d = grid(5, 1.0, {-1.0, 0.0, 1.0});
  d.options.border_offset_u_m = 0.1;
  d.options.border_offset_v_m = 0.2;
  SurfaceHint hint;
  {
    const CrgSurface keep(d);  // default: keep the last cross / long section, plus the offset
    EXPECT_NEAR(keep.height(-3.0, 0.5, hint).z_m,
                0.5 * (z_at(d, 0, 1) + z_at(d, 0, 2)) + 0.1, 1e-15);
    EXPECT_EQ(keep.height(-3.0, 0.5, hint).dz_dx, 0.0);
    EXPECT_NEAR(keep.height(2.0, -4.0, hint).z_m, z_at(d, 2, 0) + 0.2, 1e-15);
    EXPECT_NEAR(keep.height(9.0, 4.0, hint).z_m, z_at(d, 4, 2) + 0.3, 1e-15);
  }
  d.options.border_u = CrgBorderMode::kZero;
  d.options.border_v = CrgBorderMode::kZero;
  {
    const CrgSurface zero(d);
    EXPECT_EQ(zero.height(-3.0, 0.5, hint).z_m, 0.1);
    EXPECT_EQ(zero.height(2.0, 1.5, hint).z_m, 0.2);
  }
  d.options.border_u = CrgBorderMode::kRepeat;
  d.options.border_v = CrgBorderMode::kReflect;
  {
    const CrgSurface s(d);
    SurfaceHint a;
    SurfaceHint b;
    EXPECT_NEAR(s.height(-0.7, 0.3, a).z_m, s.height(3.3, 0.3, b).z_m, 1e-15);  // period 4
    EXPECT_NEAR(s.height(9.6, 0.3, a).z_m, s.height(1.6, 0.3, b).z_m, 1e-15);
    EXPECT_NEAR(s.height(1.6, 1.4, a).z_m, s.height(1.6, 0.6, b).z_m, 1e-15);  // mirrored at 1
    EXPECT_NEAR(s.height(1.6, -2.5, a).z_m, s.height(1.6, 0.5, b).z_m, 1e-15);
    EXPECT_NEAR(s.height(1.6, 1.4, a).dz_dy, -s.height(1.6, 0.6, b).dz_dy, 1e-14);
  }
  d.options.border_u = CrgBorderMode::kReflect;
  {
    const CrgSurface s(d);
    SurfaceHint a;
    SurfaceHint b;
    EXPECT_NEAR(s.height(-0.7, 0.3, a).z_m, s.height(0.7, 0.3, b).z_m, 1e-15);
    EXPECT_NEAR(s.height(5.5, 0.3, a).z_m, s.height(2.5, 0.3, b).z_m, 1e-15);
  }
}

TEST(CrgSurface, SmoothingFadesTheHeightsInAndOut) {
  CrgData d = grid(11, 1.0, {-1.0, 1.0});
  d.start_z_m = 0.25;
  d.options.smooth_ubeg_m = 4.0;
  d.options.smooth_uend_m = 2.0;
  const CrgSurface s(d);
  CrgData plain = d;
  plain.options = {};
  const CrgSurface p(plain);
  SurfaceHint h;
  // z = base + (z - base) s, s = distance into the zone / zone, base = z_ref there
  EXPECT_NEAR(s.height(1.0, -1.0, h).z_m, 0.25 + (p.height(1.0, -1.0, h).z_m - 0.25) / 4, 1e-15);
  EXPECT_NEAR(s.height(9.5, 1.0, h).z_m, 0.25 + (p.height(9.5, 1.0, h).z_m - 0.25) / 4, 1e-15);
  EXPECT_EQ(s.height(-2.0, 0.0, h).z_m, 0.25);
  EXPECT_NEAR(s.height(5.0, 0.2, h).z_m, p.height(5.0, 0.2, h).z_m, 1e-15);
  expect_gradient_matches(s, 2.3, 0.1, 1e-8);
}

TEST(CrgSurface, NanCellsAtTheEndsOfACrossSection) {
  CrgData d = grid(3, 1.0, {-1.0, -0.5, 0.0, 0.5, 1.0});
  d.z_m[5 + 0] = static_cast<float>(kNaN);  // cross section 1: right end
  d.z_m[5 + 3] = static_cast<float>(kNaN);  // left end, two cells
  d.z_m[5 + 4] = static_cast<float>(kNaN);
  d.mods.nan_offset_m = 0.05;
  SurfaceHint h;
  const CrgSurface keep(d);  // GRID_NAN_MODE 2: the nearest valid value + the offset
  EXPECT_NEAR(keep.height(1.0, -1.0, h).z_m, z_at(d, 1, 1) + 0.05f, 1e-7);
  EXPECT_NEAR(keep.height(1.0, 1.0, h).z_m, z_at(d, 1, 2) + 0.05f, 1e-7);
  EXPECT_NEAR(keep.height(1.0, 0.0, h).z_m, z_at(d, 1, 2), 1e-15);
  d.mods.nan_mode = CrgNanMode::kSetZero;
  const CrgSurface zero(d);
  EXPECT_NEAR(zero.height(1.0, 0.5, h).z_m, 0.05, 1e-7);
}

TEST(CrgSurface, PlacementPutsTheReferencePointWhereItIsAsked) {
  const CrgData d = arc(30, 1.0, 0.04);
  Placement p;
  p.given = true;
  p.u_m = 12.0;
  p.v_m = 0.5;
  p.x_m = 100.0;
  p.y_m = -20.0;
  p.z_m = 3.0;
  p.heading_rad = 1.0;
  const CrgSurface s(d, p);
  const CrgSurface file(d);
  SurfaceHint h;
  EXPECT_NEAR(s.height(100.0, -20.0, h).z_m, 3.0, 1e-12);
  double x = 0;
  double y = 0;
  s.world_point(12.0, 0.5, x, y);
  EXPECT_NEAR(x, 100.0, 1e-12);
  EXPECT_NEAR(y, -20.0, 1e-12);
  // the reference line's heading at u = 12 (segment 12..13, phi_13 = 0.52) becomes 1.0: a step
  // along u from there goes along heading 1.0 in the world
  s.world_point(12.5, 0.5, x, y);
  double fx = 0;
  double fy = 0;
  file.world_point(12.5, 0.5, fx, fy);
  double rx = 0;
  double ry = 0;
  file.world_point(12.0, 0.5, rx, ry);
  const double turn = 1.0 - 13 * 0.04;
  EXPECT_NEAR(x - 100.0, std::cos(turn) * (fx - rx) - std::sin(turn) * (fy - ry), 1e-12);
  EXPECT_NEAR(y + 20.0, std::sin(turn) * (fx - rx) + std::cos(turn) * (fy - ry), 1e-12);
  // every node keeps its height, shifted by the same amount
  const double shift = 3.0 - file.height(rx, ry, h).z_m;
  s.world_point(20.0, -1.5, x, y);
  EXPECT_NEAR(s.height(x, y, h).z_m, z_at(d, 20, 0) + shift, 1e-12);
  expect_gradient_matches(s, x + 0.3, y - 0.2, 1e-7);
}

TEST(CrgSurface, QueriesAllocateNothing) {
  const CrgData d = arc(40, 0.5, 0.02);
  const CrgSurface s(d);
  SurfaceHint hint;
  double sum = 0;
  const rig::test::AllocationCounter counter;
  for (int n = 0; n < 1000; ++n) sum += s.height(0.02 * n - 2.0, 0.001 * n - 0.5, hint).z_m;
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::road
