// TMeasy tire acceptance tests (issue 3, item 3): steady-state curves against hand computations,
// stand-still hold (eq. 24), locked wheel (eq. 25), limiter (eq. 26), analytic partials against
// finite differences, lift-off, zero allocation.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "model/tire/tmeasy_characteristic.h"
#include "model/tire/tmeasy_dual_law.h"
#include "model/tire/vertical_tire_force.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::tire::legacy {
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
  const TmeasyTire tire;
  for (double fz : {1750.0, 3500.0, 5250.0, 7000.0}) {
    const HandCurve h = hand_long(fz);
    for (double slip : {0.02, 0.08, h.sm, 0.5 * (h.sm + h.ss), h.ss, 0.8}) {
      for (double w : {40.0, -25.0}) {
        const SteadyStateForces f = tire.steady_state(long_slip_input(fz, slip, w));
        const double expected = hand_curve(h.df0, h.fm, h.sm, h.fs, h.ss, slip);
        EXPECT_NEAR(f.long_force_n, expected, 1e-6 * h.fm) << "F_z " << fz << " s " << slip;
        EXPECT_NEAR(f.lat_force_n, 0.0, 1e-9);
      }
    }
    // the peak is F_xM from the parabola, and braking is symmetric
    EXPECT_NEAR(tire.steady_state(long_slip_input(fz, h.sm, 30.0)).long_force_n, h.fm, 1e-6 * h.fm);
    EXPECT_NEAR(tire.steady_state(long_slip_input(fz, -h.sm, 30.0)).long_force_n, -h.fm,
                1e-6 * h.fm);
  }
  // a hand number: F_z = 5250 N (q = 1.5), s = s_xM = 0.13 gives F_xM = 5700 N
  EXPECT_NEAR(tire.steady_state(long_slip_input(5250, 0.13, 30.0)).long_force_n, 5700.0, 1e-6);
}

TEST(TmeasySteadyState, LateralCurveAtSeveralLoads) {
  const TmeasyTire tire;
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
      const SteadyStateForces f = tire.steady_state(in);
      EXPECT_NEAR(f.lat_force_n, hand_curve(h.df0, h.fm, h.sm, h.fs, h.ss, slip), 1e-6 * h.fm);
      EXPECT_NEAR(f.long_force_n, 0.0, 1e-9);
    }
  }
}

TEST(TmeasySteadyState, CombinedSlipStaysInsideTheFrictionEllipse) {
  const TmeasyTire tire;
  TireInput in = long_slip_input(3500, 0.1, 40.0);
  const double pure_x = tire.steady_state(in).long_force_n;
  in.lat_speed_mps = -1.0;
  const SteadyStateForces f = tire.steady_state(in);
  EXPECT_LT(f.long_force_n, pure_x);  // lateral slip takes longitudinal force away
  EXPECT_GT(f.lat_force_n, 0.0);
  EXPECT_LE(std::hypot(f.long_force_n, f.lat_force_n), 3900.0 * (1 + 1e-9));
  // generalized: F = f s, with F_x = f s_x^N (eq. 16), F_y = f s_y^N (eq. 17)
  EXPECT_NEAR(f.long_force_n, f.f_n * f.long_slip_normalized, 1e-9);
  EXPECT_NEAR(f.lat_force_n, f.f_n * f.lat_slip_normalized, 1e-9);
}

TEST(TmeasyDynamics, StandStillHoldsDeflectionAndForce) {
  const TmeasyTire tire;
  TireInput in;
  in.rolling_radius_m = kR;
  in.load_n = 3500;
  const TireDeflection d{0.01, -0.005};
  TireOutput out;
  tire.evaluate(in, d, out);
  // eq. (24) at v_x = 0, w = 0: x_e' = 0, so F_x = c_x x_e is held
  EXPECT_EQ(out.deflection_rate(0), 0.0);
  EXPECT_EQ(out.deflection_rate(1), 0.0);
  EXPECT_DOUBLE_EQ(out.long_force_n, 250e3 * 0.01);
  EXPECT_DOUBLE_EQ(out.lat_force_n, -175e3 * 0.005);
  EXPECT_FALSE(out.long_limited);
  EXPECT_EQ(out.d_rate_d_deflection(0), 0.0);  // no relaxation at rest
}

