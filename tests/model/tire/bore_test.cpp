// The bore torque element alone (issue 15, item 3; model/tire/tmeasy_bore.h): slope c_B at
// stand-still, the limit (2/3) R_P mu F_z, the hysteresis of a reversed twist and the fade with
// the rolling speed, against hand values from the parameters.
#include <cmath>
#include <cstdio>
#include <utility>

#include <gtest/gtest.h>

#include "model/tire/tmeasy_bore.h"

namespace rig::model::tire {
namespace {

constexpr double kLoadN = 4000, kMu = 1.0, kH = 1e-3;

TmeasyParams bore_tire() {
  TmeasyParams p = default_215_55_r18();
  p.radius_unloaded_m = 0.316;
  p.vertical_stiffness_npm = 200e3;
  p.bore = {true, 2000.0, 5.0, 0.2};
  return p;
}

// by hand: L = sqrt(8 * 0.316 * 4000 / 200e3) = 0.22487 m, R_P = (L/2 + B/2)/2 = 0.10622 m,
// M_B,max = 2/3 R_P mu F_z = 283.24 N m
const double kLengthM = std::sqrt(8 * 0.316 * 4000 / 200e3);
const double kMaxNm = 2.0 / 3.0 * (kLengthM / 2 + 0.2 / 2) / 2 * kMu * kLoadN;

TEST(BoreTorque, LimitFromThePatch) {
  const TmeasyParams p = bore_tire();
  EXPECT_NEAR(contact_length_m(p, kLoadN), 0.22486, 1e-5);
  EXPECT_NEAR(kMaxNm, 283.24, 0.01);
  EXPECT_NEAR(bore_radius_m(p, kLoadN), (kLengthM / 2 + 0.1) / 2, 1e-6);
  EXPECT_NEAR(bore_torque_max_nm(p, kLoadN, kMu), kMaxNm, 0.01);
  EXPECT_NEAR(bore_torque_max_nm(p, kLoadN, 0.5), 0.5 * kMaxNm, 0.01);
  TmeasyParams off = p;
  off.bore.enabled = false;
  const BoreStep none = bore_step(off, 0.1, 1.0, 0.0, kLoadN, kMu, kH);
  EXPECT_EQ(none.torque_nm, 0.0);
  EXPECT_EQ(bore_step(p, 0.1, 1.0, 0.0, 0.0, kMu, kH).torque_nm, 0.0);  // lifted off
}

// A slow twist at stand-still: M = -(c_B phi + d_B omega) up to the limit, then held at -M_max;
// reversed, the torque walks to +M_max over a turn of 2 M_max / c_B: a loop of width 2 M_max.
TEST(BoreTorque, StandStillSlopeLimitAndHysteresis) {
  const TmeasyParams p = bore_tire();
  const double rate = 0.05;  // rad/s
  double phi = 0, angle = 0, torque = 0;
  int saturated_at = -1;
  for (int k = 1; k <= 8000; ++k) {  // 0.4 rad forwards (the limit at 0.14 rad)
    const BoreStep s = bore_step(p, phi, rate, 0.0, kLoadN, kMu, kH);
    phi = s.twist_rad;
    angle += rate * kH;
    torque = s.torque_nm;
    if (saturated_at < 0 && std::abs(torque) >= kMaxNm - 0.01) saturated_at = k;
    if (saturated_at < 0) {
      EXPECT_NEAR(torque, -(2000.0 * angle + 5.0 * rate), 1e-6) << k;
      EXPECT_NEAR(s.stiffness_nmprad, 2000.0 + 5.0 / kH, 1e-9);
    }
  }
  const double limit_angle = (kMaxNm - 5.0 * rate) / 2000.0;  // c phi + d omega = M_max
  std::printf("bore: saturated at %.4f rad (hand %.4f), held %.3f N m (hand %.3f)\n",
              saturated_at * rate * kH, limit_angle, torque, -kMaxNm);
  EXPECT_NEAR(saturated_at * rate * kH, limit_angle, 2 * rate * kH);
  EXPECT_NEAR(torque, -kMaxNm, 0.01);
  // reversed: the torque rises with slope c_B until +M_max after 2 M_max / c_B of turn
  double reversed = 0;
  int flipped_at = -1;
  for (int k = 1; k <= 8000; ++k) {
    const BoreStep s = bore_step(p, phi, -rate, 0.0, kLoadN, kMu, kH);
    phi = s.twist_rad;
    reversed += rate * kH;
    if (flipped_at < 0 && s.torque_nm >= kMaxNm - 0.01) flipped_at = k;
    torque = s.torque_nm;
  }
  const double width_angle = flipped_at * rate * kH;
  std::printf("bore: reversed, +M_max after %.4f rad (hand 2 M_max / c_B = %.4f); loop %.2f N m\n",
              width_angle, 2 * kMaxNm / 2000.0, torque - (-kMaxNm));
  // sliding, the twist rests (phi' = 0: c_B phi = M_max); reversed, c_B phi - d_B omega reaches
  // -M_max after (2 M_max - d_B omega) / c_B of turn
  EXPECT_NEAR(width_angle, (2 * kMaxNm - 5.0 * rate) / 2000.0, 2 * rate * kH);
  EXPECT_NEAR(torque - (-kMaxNm), 2 * kMaxNm, 0.02);  // the loop's width
}

// The brush model, independently of the derivation in tmeasy_bore.h: a field of bristles on a
// rectangular patch |x| <= a, |y| <= b rolls along an exact circle (radius v / omega, heading
// omega t); each bristle's tip was laid on the ground where its base was at the leading edge
// (a - x)/v ago. Its deflection (base - tip in the wheel's axes, exact rotations) times k gives
// the patch's moment; divided by that of a rigid twist (k I_p) it is the equivalent twist, which
// must be omega lambda_B / v.
double brush_equivalent_twist_rad(double a, double b, double v, double omega) {
  constexpr int kN = 400;
  const auto world = [&](double t, double x, double y) {  // a patch point at time t, on the circle
    const double r = v / omega, psi = omega * t;
    const double cx = r * std::sin(psi), cy = r * (1 - std::cos(psi));
    return std::pair{cx + std::cos(psi) * x - std::sin(psi) * y,
                     cy + std::sin(psi) * x + std::cos(psi) * y};
  };
  const double t_now = 10.0, psi = omega * t_now;
  double moment = 0, polar = 0;
  for (int i = 0; i < kN; ++i) {
    const double x = -a + (i + 0.5) * 2 * a / kN;
    for (int j = 0; j < kN; ++j) {
      const double y = -b + (j + 0.5) * 2 * b / kN;
      const auto [bx, by] = world(t_now, x, y);
      const auto [tx, ty] = world(t_now - (a - x) / v, a, y);
      const double dx = std::cos(psi) * (bx - tx) + std::sin(psi) * (by - ty);
      const double dy = -std::sin(psi) * (bx - tx) + std::cos(psi) * (by - ty);
      moment += x * dy - y * dx;  // k = 1 per cell
      polar += x * x + y * y;
    }
  }
  return moment / polar;
}

TEST(BoreTorque, RelaxationLengthIsTheBrushModels) {
  const TmeasyParams p = bore_tire();
  const double a = kLengthM / 2, b = 0.1;
  const double lambda_m = bore_relaxation_length_m(p, kLoadN);
  EXPECT_NEAR(lambda_m, a * b * b / (a * a + b * b), 1e-12);
  for (const double v : {1.0, 5.0 / 3.6, 5.0}) {
    for (const double omega : {0.1, 0.3}) {
      const double twist = brush_equivalent_twist_rad(a, b, v, omega);
      std::printf("brush at %.2f m/s, %.1f rad/s: twist %.6f rad, lambda %.5f m (formula %.5f)\n",
                  v, omega, twist, twist * v / omega, lambda_m);
      EXPECT_NEAR(twist * v / omega, lambda_m, 0.01 * lambda_m);
    }
  }
}

// Rolling at 5 km/h with a steady turn of 0.3 rad/s: the patch relaxes over lambda_B, the twist
// settles at phi = omega lambda_B / v (the implicit step's fixed point too) and M = -c_B phi =
// 2000 * 0.3 * 0.04966 / 1.3889 = 21.45 N m, under a tenth of M_max; at stand-still the same
// turn slides.
TEST(BoreTorque, FadesWhenRolling) {
  const TmeasyParams p = bore_tire();
  const double rate = 0.3, v = 5.0 / 3.6;
  double phi = 0, torque = 0;
  for (int k = 0; k < 5000; ++k) {
    const BoreStep s = bore_step(p, phi, rate, v, kLoadN, kMu, kH);
    phi = s.twist_rad;
    torque = s.torque_nm;
  }
  const double a = kLengthM / 2, lambda_m = a * 0.01 / (a * a + 0.01);
  const double hand = -2000.0 * rate * lambda_m / v;
  std::printf("bore at 5 km/h: %.2f N m (hand %.2f), max %.2f\n", torque, hand, kMaxNm);
  EXPECT_NEAR(torque, hand, 1e-3 * std::abs(hand));
  EXPECT_NEAR(hand, -21.45, 0.01);
  EXPECT_LT(std::abs(torque), 0.1 * kMaxNm);
  phi = 0;
  for (int k = 0; k < 5000; ++k) phi = bore_step(p, phi, rate, 0.0, kLoadN, kMu, kH).twist_rad;
  EXPECT_NEAR(bore_step(p, phi, rate, 0.0, kLoadN, kMu, kH).torque_nm, -kMaxNm, 0.01);
}

}  // namespace
}  // namespace rig::model::tire
