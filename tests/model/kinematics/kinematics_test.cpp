// Kinematic tables of eq. (29): exactness on representable functions, derivatives by finite
// differences, clamped extrapolation, the geometry generator, zero allocation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "model/kinematics/kinematic_table.h"
#include "model/kinematics/wheel_kinematics.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::kinematics {
namespace {

const Grid2D kGrid{-0.08, 0.02, 9, -0.06, 0.015, 9};  // z in [-0.08, 0.08], u in [-0.06, 0.06]

template <class F>
KinematicTable sample(const Grid2D& g, F f) {
  std::vector<double> v;
  for (int k = 0; k < g.z_count; ++k)
    for (int l = 0; l < g.u_count; ++l)
      v.push_back(f(g.z_min + k * g.z_step, g.u_min + l * g.u_step));
  return KinematicTable(g, v);
}

double bilinear_fn(double z, double u) { return 0.3 - 1.7 * z + 2.5 * u + 40.0 * z * u; }
double quadratic_fn(double z, double u) {
  return bilinear_fn(z, u) + 12.0 * z * z - 7.0 * u * u + 30.0 * z * z * u;
}

TEST(KinematicTable, BilinearIsExactOnBilinearFunctionsEverywhere) {
  const KinematicTable t = sample(kGrid, bilinear_fn);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> z(-0.08, 0.08), u(-0.06, 0.06);
  for (int i = 0; i < 500; ++i) {
    const double zi = z(rng), ui = u(rng);
    for (Interpolation m : {Interpolation::kBilinear, Interpolation::kBicubic}) {
      const TableValue v = t.evaluate(zi, ui, m);
      EXPECT_NEAR(v.value, bilinear_fn(zi, ui), 1e-13);
      EXPECT_NEAR(v.d_dz, -1.7 + 40.0 * ui, 1e-11);
      EXPECT_NEAR(v.d_du, 2.5 + 40.0 * zi, 1e-11);
    }
  }
}

TEST(KinematicTable, BicubicIsExactOnQuadraticsInInteriorCells) {
  // Catmull-Rom reproduces degree-2 polynomials per direction (here z^2 u too) away from the
  // border cells, where the linear ghost nodes take over.
  const KinematicTable t = sample(kGrid, quadratic_fn);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> z(-0.06, 0.06), u(-0.045, 0.045);
  double bilinear_err = 0;
  for (int i = 0; i < 500; ++i) {
    const double zi = z(rng), ui = u(rng);
    const TableValue v = t.evaluate(zi, ui, Interpolation::kBicubic);
    EXPECT_NEAR(v.value, quadratic_fn(zi, ui), 1e-12);
    EXPECT_NEAR(v.d_dz, -1.7 + 40.0 * ui + 24.0 * zi + 60.0 * zi * ui, 1e-10);
    EXPECT_NEAR(v.d_du, 2.5 + 40.0 * zi - 14.0 * ui + 30.0 * zi * zi, 1e-10);
    // bilinear is not exact on it (so the check above does see the method)
    bilinear_err = std::max(
        bilinear_err,
        std::abs(t.evaluate(zi, ui, Interpolation::kBilinear).value - quadratic_fn(zi, ui)));
  }
  EXPECT_GT(bilinear_err, 1e-4);
  // nodes are reproduced by both methods
  EXPECT_DOUBLE_EQ(t.evaluate(0.04, 0.015, Interpolation::kBilinear).value, t.node(6, 5));
  EXPECT_NEAR(t.evaluate(0.04, 0.015, Interpolation::kBicubic).value, t.node(6, 5), 1e-15);
}

TEST(KinematicTable, PartialsMatchFiniteDifferencesOfTheInterpolant) {
  const KinematicTable t =
      sample(kGrid, [](double z, double u) { return std::sin(20 * z) * std::cos(15 * u); });
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> z(-0.0799, 0.0799), u(-0.0599, 0.0599);
  const double e = 1e-7;
  for (Interpolation m : {Interpolation::kBilinear, Interpolation::kBicubic}) {
    for (int i = 0; i < 300; ++i) {
      const double zi = z(rng), ui = u(rng);
      const TableValue v = t.evaluate(zi, ui, m);
      const double fz =
          (t.evaluate(zi + e, ui, m).value - t.evaluate(zi - e, ui, m).value) / (2 * e);
      const double fu =
          (t.evaluate(zi, ui + e, m).value - t.evaluate(zi, ui - e, m).value) / (2 * e);
      // bilinear is C0 at grid lines; random points are off them by far more than e
      EXPECT_NEAR(v.d_dz, fz, 1e-5 * (1 + std::abs(fz)));
      EXPECT_NEAR(v.d_du, fu, 1e-5 * (1 + std::abs(fu)));
    }
  }
  // the bicubic interpolant is C1: derivative continuous across a grid line
  const double zl = kGrid.z_min + 4 * kGrid.z_step;
  const TableValue a = t.evaluate(zl - 1e-9, 0.01, Interpolation::kBicubic);
  const TableValue b = t.evaluate(zl + 1e-9, 0.01, Interpolation::kBicubic);
  EXPECT_NEAR(a.d_dz, b.d_dz, 1e-6);
}

TEST(KinematicTable, ClampedExtrapolationHoldsTheBorder) {
  const KinematicTable t = sample(kGrid, quadratic_fn);
  for (Interpolation m : {Interpolation::kBilinear, Interpolation::kBicubic}) {
    const TableValue out = t.evaluate(0.2, -0.5, m);
    EXPECT_NEAR(out.value, t.node(8, 0), 1e-14);
    EXPECT_EQ(out.d_dz, 0.0);
    EXPECT_EQ(out.d_du, 0.0);
    const TableValue side = t.evaluate(-0.3, 0.0, m);  // out in z only: d/du still live
    EXPECT_NEAR(side.value, t.evaluate(-0.08, 0.0, m).value, 1e-14);
    EXPECT_EQ(side.d_dz, 0.0);
    EXPECT_NEAR(side.d_du, t.evaluate(-0.08, 0.0, m).d_du, 1e-12);
  }
}

TEST(KinematicTable, SingleGridLineIsConstantAndBadTablesThrow) {
  const Grid2D g{-0.1, 0.05, 5, 0.0, 1.0, 1};  // unsteered: u has one line
  const KinematicTable t = sample(g, [](double z, double) { return 3.0 * z; });
  const TableValue v = t.evaluate(0.03, 0.7, Interpolation::kBicubic);
  EXPECT_NEAR(v.value, 0.09, 1e-15);
  EXPECT_NEAR(v.d_dz, 3.0, 1e-12);
  EXPECT_EQ(v.d_du, 0.0);
  EXPECT_THROW(KinematicTable(g, std::vector<double>(4, 0.0)), std::invalid_argument);
  EXPECT_THROW(KinematicTable(Grid2D{0, -1, 3, 0, 1, 1}, std::vector<double>(3, 0.0)),
               std::invalid_argument);
  const KinematicTable other = sample(kGrid, bilinear_fn);
  EXPECT_THROW(WheelKinematics(t, t, t, t, other, Interpolation::kBilinear), std::invalid_argument);
}

TEST(WheelKinematics, GeneratedTablesFollowTheGeometry) {
  SuspensionGeometry g;
  g.steering_arm_m = 0.15;
  g.steer_y_per_u = 0.1;
  g.x_per_z = -0.05;
  g.beta_per_z = 0.1;
  const Grid2D grid{-0.1, 0.01, 21, -0.08, 0.008, 21};
  const WheelKinematics bicubic = generate_wheel_kinematics(g, grid, Interpolation::kBicubic);
  const WheelKinematics bilinear = generate_wheel_kinematics(g, grid, Interpolation::kBilinear);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> z(-0.09, 0.09), u(-0.07, 0.07);
  double err_cubic = 0, err_linear = 0;
  for (int i = 0; i < 300; ++i) {
    const double zi = z(rng), ui = u(rng);
    const WheelPose exact = evaluate_geometry(g, zi, ui);
    const WheelPose c = bicubic.evaluate(zi, ui);
    const WheelPose l = bilinear.evaluate(zi, ui);
    EXPECT_NEAR(c.x_m.value, exact.x_m.value, 1e-12);  // linear: exact
    EXPECT_NEAR(c.y_m.value, exact.y_m.value, 1e-12);  // quadratic in z, linear in u: exact
    EXPECT_NEAR(c.y_m.d_dz, exact.y_m.d_dz, 1e-10);
    EXPECT_NEAR(c.alpha_rad.value, exact.alpha_rad.value, 1e-12);
    EXPECT_NEAR(c.beta_rad.d_dz, 0.1, 1e-10);
    EXPECT_NEAR(c.gamma_rad.d_du, exact.gamma_rad.d_du, 1e-3 * exact.gamma_rad.d_du);
    EXPECT_NEAR(c.gamma_rad.d_dz, g.bump_steer_per_z, 1e-9);
    err_cubic = std::max(err_cubic, std::abs(c.gamma_rad.value - exact.gamma_rad.value));
    err_linear = std::max(err_linear, std::abs(l.gamma_rad.value - exact.gamma_rad.value));
  }
  // steer angle asin(u / arm): bicubic clearly beats bilinear on the curved function
  EXPECT_LT(err_cubic, 2e-5);  // 8 mm rack grid; asin is steepest at the border cells
  EXPECT_LT(err_cubic, 0.1 * err_linear);
  // the steer angle at full rack travel: asin(0.07/0.15)
  EXPECT_NEAR(bicubic.evaluate(0.0, 0.072).gamma_rad.value, std::asin(0.072 / 0.15), 1e-5);
}

TEST(WheelKinematics, EvaluationAllocatesNothing) {
  const WheelKinematics k =
      generate_wheel_kinematics(SuspensionGeometry{}, kGrid, Interpolation::kBicubic);
  double sum = 0;
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 1000; ++i) sum += k.evaluate(-0.1 + 2e-4 * i, 0.0).y_m.d_dz;
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::kinematics