TEST(TmeasyDynamics, LockedWheelSlidesWithTheContactPoint) {
  const TmeasyTire tire;
  TireInput in;
  in.rolling_radius_m = kR;
  in.load_n = 3500;
  in.long_speed_mps = 0.5;
  in.lat_speed_mps = -0.3;
  for (double xe : {0.0, 0.005}) {
    TireOutput out;
    tire.evaluate(in, {xe, 0.0}, out);
    EXPECT_NEAR(out.deflection_rate(0), -0.5, 1e-12);              // eq. (25): x_e' = -v_x
    EXPECT_NEAR(out.deflection_rate(1), 0.3, 1e-12);               // y_e' = -v_y
    EXPECT_NEAR(out.long_force_n, 250e3 * xe - 2000 * 0.5, 1e-9);  // eq. (22)
  }
}

TEST(TmeasyDynamics, LimiterHoldsForcesBelowTheirMaxima) {
  const TmeasyTire tire;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int limited = 0;
  for (int i = 0; i < 20000; ++i) {
    TireInput in;
    in.rolling_radius_m = kR;
    in.load_n = 3500 + 3000 * u(rng);
    in.friction = 0.7 + 0.3 * u(rng);
    in.spin_radps = 60 * u(rng);
    in.long_speed_mps = in.spin_radps * kR + 5 * u(rng);
    in.lat_speed_mps = 3 * u(rng);
    const TireDeflection d{0.03 * u(rng), 0.03 * u(rng)};
    TireOutput out;
    tire.evaluate(in, d, out);
    const double fxm = tire.max_long_force_n(in.load_n, in.friction);
    const double fym = tire.max_lat_force_n(in.load_n, in.friction);
    ASSERT_LE(std::abs(out.long_force_n), fxm * (1 + 1e-12));
    ASSERT_LE(std::abs(out.lat_force_n), fym * (1 + 1e-12));
    if (out.long_limited) {
      ++limited;
      ASSERT_EQ(out.deflection_rate(0), 0.0);  // eq. (26): x_e' = 0
      ASSERT_NEAR(std::abs(out.long_force_n), fxm, 1e-12 * fxm);
    }
  }
  EXPECT_GT(limited, 1000);  // the sample does exercise the limiter
  // a deflection whose spring force exceeds F_xM = 3900 N at 3500 N: F = F_xM sign(x_e)
  TireInput rest;
  rest.rolling_radius_m = kR;
  rest.load_n = 3500;
  TireOutput out;
  tire.evaluate(rest, {-0.02, 0.0}, out);
  EXPECT_TRUE(out.long_limited);
  EXPECT_DOUBLE_EQ(out.long_force_n, -3900.0);
  // a wheel locking at 3 m/s with a small opposite deflection: F^D = 250 - 6000 N is limited
  // to -F_xM (the force keeps its direction; it does not flip to sign(x_e))
  rest.long_speed_mps = 3.0;
  tire.evaluate(rest, {0.001, 0.0}, out);
  EXPECT_TRUE(out.long_limited);
  EXPECT_DOUBLE_EQ(out.long_force_n, -3900.0);
  EXPECT_EQ(out.deflection_rate(0), 0.0);
  TireDeflection c{-0.02, 0.05};
  tire.clamp_deflection(3500, 1.0, c);
  EXPECT_DOUBLE_EQ(c.long_m, -3900.0 / 250e3);
  EXPECT_DOUBLE_EQ(c.lat_m, 3650.0 / 175e3);
}

TEST(TmeasyDynamics, SteadyStateOfTheDeflectionDynamicsMatchesEq16UpToVn) {
  // x_e' = 0 in eq. (24): c_x x_e = -f (v_x - r w)/(r |w| s^x); eq. (16) has + v_N in the
  // denominator, so the ratio is (r |w| s^x + v_N)/(r |w| s^x).
  const TmeasyTire tire;
  const TireInput in = long_slip_input(3500, 0.03, 80.0);
  TireDeflection d{};
  TireOutput out;
  const double h = 1e-3;
  for (int k = 0; k < 2000; ++k) {  // implicit Euler in x_e (linear in x_e): converges
    tire.evaluate(in, d, out);
    d.long_m += h * out.deflection_rate(0) / (1 - h * out.d_rate_d_deflection(0));
  }
  tire.evaluate(in, d, out);
  const HandCurve x = hand_long(3500), y = hand_lat(3500);
  const double nx = hand_norm_x(x, y);
  const double fs = tire.steady_state(in).long_force_n;
  EXPECT_NEAR(out.long_force_n, fs * (kR * 80 * nx + kVn) / (kR * 80 * nx), 1e-6 * std::abs(fs));
}

// Central differences of the outputs by one input.
TireOutput eval(const TmeasyTire& t, TireInput in, TireDeflection d) {
  TireOutput o;
  t.evaluate(in, d, o);
  return o;
}

