// Tests of model/solver: eq. (8) against hand computations, the arrowhead factorization of
// eqs. (30-31), finite-difference vs analytic Jacobians, the Newton criterion of the constraint
// coupling (eqs. 45-50), and zero allocation per step.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "model/paper/coupled_pendulums.h"
#include "model/paper/quarter_car.h"
#include "model/solver/arrowhead_factorization.h"
#include "model/solver/coupled_stepper.h"
#include "model/solver/finite_difference.h"
#include "model/solver/fixed_lu.h"
#include "model/solver/force_element_stepper.h"
#include "model/solver/kinematics_product.h"
#include "model/solver/mechanical_stepper.h"
#include "model/solver/sequential_stepper.h"
#include "model/tire/tmeasy_force_element.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::solver {
namespace {

// A linear spring-damper oscillator: m v' = -k x - d v - c_s s, x' = v (K = I), coupled to a
// linear force element s' = -a s + b v (a damper with its own state).
struct LinearElement final : ForceElement<1> {
  double a = 50.0, b = 2.0;
  const Eigen::Matrix<double, 1, 1>* v = nullptr;
  Vector s = Vector::Constant(0.1);
  Eigen::Index state_size() const noexcept override { return 1; }
  Vector& state() noexcept override { return s; }
  void rate(const Vector& st, Vector& f) const noexcept override {
    f(0) = -a * st(0) + b * (*v)(0);
  }
  bool rate_jacobian(const Vector&, Matrix& j) const noexcept override {
    j(0, 0) = -a;
    return true;
  }
};

struct LinearOscillator final : MechanicalBlock<1> {
  double m = 2.0, k = 800.0, d = 3.0, c_s = 10.0;
  const Eigen::Matrix<double, 1, 1>* s = nullptr;
  Vector y = Vector::Constant(0.05), z = Vector::Constant(-0.3);
  Eigen::Index size() const noexcept override { return 1; }
  Vector& coordinates() noexcept override { return y; }
  Vector& speeds() noexcept override { return z; }
  void mass_matrix(const Vector&, Matrix& mm) const noexcept override { mm(0, 0) = m; }
  void applied_forces(const Vector& yy, const Vector& zz, Vector& q) const noexcept override {
    q(0) = -k * yy(0) - d * zz(0) - c_s * (*s)(0);
  }
  bool force_jacobians(const Vector&, const Vector&, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override {
    dq_dy(0, 0) = -k;
    dq_dz(0, 0) = -d;
    return true;
  }
};

TEST(SequentialStepper, OneStepEqualsHandComputedEq8) {
  LinearOscillator osc;
  LinearElement el;
  el.v = &osc.z;
  osc.s = &el.s;
  ForceElementStepper<1> fe(el);
  MechanicalStepper<1> ms(osc);
  SequentialStepper engine(ms);
  engine.add_stage(fe);
  const double h = 0.01;
  const double s0 = el.s(0), x0 = osc.y(0), v0 = osc.z(0);
  engine.step(h);
  // eq. (8) by hand: s1 = s0 + h (-a s0 + b v0) / (1 + h a)
  const double s1 = s0 + h * (-el.a * s0 + el.b * v0) / (1.0 + h * el.a);
  // M_VI = m + h d + h^2 k; q at x0 + h v0 with the new s1
  const double m_vi = osc.m + h * osc.d + h * h * osc.k;
  const double q = -osc.k * (x0 + h * v0) - osc.d * v0 - osc.c_s * s1;
  const double v1 = v0 + h * q / m_vi;
  const double x1 = x0 + h * v1;
  EXPECT_NEAR(el.s(0), s1, 1e-15);
  EXPECT_NEAR(osc.z(0), v1, 1e-14);
  EXPECT_NEAR(osc.y(0), x1, 1e-15);
  EXPECT_NEAR(ms.modified_mass_matrix()(0, 0), m_vi, 1e-12);
}

TEST(SequentialStepper, FiniteDifferenceModeMatchesAnalytic) {
  LinearOscillator a, b;
  LinearElement ea, eb;
  ea.v = &a.z;
  a.s = &ea.s;
  eb.v = &b.z;
  b.s = &eb.s;
  ForceElementStepper<1> fa(ea), fb(eb, JacobianMode::kFiniteDifference);
  MechanicalStepper<1> ma(a), mb(b, JacobianMode::kFiniteDifference);
  for (int i = 0; i < 100; ++i) {
    fa.advance(1e-3);
    ma.advance(1e-3);
    fb.advance(1e-3);
    mb.advance(1e-3);
  }
  EXPECT_NEAR(a.y(0), b.y(0), 1e-9);
  EXPECT_NEAR(a.z(0), b.z(0), 1e-7);
  EXPECT_NEAR(ea.s(0), eb.s(0), 1e-9);
}

TEST(SequentialStepper, StiffSpringStableAtLargeStep) {
  // k/m = 1e8 1/s^2: explicit Euler would explode at h = 1e-2 (|1 + i h w| > 1); the modified
  // implicit Euler decays.
  LinearOscillator osc;
  osc.k = 2e8;
  osc.c_s = 0.0;
  Eigen::Matrix<double, 1, 1> zero_s = Eigen::Matrix<double, 1, 1>::Zero();
  osc.s = &zero_s;
  MechanicalStepper<1> ms(osc);
  const double e0 = 0.5 * osc.k * osc.y(0) * osc.y(0) + 0.5 * osc.m * osc.z(0) * osc.z(0);
  for (int i = 0; i < 1000; ++i) ms.advance(1e-2);
  const double e1 = 0.5 * osc.k * osc.y(0) * osc.y(0) + 0.5 * osc.m * osc.z(0) * osc.z(0);
  EXPECT_LT(e1, 1e-6 * e0);
}

// ---- arrowhead factorization (eqs. 30-31) ----
Eigen::MatrixXd random_arrowhead(const ArrowheadPartition& p, unsigned seed) {
  std::srand(seed);
  const Eigen::Index n = p.total_size();
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
  a.diagonal().array() += static_cast<double>(n);  // well conditioned
  Eigen::Index oi = p.body_size;
  for (std::size_t i = 0; i < p.leaf_sizes.size(); ++i) {
    Eigen::Index oj = p.body_size;
    for (std::size_t j = 0; j < p.leaf_sizes.size(); ++j) {
      if (i != j) a.block(oi, oj, p.leaf_sizes[i], p.leaf_sizes[j]).setZero();
      oj += p.leaf_sizes[j];
    }
    oi += p.leaf_sizes[i];
  }
  return a;
}

TEST(ArrowheadFactorization, SolvesLikeDenseLu) {
  const ArrowheadPartition p{6, {5, 5, 4}};  // body, front axle, rear axle, third axle
  const Eigen::MatrixXd a = random_arrowhead(p, 7);
  ArrowheadFactorization f(p);
  f.compute(a);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(p.total_size(), 3);
  Eigen::MatrixXd x(p.total_size(), 3);
  f.solve(b, x);
  const Eigen::MatrixXd x_dense = a.partialPivLu().solve(b);
  EXPECT_LT((x - x_dense).norm(), 1e-12 * x_dense.norm());
  EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm());
}

// The vehicle's partition (6-DOF body, 2 hub travels per axle) takes the fixed-size path.
TEST(ArrowheadFactorization, VehiclePartitionSolvesLikeDenseLu) {
  for (const std::size_t axles : {1u, 2u, 3u, 6u}) {
    const ArrowheadPartition p{6, std::vector<Eigen::Index>(axles, 2)};
    const Eigen::MatrixXd a = random_arrowhead(p, 5 + static_cast<unsigned>(axles));
    ArrowheadFactorization f(p);
    f.compute(a);
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(p.total_size(), 3);
    Eigen::MatrixXd x(p.total_size(), 3);
    f.solve(b, x);
    const Eigen::MatrixXd x_dense = a.partialPivLu().solve(b);
    EXPECT_LT((x - x_dense).norm(), 1e-12 * x_dense.norm()) << axles << " axles";
    EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm()) << axles << " axles";
  }
}

