// TMeasy acceptance tests of the one tire law (model/tire/tmeasy_tire.h): steady-state curves
// against hand computations, stand-still hold (eq. 24), locked wheel (eq. 25), the elliptic
// limiter (eq. 26), the damping-path partials against finite differences, lift-off, the aligning
// torque, zero allocation.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "model/tire/tmeasy_characteristic.h"
#include "model/tire/tmeasy_tire.h"
#include "model/tire/vertical_tire_force.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::tire {
namespace {

constexpr double kR = 0.3;   // rolling radius for the tests [m]
constexpr double kVn = 0.5;  // v_N of the default set

// Hand formulas, written out independently of the library.
double hand_parabola(double w1, double w2, double q) {
  return q * (2 * w1 - w2 / 2 - (w1 - w2 / 2) * q);
}
double hand_linear(double w1, double w2, double q) { return w1 + (w2 - w1) * (q - 1); }
// Rill's characteristic F(s), s >= 0.
double hand_curve(double df0, double fm, double sm, double fs, double ss, double s) {
  if (s <= sm) {
    const double sig = s / sm;
    return df0 * s / (1 + sig * (sig + df0 * sm / fm - 2));
  }
  if (s <= ss) {
    const double sig = (s - sm) / (ss - sm);
    return fm - (fm - fs) * sig * sig * (3 - 2 * sig);
  }
  return fs;
}
struct HandCurve {
  double df0, fm, sm, fs, ss;
};
HandCurve hand_long(double fz) {
  const double q = fz / 3500.0;
  const double fm = hand_parabola(3900, 7400, q);
  const double sm = hand_linear(0.11, 0.15, q);
  return {hand_parabola(100e3, 190e3, q), fm, sm, hand_parabola(0.9 * 3900, 0.9 * 7400, q), 3 * sm};
}
HandCurve hand_lat(double fz) {
  const double q = fz / 3500.0;
  const double fm = hand_parabola(3650, 6935, q);
  const double sm = hand_linear(0.16, 0.21, q);
  return {hand_parabola(80e3, 152e3, q), fm, sm, hand_parabola(0.9 * 3650, 0.9 * 6935, q), 3 * sm};
}
// TMeasy normalizing factor s^x (Rill 2011, eq. 3.83).
double hand_norm_x(const HandCurve& x, const HandCurve& y) {
  return x.sm / (x.sm + y.sm) + (x.fm / x.df0) / (x.fm / x.df0 + y.fm / y.df0);
}
double hand_norm_y(const HandCurve& x, const HandCurve& y) {
  return y.sm / (x.sm + y.sm) + (y.fm / y.df0) / (x.fm / x.df0 + y.fm / y.df0);
}

TEST(TmeasyLoad, ParabolaAtOneAndAHalfNominalLoadByHand) {
  const TmeasyParams p = default_215_55_r18();
  // q = 1.5: dFx0 = 1.5 (200 - 95 - (100 - 95) 1.5) kN = 146.25 kN;
  //          F_xM = 1.5 (7.8 - 3.7 - (3.9 - 3.7) 1.5) kN = 5.7 kN; s_xM = 0.11 + 0.04 * 0.5 = 0.13
  const TmeasyCurve x = curve_at_load(p.longitudinal, 1.5, 1.0);
  EXPECT_NEAR(x.initial_slope_n, 146250.0, 1e-6);
  EXPECT_NEAR(x.max_force_n, 5700.0, 1e-9);
  EXPECT_NEAR(x.max_slip, 0.13, 1e-15);
  EXPECT_NEAR(x.slide_force_n, 0.9 * 5700.0, 1e-9);
  EXPECT_NEAR(x.slide_slip, 0.39, 1e-15);
  // lateral: dFy0 = 1.5 (160 - 76 - 4 * 1.5) kN = 117 kN; F_yM = 1.5 (7.3 - 3.4675 - 0.1825 * 1.5)
  // kN
  const TmeasyCurve y = curve_at_load(p.lateral, 1.5, 1.0);
  EXPECT_NEAR(y.initial_slope_n, 117000.0, 1e-6);
  EXPECT_NEAR(y.max_force_n, 1.5 * (7300.0 - 3467.5 - 182.5 * 1.5), 1e-9);
  EXPECT_NEAR(y.max_slip, 0.185, 1e-15);
  // the parabola passes through both reference loads
  EXPECT_DOUBLE_EQ(curve_at_load(p.longitudinal, 1.0, 1.0).max_force_n, 3900.0);
  EXPECT_DOUBLE_EQ(curve_at_load(p.longitudinal, 2.0, 1.0).max_force_n, 7400.0);
  EXPECT_DOUBLE_EQ(curve_at_load(p.lateral, 2.0, 1.0).initial_slope_n, 152e3);
  // friction mu/mu0 = 0.5 halves forces and slips, keeps the initial slope
  const TmeasyCurve w = curve_at_load(p.longitudinal, 1.0, 0.5);
  EXPECT_DOUBLE_EQ(w.max_force_n, 1950.0);
  EXPECT_DOUBLE_EQ(w.max_slip, 0.055);
  EXPECT_DOUBLE_EQ(w.initial_slope_n, 100e3);
  // d/dq by hand: 2 w1 - w2/2 - 2 (w1 - w2/2) q at q = 1.5: 7.8 - 3.7 - 0.6 = 3.5 kN
  EXPECT_NEAR(curve_at_load_dq(p.longitudinal, 1.5, 1.0).max_force_n, 3500.0, 1e-9);
}

TEST(TmeasyLoad, DefaultSetIsValidAndBadValuesAreNamed) {
  TmeasyParams p = default_215_55_r18();
  EXPECT_EQ(check_params(p), nullptr);
  EXPECT_EQ(p.lateral.at_double.slide_force_n, 0.9 * 6935.0);
  EXPECT_EQ(p.lateral.at_double.slide_slip, 3 * 0.21);
  p.longitudinal.at_double.slide_slip = 0.1;  // below s_M = 0.15
  ASSERT_NE(check_params(p), nullptr);
  EXPECT_STREQ(check_params(p), "longitudinal.at_double: need 0 < s_M < s_S");
  p = default_215_55_r18();
  p.velocity_floor_mps = 0;
  EXPECT_STREQ(check_params(p), "velocity_floor_mps: v_N must be > 0");
}

TEST(TmeasyCharacteristic, SegmentsByHand) {
  const TmeasyCurve c{100e3, 3900, 0.11, 3510, 0.33};
  EXPECT_NEAR(evaluate_characteristic(c, 0.0).f_n, 100e3, 1e-9);  // f(0) = dF0
  EXPECT_NEAR(evaluate_characteristic(c, 0.11).force_n, 3900, 1e-9);
  EXPECT_NEAR(evaluate_characteristic(c, 0.11).dforce_ds, 0.0, 1e-6);  // maximum
  EXPECT_NEAR(evaluate_characteristic(c, 0.5).force_n, 3510, 1e-9);
  // mid of the cubic: sigma = 1/2 -> F_M - (F_M - F_S)/2
  EXPECT_NEAR(evaluate_characteristic(c, 0.22).force_n, 3705, 1e-9);
  // rational segment at s = 0.05: sigma = 5/11, A = 100e3 * 0.11 / 3900
  const double sig = 0.05 / 0.11, a = 100e3 * 0.11 / 3900;
  EXPECT_NEAR(evaluate_characteristic(c, 0.05).force_n, 5000.0 / (1 + sig * (sig + a - 2)), 1e-9);
}

// Per-call inputs as the tests state them: the kinematics plus F_z and mu.
struct TireInput {
  double long_speed_mps = 0;
  double lat_speed_mps = 0;
  double spin_radps = 0;
  double rolling_radius_m = 0;
  double load_n = 0;
  double friction = 1.0;
};
TireKinematics kinematics_of(const TireInput& in) {
  return {in.long_speed_mps, in.lat_speed_mps, in.spin_radps, in.rolling_radius_m};
}
SteadyStateForces steady(const TireInput& in, const TmeasyParams& p = default_215_55_r18()) {
  return steady_state_forces(p, kinematics_of(in), in.load_n, in.friction);
}
/// The law as a vehicle evaluates it: the characteristic at F_z and mu, f at the kinematics, the
/// deflection dynamics and the limited forces at deflection s.
struct Evaluation {
  TireCharacteristic characteristic;
  double f_per_slip = 0;
  double sliding_ratio = 1;
  DeflectionDynamics dynamics;
  TireForces forces;
};
Evaluation evaluate(const TireInput& in, const Eigen::Vector2d& s,
                    const TmeasyParams& p = default_215_55_r18()) {
  Evaluation e;
  e.characteristic = characteristic_at(p, in.load_n, in.friction);
  const TireSlip slip = slip_of(e.characteristic, kinematics_of(in), p.velocity_floor_mps);
  e.f_per_slip = slip.f_per_slip;
  e.sliding_ratio = slip.sliding_ratio;
  e.dynamics = deflection_dynamics(p, e.characteristic, kinematics_of(in), e.f_per_slip, s);
  e.forces = limited_forces(p, e.characteristic, e.sliding_ratio, s, e.dynamics);
  return e;
}

// Sets v_x for a prescribed longitudinal slip s_x = s_x^N s^x at spin w.
TireInput long_slip_input(double fz, double slip, double w) {
  const HandCurve x = hand_long(fz), y = hand_lat(fz);
  const double nx = hand_norm_x(x, y);
  TireInput in;
  in.spin_radps = w;
  in.rolling_radius_m = kR;
  in.load_n = fz;
  // eq. (14): s_x^N = -(v_x - r w)/(r |w| s^x + v_N) and s_x = s^x s_x^N
  in.long_speed_mps = kR * w - slip / nx * (kR * std::abs(w) * nx + kVn);
  return in;
}

TEST(TmeasySteadyState, LongitudinalCurveAtSeveralLoads) {
  for (double fz : {1750.0, 3500.0, 5250.0, 7000.0}) {
    const HandCurve h = hand_long(fz);
    for (double slip : {0.02, 0.08, h.sm, 0.5 * (h.sm + h.ss), h.ss, 0.8}) {
      for (double w : {40.0, -25.0}) {
        const SteadyStateForces f = steady(long_slip_input(fz, slip, w));
        const double expected = hand_curve(h.df0, h.fm, h.sm, h.fs, h.ss, slip);
        EXPECT_NEAR(f.long_force_n, expected, 1e-6 * h.fm) << "F_z " << fz << " s " << slip;
        EXPECT_NEAR(f.lat_force_n, 0.0, 1e-9);
      }
    }
    // the peak is F_xM from the parabola, and braking is symmetric
    EXPECT_NEAR(steady(long_slip_input(fz, h.sm, 30.0)).long_force_n, h.fm, 1e-6 * h.fm);
    EXPECT_NEAR(steady(long_slip_input(fz, -h.sm, 30.0)).long_force_n, -h.fm, 1e-6 * h.fm);
  }
  // a hand number: F_z = 5250 N (q = 1.5), s = s_xM = 0.13 gives F_xM = 5700 N
  EXPECT_NEAR(steady(long_slip_input(5250, 0.13, 30.0)).long_force_n, 5700.0, 1e-6);
}

TEST(TmeasySteadyState, LateralCurveAtSeveralLoads) {
  for (double fz : {1750.0, 3500.0, 7000.0}) {
    const HandCurve x = hand_long(fz), h = hand_lat(fz);
    const double ny = hand_norm_y(x, h);
    for (double slip : {0.03, h.sm, 0.4, 1.0}) {
      TireInput in;
      in.spin_radps = 50.0;
      in.rolling_radius_m = kR;
      in.long_speed_mps = kR * 50.0;  // free rolling
      in.load_n = fz;
      // eq. (15): s_y^N = -v_y/(r |w| s^y + v_N), s_y = s^y s_y^N
      in.lat_speed_mps = -slip / ny * (kR * 50.0 * ny + kVn);
      const SteadyStateForces f = steady(in);
      EXPECT_NEAR(f.lat_force_n, hand_curve(h.df0, h.fm, h.sm, h.fs, h.ss, slip), 1e-6 * h.fm);
      EXPECT_NEAR(f.long_force_n, 0.0, 1e-9);
    }
  }
}

TEST(TmeasySteadyState, CombinedSlipStaysInsideTheFrictionEllipse) {
  TireInput in = long_slip_input(3500, 0.1, 40.0);
  const double pure_x = steady(in).long_force_n;
  in.lat_speed_mps = -1.0;
  const SteadyStateForces f = steady(in);
  EXPECT_LT(f.long_force_n, pure_x);  // lateral slip takes longitudinal force away
  EXPECT_GT(f.lat_force_n, 0.0);
  EXPECT_LE(std::hypot(f.long_force_n, f.lat_force_n), 3900.0 * (1 + 1e-9));
  // generalized: F = f s, with F_x = f s_x^N (eq. 16), F_y = f s_y^N (eq. 17)
  EXPECT_NEAR(f.long_force_n, f.slip.f_per_slip * f.slip.slip_x, 1e-9);
  EXPECT_NEAR(f.lat_force_n, f.slip.f_per_slip * f.slip.slip_y, 1e-9);
}

TEST(TmeasyDynamics, StandStillHoldsDeflectionAndForce) {
  TireInput in;
  in.rolling_radius_m = kR;
  in.load_n = 3500;
  const Evaluation e = evaluate(in, {0.01, -0.005});
  // eq. (24) at v_x = 0, w = 0: x_e' = 0, so F_x = c_x x_e is held
  EXPECT_EQ(e.dynamics.x.rate, 0.0);
  EXPECT_EQ(e.dynamics.y.rate, 0.0);
  EXPECT_DOUBLE_EQ(e.forces.long_force_n, 250e3 * 0.01);
  EXPECT_DOUBLE_EQ(e.forces.lat_force_n, -175e3 * 0.005);
  EXPECT_FALSE(e.forces.limited);
  EXPECT_EQ(e.dynamics.x.d_rate_d_deflection, 0.0);  // no relaxation at rest
}

TEST(TmeasyDynamics, LockedWheelSlidesWithTheContactPoint) {
  TireInput in;
  in.rolling_radius_m = kR;
  in.load_n = 3500;
  in.long_speed_mps = 0.5;
  in.lat_speed_mps = -0.3;
  // the damping at v_x = 0.5 m/s: d_x plus half (weight (1 + cos(pi/2))/2) the low-speed
  // damping 2 zeta sqrt(c_x F_z/g) = 2 sqrt(250e3 * 3500 / 9.80665) = 18,891.6 N s/m
  const double d_x = 2000 + 0.5 * 2 * std::sqrt(250e3 * 3500 / 9.80665);
  EXPECT_NEAR(d_x, 11445.9, 0.1);
  for (double xe : {0.0, 0.005}) {
    const Evaluation e = evaluate(in, {xe, 0.0});
    EXPECT_NEAR(e.dynamics.x.rate, -0.5, 1e-12);  // eq. (25): x_e' = -v_x
    EXPECT_NEAR(e.dynamics.y.rate, 0.3, 1e-12);   // y_e' = -v_y
    EXPECT_NEAR(e.dynamics.damping.x_nspm, d_x, 1e-9);
    // eq. (22) c x_e + d x_e' = (250e3 x_e - 5723, 0 + 0.3 d_y) lies beyond the ellipse: limited
    EXPECT_TRUE(e.forces.limited);
  }
  // without the low-speed damping: the paper's d_x
  TmeasyParams bare = default_215_55_r18();
  bare.low_speed_damping_ratio = 0;
  EXPECT_NEAR(evaluate(in, {0.005, 0.0}, bare).forces.long_force_n, 250e3 * 0.005 - 2000 * 0.5,
              1e-9);
}

TEST(TmeasyDynamics, EllipticLimiterHoldsTheCombinedForceOnTheEllipse) {
  const TmeasyParams p = default_215_55_r18();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int limited = 0, sliding = 0;
  for (int i = 0; i < 20000; ++i) {
    TireInput in;
    in.rolling_radius_m = kR;
    in.load_n = 3500 + 3000 * u(rng);
    in.friction = 0.7 + 0.3 * u(rng);
    in.spin_radps = 60 * u(rng);
    in.long_speed_mps = in.spin_radps * kR + 5 * u(rng);
    in.lat_speed_mps = 3 * u(rng);
    const Eigen::Vector2d s(0.03 * u(rng), 0.03 * u(rng));
    const Evaluation e = evaluate(in, s);
    const double fxm = e.characteristic.x.max_force_n, fym = e.characteristic.y.max_force_n;
    const double rho = std::hypot(e.forces.long_force_n / fxm, e.forces.lat_force_n / fym);
    ASSERT_LE(rho, 1 + 1e-12);  // eq. (26): never outside the ellipse of the maxima
    ASSERT_LE(e.sliding_ratio, 1.0);
    if (e.forces.limited) {
      ++limited;
      // on the ellipse scaled by kappa = F(s)/F_M, in the direction of the dynamic force
      ASSERT_NEAR(rho, e.sliding_ratio, 1e-12);
      if (e.sliding_ratio < 1.0) ++sliding;
      const double fx = 250e3 * s(0) + e.dynamics.damping.x_nspm * e.dynamics.x.rate;
      const double fy = 175e3 * s(1) + e.dynamics.damping.y_nspm * e.dynamics.y.rate;
      ASSERT_NEAR(e.forces.long_force_n * fy - e.forces.lat_force_n * fx, 0.0,
                  1e-9 * std::hypot(fx, fy) * fxm);
    }
    // the state's clamp: the spring force within the same ellipse
    Eigen::Vector2d clamped = s;
    limit_deflection(p, e.characteristic, e.sliding_ratio, clamped);
    ASSERT_LE(std::hypot(250e3 * clamped(0) / fxm, 175e3 * clamped(1) / fym),
              e.sliding_ratio + 1e-12);
  }
  EXPECT_GT(limited, 1000);  // the sample does exercise the limiter
  EXPECT_GT(sliding, 100);   // ... and its sliding part
  // pure longitudinal slip: the paper's clamp. A deflection whose spring force exceeds
  // F_xM = 3900 N at 3500 N gives F = F_xM sign(x_e)
  TireInput rest;
  rest.rolling_radius_m = kR;
  rest.load_n = 3500;
  Evaluation e = evaluate(rest, {-0.02, 0.0});
  EXPECT_TRUE(e.forces.limited);
  EXPECT_DOUBLE_EQ(e.forces.long_force_n, -3900.0);
  // a wheel locked at 3 m/s (s_x = 3/v_N = 6, beyond s_S: full slide) with a small opposite
  // deflection: F^D = 250 - 6000 N is limited to the sliding force -F_xS = -0.9 F_xM = -3510 N
  // (the force keeps its direction; it does not flip to sign(x_e))
  rest.long_speed_mps = 3.0;
  e = evaluate(rest, {0.001, 0.0});
  EXPECT_TRUE(e.forces.limited);
  EXPECT_DOUBLE_EQ(e.sliding_ratio, 0.9);
  EXPECT_NEAR(e.forces.long_force_n, -3510.0, 1e-9);
  // the clamp of eq. (26) on the state: beyond both maxima, scaled back onto the ellipse along
  // its own direction (pure: |x_e| = F_xM/c_x)
  Eigen::Vector2d c(-0.02, 0.05);
  limit_deflection(p, e.characteristic, 1.0, c);
  EXPECT_NEAR(std::hypot(250e3 * c(0) / 3900.0, 175e3 * c(1) / 3650.0), 1.0, 1e-15);
  EXPECT_NEAR(c(1) / c(0), 0.05 / -0.02, 1e-12);
  Eigen::Vector2d pure(-0.02, 0.0);
  limit_deflection(p, e.characteristic, 1.0, pure);
  EXPECT_DOUBLE_EQ(pure(0), -3900.0 / 250e3);
  limit_deflection(p, e.characteristic, e.sliding_ratio, pure);  // sliding: |x_e| = F_xS/c_x
  EXPECT_DOUBLE_EQ(pure(0), -3510.0 / 250e3);
}

TEST(TmeasyDynamics, SteadyStateOfTheDeflectionDynamicsMatchesEq16UpToVn) {
  // x_e' = 0 in eq. (24): c_x x_e = -f (v_x - r w)/(r |w| s^x); eq. (16) has + v_N in the
  // denominator, so the ratio is (r |w| s^x + v_N)/(r |w| s^x).
  const TireInput in = long_slip_input(3500, 0.03, 80.0);
  Eigen::Vector2d s = Eigen::Vector2d::Zero();
  const double h = 1e-3;
  for (int k = 0; k < 2000; ++k) {  // implicit Euler in x_e (linear in x_e): converges
    const DirectionalDynamics x = evaluate(in, s).dynamics.x;
    s(0) += h * x.rate / (1 - h * x.d_rate_d_deflection);
  }
  const Evaluation e = evaluate(in, s);
  const HandCurve x = hand_long(3500), y = hand_lat(3500);
  const double nx = hand_norm_x(x, y);
  const double fs = steady(in).long_force_n;
  EXPECT_NEAR(e.forces.long_force_n, fs * (kR * 80 * nx + kVn) / (kR * 80 * nx),
              1e-6 * std::abs(fs));
}

/// Tire states for the partial-derivative tests (the last one limited).
struct PartialsCase {
  double vx, vy, w, fz, xe, ye;
};
constexpr PartialsCase kPartialsCases[] = {
    {20.0, 0.0, 70.0, 3500, 0.004, 0.0},      // driving, pure longitudinal
    {15.0, -0.8, 48.0, 4200, -0.003, 0.002},  // braking while cornering
    {5.0, 0.6, 17.5, 2600, 0.001, -0.004},    // combined, low speed
    {-3.0, 0.2, -9.0, 5200, -0.002, 0.001},   // reversing
    {0.05, 0.01, 0.1, 3500, 0.002, 0.001},    // near stand-still
    {3.0, 0.0, 0.0, 3500, 0.001, 0.0},        // locked and sliding: limited
};

// The partials the solver uses are those of eq. (24) at frozen f (the stiff damping path,
// method.md sec. 6): central differences with f held fixed must give them exactly.
TEST(TmeasyDynamics, PartialsAtFrozenFMatchFiniteDifferences) {
  // the low-speed damping's weight moves with v_x and is frozen like f: off here, and its
  // damping path checked by hand below
  TmeasyParams p = default_215_55_r18();
  p.low_speed_damping_ratio = 0;
  for (const PartialsCase& c : kPartialsCases) {
    const TireInput in{c.vx, c.vy, c.w, kR, c.fz, 1.0};
    const Evaluation e = evaluate(in, {c.xe, c.ye}, p);
    if (e.forces.limited) continue;  // the frozen-f paths of the unlimited force
    const TireKinematics k = kinematics_of(in);
    const auto at = [&](TireKinematics kk, Eigen::Vector2d s) {
      return deflection_dynamics(p, e.characteristic, kk, e.f_per_slip, s);
    };
    const auto force_x = [&](TireKinematics kk) {
      const DeflectionDynamics d = at(kk, {c.xe, c.ye});
      return 250e3 * c.xe + 2000 * d.x.rate;
    };
    const auto force_y = [&](TireKinematics kk) {
      const DeflectionDynamics d = at(kk, {c.xe, c.ye});
      return 175e3 * c.ye + 1750 * d.y.rate;
    };
    const double dv = 1e-6, dxe = 1e-9;
    TireKinematics kp = k, km = k;
    kp.long_speed_mps += dv;
    km.long_speed_mps -= dv;
    EXPECT_NEAR(-(force_x(kp) - force_x(km)) / (2 * dv), e.dynamics.x.damping_nspm,
                1e-6 * e.dynamics.x.damping_nspm);
    kp = k;
    km = k;
    kp.lat_speed_mps += dv;
    km.lat_speed_mps -= dv;
    EXPECT_NEAR(-(force_y(kp) - force_y(km)) / (2 * dv), e.dynamics.y.damping_nspm,
                1e-6 * e.dynamics.y.damping_nspm);
    const double fd_rate =
        (at(k, {c.xe + dxe, c.ye}).x.rate - at(k, {c.xe - dxe, c.ye}).x.rate) / (2 * dxe);
    EXPECT_NEAR(fd_rate, e.dynamics.x.d_rate_d_deflection,
                1e-5 * (1 + std::abs(e.dynamics.x.d_rate_d_deflection)));
    // the spin stage's dF_x/dw = r dF_x/dv_slip, and damping_paths() gives the same paths
    const SpinForce sf = spin_force(
        p, TireContact{e.characteristic, k, e.f_per_slip, e.sliding_ratio}, {c.xe, c.ye});
    EXPECT_DOUBLE_EQ(sf.d_force_d_spin, e.dynamics.x.damping_nspm * kR);
    EXPECT_DOUBLE_EQ(sf.long_force_n, e.forces.long_force_n);
    const DampingPaths paths = damping_paths(p, e.characteristic, k, e.f_per_slip);
    EXPECT_EQ(paths.long_nspm, e.dynamics.x.damping_nspm);
    EXPECT_EQ(paths.lat_nspm, e.dynamics.y.damping_nspm);
  }
  // with the low-speed damping near stand-still (v_x = 0.05 m/s, w = 0.1 rad/s): the path is
  // d f / (d r|w| s^x + f) with d = d_x + w_low d_low, w_low = (1 + cos(0.05 pi))/2
  const TmeasyParams q = default_215_55_r18();
  const TireInput in{0.05, 0.01, 0.1, kR, 3500, 1.0};
  const Evaluation e = evaluate(in, {0.002, 0.001}, q);
  const double d =
      2000 + 0.5 * (1 + std::cos(0.05 * 3.14159265358979)) * 2 * std::sqrt(250e3 * 3500 / 9.80665);
  const double rs = kR * 0.1 * e.characteristic.normalize_x;
  EXPECT_NEAR(e.dynamics.damping.x_nspm, d, 1e-6);
  EXPECT_NEAR(e.dynamics.x.damping_nspm, d * e.f_per_slip / (d * rs + e.f_per_slip), 1e-6);
}

// The complete partials (f moving with the slip, the limiter included) against central
// differences of the limited forces.
TEST(TmeasyDynamics, CompletePartialsMatchFiniteDifferences) {
  const TmeasyParams p = default_215_55_r18();
  for (const PartialsCase& c : kPartialsCases) {
    const TireCharacteristic ch = characteristic_at(p, c.fz, 1.0);
    const Eigen::Vector2d s(c.xe, c.ye);
    const TireKinematics k{c.vx, c.vy, c.w, kR};
    const auto forces = [&](TireKinematics kk) {
      const TireForces t = tire_forces(p, ch, kk, slip_of(ch, kk, p.velocity_floor_mps), s);
      return Eigen::Vector2d(t.long_force_n, t.lat_force_n);
    };
    const TireForcePartials a = tire_force_partials(p, ch, k, s);
    for (int j = 0; j < 3; ++j) {
      const double e = 1e-6;
      TireKinematics kp = k, km = k;
      double* ps[3] = {&kp.long_speed_mps, &kp.lat_speed_mps, &kp.spin_radps};
      double* ms[3] = {&km.long_speed_mps, &km.lat_speed_mps, &km.spin_radps};
      *ps[j] += e;
      *ms[j] -= e;
      const Eigen::Vector2d fd = (forces(kp) - forces(km)) / (2 * e);
      EXPECT_NEAR(a.d_force(0, j), fd(0), 1e-5 * (1 + std::abs(fd(0)))) << c.vx << " col " << j;
      EXPECT_NEAR(a.d_force(1, j), fd(1), 1e-5 * (1 + std::abs(fd(1)))) << c.vx << " col " << j;
    }
  }
}

TEST(TmeasyDynamics, LiftOffGivesNoForceAndNoDeflection) {
  const TmeasyParams p = default_215_55_r18();
  for (double fz : {0.0, -100.0}) {
    TireInput in;
    in.long_speed_mps = 10;
    in.spin_radps = 20;
    in.rolling_radius_m = kR;
    in.load_n = fz;
    const Evaluation e = evaluate(in, {0.004, -0.002});
    EXPECT_EQ(e.characteristic.x.max_force_n, 0.0);
    EXPECT_EQ(e.f_per_slip, 0.0);
    EXPECT_EQ(e.forces.long_force_n, 0.0);
    EXPECT_EQ(e.forces.lat_force_n, 0.0);
    EXPECT_TRUE(e.forces.limited);
    // f = 0: the free spring-damper relaxes, c x_e + d x_e' = 0 (up to the 1e-9 guard)
    EXPECT_NEAR(e.dynamics.x.rate, -250e3 / 2000 * 0.004, 1e-12);
    EXPECT_NEAR(e.dynamics.y.rate, 175e3 / 1750 * 0.002, 1e-12);
    // and the state's clamp empties it at once: no capacity, no deflection
    Eigen::Vector2d s(0.004, -0.002);
    limit_deflection(p, e.characteristic, 1.0, s);
    EXPECT_EQ(s, Eigen::Vector2d::Zero());
    EXPECT_EQ(steady(in).long_force_n, 0.0);
  }
}

TEST(TmeasyTorques, AligningTorqueFromPneumaticTrailAndRollingResistance) {
  const TmeasyParams p = default_215_55_r18();
  TireInput in;
  in.long_speed_mps = 20;
  in.spin_radps = 20 / kR;
  in.rolling_radius_m = kR;
  in.load_n = 3500;
  in.lat_speed_mps = -0.2;  // small lateral slip: trail near n0, M_z restores (opposes F_y)
  const Evaluation e = evaluate(in, {0.0, 0.005});
  ASSERT_GT(e.forces.lat_force_n, 0.0);
  const double s_y = 0.2 / (20 + 0.5);
  const double l = std::sqrt(8 * 0.3469 * 3500 / 200e3);  // contact length
  const double x = s_y / 0.4, w = 0.4 / 0.6;              // TMeasy trail, first segment
  const double n = 0.178 * ((1 - w) * (1 - x) + w * (1 - (3 - 2 * x) * x * x)) * l;
  EXPECT_NEAR(aligning_torque_nm(p, kinematics_of(in), 3500, e.forces.lat_force_n),
              -n * e.forces.lat_force_n, 1e-9);
  // rolling resistance: the dry-friction torque f_r r F_z that holds a wheel like a brake
  EXPECT_DOUBLE_EQ(rolling_resistance_torque_nm(p, 3500, kR), 0.01 * kR * 3500);
  // large lateral slip beyond s_yE: no trail
  in.lat_speed_mps = -15;
  EXPECT_EQ(aligning_torque_nm(p, kinematics_of(in), 3500, 1000.0), 0.0);
}

TEST(VerticalTire, ForceWithLiftOffAndRollingRadius) {
  const VerticalForce f = vertical_tire_force(200e3, 50, 0.0175, 0.01);
  EXPECT_DOUBLE_EQ(f.force_n, 3500.5);
  EXPECT_EQ(f.d_force_d_deflection, 200e3);
  EXPECT_EQ(f.d_force_d_rate, 50);
  EXPECT_TRUE(f.in_contact);
  const VerticalForce off = vertical_tire_force(200e3, 50, -0.001, 0.0);
  EXPECT_EQ(off.force_n, 0.0);
  EXPECT_EQ(off.d_force_d_deflection, 0.0);
  EXPECT_FALSE(vertical_tire_force(200e3, 5000, 0.001, -1.0).in_contact);  // rebounding fast
  // r_D = 2/3 r_0 + 1/3 r_S, r_S = r_0 - dz (dz = F_z/c_z = 17.5 mm at 3500 N)
  EXPECT_DOUBLE_EQ(dynamic_rolling_radius(0.3469, 0.0175),
                   2.0 / 3 * 0.3469 + (0.3469 - 0.0175) / 3);
  EXPECT_DOUBLE_EQ(dynamic_rolling_radius(0.3469, -0.001), 0.3469);  // lifted off
}

TEST(TmeasyTire, EvaluationAllocatesNothing) {
  TireInput in = long_slip_input(3500, 0.05, 30.0);
  in.lat_speed_mps = 0.3;
  double sum = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 1000; ++i) {
    in.load_n = 2000 + i;
    sum += evaluate(in, {1e-4 * i, 0.0}).forces.long_force_n + steady(in).lat_force_n;
  }
  const auto allocations = counter.count();
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(allocations, 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::tire

// The one tire law as a solver force element (tmeasy_force_element.h), advanced by the solver's
// eq. (8) force-element stepper.
#include "model/solver/finite_difference.h"
#include "model/solver/force_element_stepper.h"
#include "model/tire/tmeasy_force_element.h"

namespace rig::model::tire {
namespace {

constexpr double kRadius = 0.3;

/// A contact at rest or sliding: the characteristic at F_z and mu, f of the kinematics.
TireContact contact_at(const TmeasyParams& p, double load_n, const TireKinematics& k) {
  TireContact c;
  c.characteristic = characteristic_at(p, load_n, 1.0);
  c.kinematics = k;
  const TireSlip slip = slip_of(c.characteristic, k, p.velocity_floor_mps);
  c.f_per_slip = slip.f_per_slip;
  c.sliding_ratio = slip.sliding_ratio;
  return c;
}

TEST(TmeasyForceElement, StepperHoldsAtRestAndFollowsALockedWheel) {
  const TmeasyParams p = default_215_55_r18();
  TireContact contact = contact_at(p, 3500.0, {0.0, 0.0, 0.0, kRadius});
  Eigen::Vector2d s(0.01, -0.004);
  TmeasyForceElement element(p, contact, s);
  solver::ForceElementStepper<2> stepper(element);
  Eigen::internal::set_is_malloc_allowed(false);
  const rig::test::AllocationCounter counter;
  for (int k = 0; k < 1000; ++k) stepper.advance(1e-3);  // stand-still: held (eq. 24)
  const auto allocations = counter.count();
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(allocations, 0u);
  EXPECT_EQ(s(0), 0.01);
  EXPECT_EQ(s(1), -0.004);
  const TireForces held = tire_forces(p, contact.characteristic, contact.kinematics, contact, s);
  EXPECT_DOUBLE_EQ(held.long_force_n, 2500.0);
  EXPECT_DOUBLE_EQ(held.lat_force_n, -700.0);
  EXPECT_FALSE(held.limited);
  // locked wheel sliding at 0.15 m/s: x_e' = -v_x (eq. 25) until the spring force reaches
  // F(s) = kappa F_xM at the slip s_x^N = 0.15/v_N = 0.3 (between s_M and s_S: the characteristic
  // from its pieces), where eq. (26) holds it; the force c_x x_e + d_x x_e' = -F(s) - 300 N is
  // limited to -F(s)
  contact = contact_at(p, 3500.0, {0.15, 0.0, 0.0, kRadius});
  const TmeasyCurve& cx = contact.characteristic.x;
  const double slip_n = 0.15 / p.velocity_floor_mps;  // s_x^N; phi = 0: s_M -> s_xM / s^x
  TmeasyCurve generalized = cx;
  generalized.initial_slope_n *= contact.characteristic.normalize_x;
  generalized.max_slip /= contact.characteristic.normalize_x;
  generalized.slide_slip /= contact.characteristic.normalize_x;
  ASSERT_GT(slip_n, generalized.max_slip);
  ASSERT_LT(slip_n, generalized.slide_slip);
  const double f_sliding = evaluate_characteristic(generalized, slip_n).force_n;
  EXPECT_NEAR(contact.sliding_ratio, f_sliding / 3900.0, 1e-12);
  EXPECT_LT(f_sliding, 3900.0);
  EXPECT_GT(f_sliding, 3510.0);
  s.setZero();
  for (int k = 0; k < 10; ++k) stepper.advance(1e-3);
  EXPECT_NEAR(s(0), -0.0015, 1e-12);
  for (int k = 0; k < 200; ++k) stepper.advance(1e-3);
  EXPECT_NEAR(s(0), -f_sliding / 250e3, 1e-12);
  const TireForces sliding = tire_forces(p, contact.characteristic, contact.kinematics, contact, s);
  EXPECT_TRUE(sliding.limited);
  EXPECT_NEAR(sliding.long_force_n, -f_sliding, 1e-9);
}

TEST(TmeasyForceElement, RateJacobianMatchesFiniteDifferences) {
  const TmeasyParams p = default_215_55_r18();
  const TireContact contact = contact_at(p, 3000.0, {12.0, 0.4, 38.0, kRadius});
  Eigen::Vector2d s(0.001, -0.002);
  TmeasyForceElement element(p, contact, s);
  Eigen::Matrix2d analytic, fd;
  ASSERT_TRUE(element.rate_jacobian(s, analytic));
  Eigen::Vector2d work, f0, f1;
  solver::finite_difference_rate_jacobian<2>(element, s, fd, work, f0, f1);
  EXPECT_NEAR((analytic - fd).norm(), 0.0, 1e-4 * analytic.norm());
  // by hand, eq. (24): d x_e'/d x_e = -c_x r|w| s^x / (d_x r|w| s^x + f)
  const double a = kRadius * 38.0 * contact.characteristic.normalize_x;
  EXPECT_NEAR(analytic(0, 0), -250e3 * a / (2000 * a + contact.f_per_slip), 1e-9);
  EXPECT_EQ(analytic(0, 1), 0.0);
}

}  // namespace
}  // namespace rig::model::tire