TEST(TmeasyDynamics, AnalyticPartialsMatchFiniteDifferences) {
  const TmeasyTire tire;
  struct Case {
    double vx, vy, w, fz, xe, ye;
  };
  const Case cases[] = {
      {20.0, 0.0, 70.0, 3500, 0.004, 0.0},      // driving, pure longitudinal
      {15.0, -0.8, 48.0, 4200, -0.003, 0.002},  // braking while cornering
      {5.0, 0.6, 17.5, 2600, 0.001, -0.004},    // combined, low speed
      {-3.0, 0.2, -9.0, 5200, -0.002, 0.001},   // reversing
      {0.05, 0.01, 0.1, 3500, 0.002, 0.001},    // near stand-still
  };
  for (const Case& c : cases) {
    TireInput in;
    in.long_speed_mps = c.vx;
    in.lat_speed_mps = c.vy;
    in.spin_radps = c.w;
    in.rolling_radius_m = kR;
    in.load_n = c.fz;
    const TireDeflection d{c.xe, c.ye};
    const TireOutput o = eval(tire, in, d);
    ASSERT_FALSE(o.long_limited || o.lat_limited);
    for (int j = 0; j < kTirePartialCount; ++j) {
      const double step[] = {1e-6, 1e-6, 1e-6, 1e-3, 1e-9, 1e-9};
      TireInput ip = in, im = in;
      TireDeflection dp = d, dm = d;
      auto bump = [&](TireInput& i, TireDeflection& dd, double e) {
        if (j == kByLongSpeed) i.long_speed_mps += e;
        if (j == kByLatSpeed) i.lat_speed_mps += e;
        if (j == kBySpin) i.spin_radps += e;
        if (j == kByLoad) i.load_n += e;
        if (j == kByLongDeflection) dd.long_m += e;
        if (j == kByLatDeflection) dd.lat_m += e;
      };
      bump(ip, dp, step[j]);
      bump(im, dm, -step[j]);
      const TireOutput op = eval(tire, ip, dp), om = eval(tire, im, dm);
      const double fd_fx = (op.long_force_n - om.long_force_n) / (2 * step[j]);
      const double fd_fy = (op.lat_force_n - om.lat_force_n) / (2 * step[j]);
      const double fd_rx = (op.deflection_rate(0) - om.deflection_rate(0)) / (2 * step[j]);
      const double fd_ry = (op.deflection_rate(1) - om.deflection_rate(1)) / (2 * step[j]);
      const double tol_f =
          1e-5 * (1 + std::abs(fd_fx)) + 1e-5 * o.d_force.row(0).cwiseAbs().maxCoeff() * 1e-3;
      EXPECT_NEAR(o.d_force(0, j), fd_fx, tol_f) << "dFx/d" << j << " vx " << c.vx;
      EXPECT_NEAR(o.d_force(1, j), fd_fy, 1e-5 * (1 + std::abs(fd_fy))) << "dFy/d" << j;
      EXPECT_NEAR(o.d_rate(0, j), fd_rx, 1e-5 * (1 + std::abs(fd_rx))) << "dxe'/d" << j;
      EXPECT_NEAR(o.d_rate(1, j), fd_ry, 1e-5 * (1 + std::abs(fd_ry))) << "dye'/d" << j;
    }
    EXPECT_EQ(o.d_rate_d_deflection(0), o.d_rate(0, kByLongDeflection));
    EXPECT_EQ(o.d_rate_d_deflection(1), o.d_rate(1, kByLatDeflection));
    // the stiff damping path of M_VI: dF_x/dv_x is the damper d_x times dx_e'/dv_x
    EXPECT_NEAR(o.d_force(0, kByLongSpeed), 2000.0 * o.d_rate(0, kByLongSpeed), 1e-9);
    // rolling resistance torque derivative
    TireInput wp = in, wm = in;
    wp.spin_radps += 1e-6;
    wm.spin_radps -= 1e-6;
    const double fd_t =
        (eval(tire, wp, d).rolling_torque_nm - eval(tire, wm, d).rolling_torque_nm) / 2e-6;
    EXPECT_NEAR(o.d_rolling_torque_d_spin, fd_t, 1e-5 * (1 + std::abs(fd_t)));
  }
}