// A body tail (body speeds stored after the leaves, the vehicle's frame twist): coupled to the
// body and to every leaf, it is factorized with the body; the leaves' mutual blocks are ignored.
TEST(ArrowheadFactorization, BodyTailSolvesLikeDenseLu) {
  for (const ArrowheadPartition& p :
       {ArrowheadPartition{6, {2, 2, 2}, 1}, ArrowheadPartition{6, {5, 4}, 2}}) {
    const Eigen::MatrixXd a = random_arrowhead(p, 17);
    Eigen::MatrixXd with_garbage = a;
    with_garbage(p.body_size, p.body_size + p.leaf_sizes[0]) = 1e3;  // a leaf-leaf entry
    ArrowheadFactorization f(p);
    EXPECT_EQ(f.partition().body_size, p.body_size + p.body_tail_size);
    f.compute(with_garbage);
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(p.total_size(), 3);
    Eigen::MatrixXd x(p.total_size(), 3);
    f.solve(b, x);
    const Eigen::MatrixXd x_dense = a.partialPivLu().solve(b);
    EXPECT_LT((x - x_dense).norm(), 1e-12 * x_dense.norm()) << p.body_tail_size;
    EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm()) << p.body_tail_size;
  }
}

// A right-hand side that is zero on the leaf rows: the body rows of the full solve equal S^-1 b_B
// (solve_body), on the fixed-size vehicle path and on the general one.
TEST(ArrowheadFactorization, BodySolveEqualsBodyRowsOfTheFullSolve) {
  for (const ArrowheadPartition& p :
       {ArrowheadPartition{6, {2, 2}}, ArrowheadPartition{6, {2, 2, 2}},
        ArrowheadPartition{6, {5, 5, 4}}, ArrowheadPartition{3, {2, 2}}}) {
    const Eigen::MatrixXd a = random_arrowhead(p, 13);
    ArrowheadFactorization f(p);
    f.compute(a);
    const Eigen::Index nb = p.body_size;
    const Eigen::MatrixXd b_body = Eigen::MatrixXd::Random(nb, 5);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(p.total_size(), 5);
    b.topRows(nb) = b_body;
    Eigen::MatrixXd x(p.total_size(), 5);
    f.solve(b, x);
    Eigen::MatrixXd x_body(nb, 5);
    f.solve_body(b_body, x_body);
    EXPECT_LE((x_body - x.topRows(nb)).norm(), 1e-12 * x.topRows(nb).norm()) << nb;
  }
}

