// The bore torque element alone (issue 15, item 3; model/tire/tmeasy_bore.h): slope c_B at
// stand-still, the limit (2/3) R_P mu F_z, the hysteresis of a reversed twist and the fade with
// the rolling speed, against hand values from the parameters.
#include <cmath>
#include <cstdio>

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

// Rolling at 5 km/h with a steady turn of 0.3 rad/s: the patch relaxes over its length, the
// twist settles at phi = omega L / v (the implicit step's fixed point too) and M = -c_B phi =
// 2000 * 0.3 * 0.22487 / 1.3889 = 97.1 N m, a third of M_max; at stand-still the same turn slides.
TEST(BoreTorque, FadesWhenRolling) {
  const TmeasyParams p = bore_tire();
  const double rate = 0.3, v = 5.0 / 3.6;
  double phi = 0, torque = 0;
  for (int k = 0; k < 5000; ++k) {
    const BoreStep s = bore_step(p, phi, rate, v, kLoadN, kMu, kH);
    phi = s.twist_rad;
    torque = s.torque_nm;
  }
  const double hand = -2000.0 * rate * kLengthM / v;
  std::printf("bore at 5 km/h: %.2f N m (hand %.2f), max %.2f\n", torque, hand, kMaxNm);
  EXPECT_NEAR(torque, hand, 1e-3 * std::abs(hand));
  EXPECT_LT(std::abs(torque), 0.5 * kMaxNm);
  phi = 0;
  for (int k = 0; k < 5000; ++k) phi = bore_step(p, phi, rate, 0.0, kLoadN, kMu, kH).twist_rad;
  EXPECT_NEAR(bore_step(p, phi, rate, 0.0, kLoadN, kMu, kH).torque_nm, -kMaxNm, 0.01);
}

}  // namespace
}  // namespace rig::model::tire