TEST(TmeasyDynamics, LiftOffGivesNoForceAndRelaxes) {
  const TmeasyTire tire;
  for (double fz : {0.0, -100.0}) {
    TireInput in;
    in.long_speed_mps = 10;
    in.spin_radps = 20;
    in.rolling_radius_m = kR;
    in.load_n = fz;
    TireOutput out;
    tire.evaluate(in, {0.004, -0.002}, out);
    EXPECT_TRUE(out.lifted_off);
    EXPECT_EQ(out.long_force_n, 0.0);
    EXPECT_EQ(out.lat_force_n, 0.0);
    EXPECT_EQ(out.aligning_torque_nm, 0.0);
    EXPECT_DOUBLE_EQ(out.deflection_rate(0), -250e3 / 2000 * 0.004);  // c x_e + d x_e' = 0
    EXPECT_DOUBLE_EQ(out.deflection_rate(1), 175e3 / 1750 * 0.002);
    EXPECT_DOUBLE_EQ(out.d_rate_d_deflection(0), -125.0);
    EXPECT_EQ(tire.steady_state(in).long_force_n, 0.0);
  }
}

TEST(TmeasyTorques, AligningTorqueFromPneumaticTrailAndRollingResistance) {
  const TmeasyTire tire;
  TireInput in;
  in.long_speed_mps = 20;
  in.spin_radps = 20 / kR;
  in.rolling_radius_m = kR;
  in.load_n = 3500;
  in.lat_speed_mps = -0.2;  // small lateral slip: trail near n0, M_z restores (opposes F_y)
  TireOutput out;
  tire.evaluate(in, {0.0, 0.005}, out);
  ASSERT_GT(out.lat_force_n, 0.0);
  const double s_y = 0.2 / (20 + 0.5);
  const double l = std::sqrt(8 * 0.3469 * 3500 / 200e3);  // contact length
  const double x = s_y / 0.4, w = 0.4 / 0.6;              // TMeasy trail, first segment
  const double n = 0.178 * ((1 - w) * (1 - x) + w * (1 - (3 - 2 * x) * x * x)) * l;
  EXPECT_NEAR(out.aligning_torque_nm, -n * out.lat_force_n, 1e-9);
  // rolling resistance opposes the spin: -f_r F_z r v/(|v| + v_N), v = r w
  EXPECT_NEAR(out.rolling_torque_nm, -0.01 * 3500 * kR * 20 / 20.5, 1e-9);
  // large lateral slip beyond s_yE: no trail
  in.lat_speed_mps = -15;
  tire.evaluate(in, {0.0, 0.0}, out);
  EXPECT_EQ(out.aligning_torque_nm, 0.0);
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
  const TmeasyTire tire;
  TireInput in = long_slip_input(3500, 0.05, 30.0);
  in.lat_speed_mps = 0.3;
  TireOutput out;
  double sum = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  const rig::test::AllocationCounter counter;
  for (int i = 0; i < 1000; ++i) {
    in.load_n = 2000 + i;
    tire.evaluate(in, {1e-4 * i, 0.0}, out);
    sum += out.long_force_n + tire.steady_state(in).lat_force_n;
  }
  const auto allocations = counter.count();
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(allocations, 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace rig::model::tire::legacy

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
  c.f_per_slip = slip_of(c.characteristic, k, p.velocity_floor_mps).f_per_slip;
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
  const TireForces held =
      tire_forces(p, contact.characteristic, contact.kinematics, contact.f_per_slip, s);
  EXPECT_DOUBLE_EQ(held.long_force_n, 2500.0);
  EXPECT_DOUBLE_EQ(held.lat_force_n, -700.0);
  EXPECT_FALSE(held.limited);
  // locked wheel sliding at 0.2 m/s: x_e' = -v_x (eq. 25) until the spring force reaches
  // F_xM = 3900 N at 3500 N, i.e. x_e = -F_xM/c_x = -0.0156 m, where eq. (26) holds it; the
  // force c_x x_e + d_x x_e' = -3900 - 400 N is limited to -F_xM
  contact = contact_at(p, 3500.0, {0.2, 0.0, 0.0, kRadius});
  s.setZero();
  for (int k = 0; k < 10; ++k) stepper.advance(1e-3);
  EXPECT_NEAR(s(0), -0.002, 1e-12);
  for (int k = 0; k < 200; ++k) stepper.advance(1e-3);
  EXPECT_NEAR(s(0), -3900.0 / 250e3, 1e-12);
  const TireForces sliding =
      tire_forces(p, contact.characteristic, contact.kinematics, contact.f_per_slip, s);
  EXPECT_TRUE(sliding.limited);
  EXPECT_NEAR(sliding.long_force_n, -3900.0, 1e-9);
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