// The chassis rows alone (a joint's forces, ChainStepper): b on the body's head rows, zero on
// the leaves and on a tail. solve_body pads the tail with zeros and gives exactly (bit for bit)
// the head rows of the full solve, on the 6-DOF path, the 7-DOF path (a frame's twist as the
// tail) and the general one; and they solve A x = [b; 0] as dense LU does.
TEST(ArrowheadFactorization, HeadRowsSolveEqualsTheFullSolveBitForBit) {
  for (const ArrowheadPartition& p :
       {ArrowheadPartition{6, {2, 2, 2}}, ArrowheadPartition{6, {2, 2, 2}, 1},
        ArrowheadPartition{6, {2, 2}, 1}, ArrowheadPartition{6, {5, 4}, 2}}) {
    const Eigen::MatrixXd a = random_arrowhead(p, 23);
    ArrowheadFactorization f(p);
    EXPECT_EQ(f.body_head_size(), 6);
    f.compute(a);
    const Eigen::MatrixXd b_head = Eigen::MatrixXd::Random(6, 4);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(p.total_size(), 4);
    b.topRows(6) = b_head;
    Eigen::MatrixXd x(p.total_size(), 4);
    f.solve(b, x);
    Eigen::MatrixXd x_head(6, 4);
    f.solve_body(b_head, x_head);
    EXPECT_EQ(x_head, x.topRows(6)) << p.body_tail_size;
    const Eigen::MatrixXd x_dense = a.partialPivLu().solve(b);
    EXPECT_LT((x - x_dense).norm(), 1e-12 * x_dense.norm()) << p.body_tail_size;
  }
}

// M_VI -= h^2 dq/dy K^-1 for K^-1 = diag(R, E, I) (the framework's): the structured product
// equals Eigen's general product bit for bit (the sums in the same order, K's zeros left out).
TEST(KinematicsProduct, EqualsTheGeneralProductBitForBit) {
  for (Eigen::Index n = 6; n <= 24; ++n) {
    std::srand(static_cast<unsigned>(n));
    const Eigen::MatrixXd dq_dy = Eigen::MatrixXd::Random(n, n) * 1e5;
    Eigen::MatrixXd k_inv = Eigen::MatrixXd::Identity(n, n);
    k_inv.topLeftCorner(3, 3) = Eigen::Matrix3d::Random();
    k_inv.block(3, 3, 3, 3) = Eigen::Matrix3d::Random();
    const Eigen::MatrixXd m0 = Eigen::MatrixXd::Random(n, n) * 1e3;
    const double h = 1e-3;
    Eigen::MatrixXd general = m0, structured = m0;
    general.noalias() -= (h * h) * dq_dy * k_inv;
    subtract_dq_dy_k_inv(6, -(h * h), dq_dy, k_inv, structured);
    EXPECT_EQ(structured, general) << n;
    EXPECT_LT((structured - (m0 - h * h * dq_dy * k_inv)).norm(), 1e-12 * m0.norm()) << n;
  }
}

// y += h K^-1 z for the same K^-1 (eq. 6's prediction, eq. 8's update): equal to Eigen's GEMV
// of the dynamic-size product bit for bit.
TEST(KinematicsProduct, VectorEqualsTheGeneralProductBitForBit) {
  for (Eigen::Index n = 6; n <= 24; ++n) {
    std::srand(static_cast<unsigned>(100 + n));
    Eigen::MatrixXd k_inv = Eigen::MatrixXd::Identity(n, n);
    k_inv.topLeftCorner(3, 3) = Eigen::Matrix3d::Random();
    k_inv.block(3, 3, 3, 3) = Eigen::Matrix3d::Random() * 3.0;
    const Eigen::VectorXd z = Eigen::VectorXd::Random(n) * 30.0;
    const Eigen::VectorXd y0 = Eigen::VectorXd::Random(n) * 100.0;
    const double h = 1e-3;
    Eigen::VectorXd general = y0, structured = y0;
    general.noalias() += h * k_inv * z;
    add_k_inv_times(6, h, k_inv, z, structured);
    EXPECT_EQ(std::memcmp(structured.data(), general.data(),
                          sizeof(double) * static_cast<std::size_t>(n)),
              0)
        << n;
  }
}

TEST(ArrowheadFactorization, IgnoresEntriesOfTheZeroBlocks) {
  const ArrowheadPartition p{3, {2, 2}};
  Eigen::MatrixXd a = random_arrowhead(p, 11);
  ArrowheadFactorization f(p);
  f.compute(a);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(7);
  Eigen::VectorXd x1(7), x2(7);
  f.solve(b, x1);
  a.block(3, 5, 2, 2).setConstant(99.0);  // front-rear block: not part of the structure
  f.compute(a);
  f.solve(b, x2);
  EXPECT_EQ((x1 - x2).norm(), 0.0);
}

// A 7-DOF block with arrowhead structure: body (3) + two "axles" (2 each), springs to ground
// and body-axle springs; stepped with the arrowhead factorization vs dense.
struct ArrowBlock final : MechanicalBlock<Eigen::Dynamic> {
  Vector y = Vector::LinSpaced(7, 0.01, 0.07), z = Vector::Zero(7);
  Matrix stiffness = Matrix::Zero(7, 7);
  ArrowBlock() {
    const ArrowheadPartition p{3, {2, 2}};
    stiffness = -random_arrowhead(p, 3).cwiseAbs() * 1e4;
    stiffness = 0.5 * (stiffness + stiffness.transpose()).eval();
  }
  Eigen::Index size() const noexcept override { return 7; }
  Vector& coordinates() noexcept override { return y; }
  Vector& speeds() noexcept override { return z; }
  void mass_matrix(const Vector&, Matrix& m) const noexcept override {
    m.setIdentity();
    m.diagonal() *= 3.0;
  }
  void applied_forces(const Vector& yy, const Vector& zz, Vector& q) const noexcept override {
    q.noalias() = stiffness * yy;
    q -= 5.0 * zz;
  }
  bool force_jacobians(const Vector&, const Vector&, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override {
    dq_dy = stiffness;
    dq_dz.setIdentity();
    dq_dz *= -5.0;
    return true;
  }
};

TEST(MechanicalStepper, ArrowheadAndDenseGiveTheSameSteps) {
  ArrowBlock b1, b2;
  MechanicalStepper<Eigen::Dynamic> dense(b1);
  MechanicalStepper<Eigen::Dynamic, ArrowheadFactorization> arrow(b2,
                                                                  ArrowheadPartition{3, {2, 2}});
  for (int i = 0; i < 200; ++i) {
    dense.advance(1e-3);
    arrow.advance(1e-3);
  }
  EXPECT_LT((b1.y - b2.y).norm(), 1e-12);
  EXPECT_GT(b1.y.norm(), 1e-6);  // it moved
}

// solve_mass_leading: the Schur shortcut (rows = body size) and the full solve restricted to the
// leading rows (other row counts, dense factorization) give the leading rows of solve_mass.
TEST(MechanicalStepper, SolveMassLeadingEqualsLeadingRowsOfTheFullSolve) {
  ArrowBlock b1, b2;
  MechanicalStepper<Eigen::Dynamic> dense(b1);
  MechanicalStepper<Eigen::Dynamic, ArrowheadFactorization> arrow(b2,
                                                                  ArrowheadPartition{3, {2, 2}});
  dense.begin_step(1e-3);
  arrow.begin_step(1e-3);
  for (const Eigen::Index r : {Eigen::Index{3}, Eigen::Index{2}, Eigen::Index{5}}) {
    const Eigen::MatrixXd b_lead = Eigen::MatrixXd::Random(r, 4);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(7, 4);
    b.topRows(r) = b_lead;
    for (const CouplableSystem* s : {static_cast<const CouplableSystem*>(&dense),
                                     static_cast<const CouplableSystem*>(&arrow)}) {
      Eigen::MatrixXd x(7, 4), x_lead(r, 4);
      s->solve_mass(b, x);
      s->solve_mass_leading(b_lead, x_lead);
      EXPECT_LE((x_lead - x.topRows(r)).norm(), 1e-12 * x.topRows(r).norm()) << r;
    }
  }
}

// ---- finite differences vs analytic Jacobians of the paper blocks ----
TEST(Jacobians, PendulumAnalyticMatchesFiniteDifference) {
  paper::Pendulum p(10.0, 1.0, 9.81, 0.7);
  Eigen::Matrix<double, 1, 1> y, z, dy_a, dz_a, dy_f, dz_f, w1, w2, q0, q1;
  y << 0.7;
  z << 0.4;
  ASSERT_TRUE(p.force_jacobians(y, z, dy_a, dz_a));
  finite_difference_force_jacobians<1>(p, y, z, dy_f, dz_f, w1, w2, q0, q1);
  EXPECT_NEAR(dy_a(0, 0), dy_f(0, 0), 1e-6 * std::abs(dy_a(0, 0)));
  EXPECT_NEAR(dz_a(0, 0), dz_f(0, 0), 1e-6);
}

TEST(Jacobians, QuarterCarBodyAndTireAnalyticMatchFiniteDifference) {
  const paper::QuarterCarParams params;
  const paper::QuarterCarTire tire(params.tire, 3900.0, params.wheel_radius_m);
  for (const auto& [v, w, x_e] :
       {std::tuple{10.0, 34.0, 0.004}, std::tuple{0.3, 0.5, -0.002}, std::tuple{5.0, 18.0, 0.0}}) {
    Eigen::Vector2d s(x_e, 0.0);
    Eigen::Vector2d y(1.0, 0.0), z(v, w);
    paper::QuarterCarBody body(params, tire, y, z, s);
    Eigen::Matrix2d dy_a, dz_a, dy_f, dz_f;
    Eigen::Vector2d w1, w2, q0, q1;
    ASSERT_TRUE(body.force_jacobians(y, z, dy_a, dz_a));
    finite_difference_force_jacobians<2>(body, y, z, dy_f, dz_f, w1, w2, q0, q1);
    EXPECT_LT((dz_a - dz_f).norm(), 1e-4 * dz_a.norm()) << "v=" << v << " w=" << w;
    EXPECT_LT((dy_a - dy_f).norm(), 1e-6);

    const tire::TireContact contact = tire.contact(v, w);
    tire::TmeasyForceElement el(params.tire, contact, s);
    Eigen::Matrix2d j_a, j_f;
    Eigen::Vector2d ws, f0, f1;
    ASSERT_TRUE(el.rate_jacobian(s, j_a));
    finite_difference_rate_jacobian<2>(el, s, j_f, ws, f0, f1);
    EXPECT_NEAR(j_a(0, 0), j_f(0, 0), 1e-4 * std::abs(j_a(0, 0)));
  }
}

// ---- constraint coupling: the Newton criterion ----
// At h = 1 ms a position-only tolerance of 0.1 mm accepts the warm start (the previous lambda):
// |g| stays below the tolerance while the rod force wanders far off (measured: errors of
// ~10x the peak force). The default
// criterion also demands a small relative lambda increment and tracks the force.
TEST(ConstraintCoupling, PositionOnlyCriterionLeavesLambdaWrong) {
  NewtonParams loose;
  loose.criterion = NewtonCriterion::kPosition;
  loose.position_tolerance = 1e-4;  // 0.1 mm
  paper::CoupledPendulums tight_run;
  paper::CoupledPendulums loose_run({}, loose);
  double max_force_error = 0, max_g_loose = 0, peak = 0;
  int loose_iterations = 0;
  for (int i = 0; i < 1000; ++i) {
    tight_run.step(1e-3);
    loose_iterations += loose_run.step(1e-3).iterations;
    max_force_error =
        std::max(max_force_error, std::abs(tight_run.rod_force_n() - loose_run.rod_force_n()));
    max_g_loose = std::max(max_g_loose, std::abs(loose_run.constraint_violation_m()));
    peak = std::max(peak, std::abs(tight_run.rod_force_n()));
  }
  EXPECT_LT(max_g_loose, 1e-4);            // |g| looks fine...
  EXPECT_GT(max_force_error, 0.3 * peak);  // ...but lambda is badly wrong
  std::printf(
      "position-only criterion (0.1 mm): max rod force error %.1f N (peak %.1f N), "
      "%d Newton iterations in 1000 steps\n",
      max_force_error, peak, loose_iterations);
}

TEST(ConstraintCoupling, ReportsIterationsResidualAndCap) {
  NewtonParams capped = paper::default_pendulum_newton_params();
  capped.max_iterations = 1;
  paper::CoupledPendulums p({}, capped);
  const NewtonReport r = p.step(0.05);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.residual, 0.0);
  paper::CoupledPendulums q;
  const NewtonReport r2 = q.step(0.05);
  EXPECT_TRUE(r2.converged);
  EXPECT_LE(r2.residual, 1e-7);
  EXPECT_NEAR(std::abs(q.constraint_violation_m()), r2.residual, 1e-12);
}

// Two engines (oscillator + its damper element each) joined by y1 - y2 = d0: a linear
// constraint, so Newton converges in one iteration and g = 0 to round-off; the multiplier is
// the force that a rigid link would carry (equal and opposite on both systems).
struct OffsetConstraint final : ConstraintFunction {
  double offset = 0.0;
  Eigen::Index size() const noexcept override { return 1; }
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dy) const noexcept override {
    g(0) = y(0) - y(1) - offset;
    dg_dy << 1.0, -1.0;
  }
};

TEST(CoupledStepper, EnginesJoinedByALinearConstraint) {
  LinearOscillator o1, o2;
  LinearElement e1, e2;
  e1.v = &o1.z;
  o1.s = &e1.s;
  e2.v = &o2.z;
  o2.s = &e2.s;
  o2.m = 5.0;
  o2.k = 100.0;
  o2.y(0) = 0.02;
  ForceElementStepper<1> f1(e1), f2(e2);
  MechanicalStepper<1> m1(o1), m2(o2);
  SequentialStepper engine1(m1), engine2(m2);
  engine1.add_stage(f1);
  engine2.add_stage(f2);
  OffsetConstraint c;
  c.offset = o1.y(0) - o2.y(0);
  CoupledStepper coupled({&engine1, &engine2}, c);
  for (int i = 0; i < 500; ++i) {
    const NewtonReport r = coupled.step(1e-3);
    ASSERT_TRUE(r.converged);
    ASSERT_LE(r.iterations, 2);
    ASSERT_NEAR(o1.y(0) - o2.y(0), c.offset, 1e-14);
  }
  // Rigidly joined: one body of mass m1 + m2 -> equal speeds
  EXPECT_NEAR(o1.z(0), o2.z(0), 1e-12);
  EXPECT_GT(std::abs(coupled.multipliers()(0)), 1e-3);
}

TEST(SequentialStepper, StagesRunInOrderWithTheNewestStates) {
  // The framework's force reads the element's state: after a step it must have used s(k+1).
  LinearOscillator osc;
  LinearElement el;
  el.v = &osc.z;
  osc.s = &el.s;
  osc.k = 0.0;
  osc.d = 0.0;
  ForceElementStepper<1> fe(el);
  MechanicalStepper<1> ms(osc);
  SequentialStepper engine(ms);
  engine.add_stage(fe);
  const double v0 = osc.z(0);
  engine.step(0.01);
  EXPECT_NEAR(osc.z(0), v0 + 0.01 * (-osc.c_s * el.s(0)) / osc.m, 1e-15);
}

// ---- no allocation per step ----
// A 12-state linear element of dynamic size (like the vehicle's half shafts).
struct DynamicElement final : ForceElement<Eigen::Dynamic> {
  Vector s = Vector::LinSpaced(12, -1.0, 1.0);
  Matrix a = -Matrix::Identity(12, 12) * 30.0 + Matrix::Constant(12, 12, 0.5);
  Eigen::Index state_size() const noexcept override { return 12; }
  Vector& state() noexcept override { return s; }
  void rate(const Vector& st, Vector& f) const noexcept override { f.noalias() = a * st; }
  bool rate_jacobian(const Vector&, Matrix& j) const noexcept override {
    j = a;
    return true;
  }
};

TEST(NoAllocation, SolverStepsAllocateNothing) {
  paper::CoupledPendulums pendulums;
  paper::QuarterCar car;
  ArrowBlock block;
  MechanicalStepper<Eigen::Dynamic, ArrowheadFactorization> arrow(block,
                                                                  ArrowheadPartition{3, {2, 2}});
  LinearOscillator osc;
  LinearElement el;
  el.v = &osc.z;
  osc.s = &el.s;
  ForceElementStepper<1> fe(el, JacobianMode::kFiniteDifference);
  MechanicalStepper<1> ms(osc, JacobianMode::kFiniteDifference);
  SequentialStepper engine(ms);
  engine.add_stage(fe);
  ArrowBlock dense_block;
  MechanicalStepper<Eigen::Dynamic> dense(dense_block, JacobianMode::kFiniteDifference);
  DynamicElement dyn_element;
  ForceElementStepper<Eigen::Dynamic> dyn_stepper(dyn_element);
  ForceElementStepper<Eigen::Dynamic> dyn_stepper_fd(dyn_element, JacobianMode::kFiniteDifference);
  const Eigen::MatrixXd b_lead = Eigen::MatrixXd::Ones(3, 2);
  Eigen::MatrixXd x_lead(3, 2);
  const test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  for (int i = 0; i < 2000; ++i) {
    dense.advance(1e-3);
    dense.solve_mass_leading(b_lead, x_lead);  // full solve, leading rows
    dyn_stepper.advance(1e-3);
    dyn_stepper_fd.advance(1e-3);
    pendulums.step(1e-3);
    car.step(1e-3, paper::paper_maneuver_inputs(i * 1e-3 * 10));
    arrow.advance(1e-3);
    arrow.solve_mass_leading(b_lead, x_lead);  // Schur shortcut
    engine.step(1e-3);
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
}

// FixedLU (model/solver/fixed_lu.h) against Eigen's PartialPivLU of the same fixed size: the
// same factors, solutions and inverse, bit for bit, on random matrices (pivoting on), on ones
// with a zero column and exact ties of the pivot candidates, and on a singular one.
template <typename A, typename B>
bool same_bits(const A& a, const B& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

template <int N>
void expect_fixed_lu_equals_eigen(const Eigen::Matrix<double, N, N>& a, int seed) {
  using Mat = Eigen::Matrix<double, N, N>;
  using Vec = Eigen::Matrix<double, N, 1>;
  const Eigen::PartialPivLU<Mat> eigen(a);
  const FixedLU<N> fixed(a);
  EXPECT_TRUE(same_bits(fixed.matrix_lu(), eigen.matrixLU())) << N << " seed " << seed;
  const Vec b = Vec::Random() * 1e3;
  const Vec x_eigen = eigen.solve(b);
  const Vec x_fixed = fixed.solve(b);
  EXPECT_TRUE(same_bits(x_fixed, x_eigen)) << N << " seed " << seed;
  const Eigen::Matrix<double, N, 3> bm = Eigen::Matrix<double, N, 3>::Random();
  const Eigen::Matrix<double, N, 3> xm_eigen = eigen.solve(bm);
  EXPECT_TRUE(same_bits(fixed.solve(bm), xm_eigen)) << N << " seed " << seed;
  const Mat inv_eigen = eigen.inverse();
  EXPECT_TRUE(same_bits(fixed.inverse(), inv_eigen)) << N << " seed " << seed;
}

template <int N>
void fixed_lu_cases() {
  using Mat = Eigen::Matrix<double, N, N>;
  for (int seed = 1; seed <= 200; ++seed) {
    std::srand(static_cast<unsigned>(seed));
    Mat a = Mat::Random() * 1e4;
    if (seed % 4 == 0) a += Mat::Identity() * 1e6;  // diagonally dominant: no exchanges
    if (seed % 5 == 0) a.col(seed % N).setZero();   // a zero column: no division there
    if (seed % 7 == 0) a(1 % N, 0) = -a(0, 0);      // tied candidates: the first is taken
    expect_fixed_lu_equals_eigen<N>(a, seed);
  }
  Mat singular = Mat::Random();
  singular.row(N - 1) = singular.row(0);
  expect_fixed_lu_equals_eigen<N>(singular, 0);
}

TEST(FixedLU, EqualsEigensPartialPivLuBitForBit) {
  fixed_lu_cases<2>();
  fixed_lu_cases<3>();
  fixed_lu_cases<6>();
  fixed_lu_cases<7>();
}

}  // namespace
}  // namespace rig::model::solver
