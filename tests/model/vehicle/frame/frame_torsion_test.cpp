// Frame torsion (issue 17 item 5, model/vehicle/frame/frame_torsion.h) on the 6x4 tractor of
// config/vehicles/tractor-6x4-frame.toml against hand calculations: (a) the torsion mode's
// frequency from the 2 x 2 eigenproblem of the two parts' roll inertias on their axles' roll
// stiffnesses joined by the frame; (b) the lateral load transfer per axle under a steady lateral
// acceleration (a banked road) from the two-part roll model, with and without the frame, and a
// stiff frame as the one rigid chassis; (c) the static loads unchanged (rigid body on springs);
// (d) analytic against finite-difference partials, and a maneuver at h = 1 ms without
// allocation; the config's [frame] keys; rigid axles behind the split (the rigid-axle truck).
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "io/config/vehicle_file.h"
#include "model/solver/finite_difference.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"
#include "tests/support/vehicle_rest.h"

namespace rig::model::vehicle {
namespace {

constexpr double kG = 9.81;
constexpr double kH = 1e-3;
constexpr double kPi = std::numbers::pi;

VehicleParams frame_tractor() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-frame.toml");
}

/// The same tractor without [frame]: tractor-6x4-cab.toml.
VehicleParams cab_tractor() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-cab.toml");
}

using test::rest;  // at rest, brakes on, settled (tests/support/vehicle_rest.h)

/// Roll stiffness of axle a against the ground: the suspension (springs k at +-t/2, the bar's
/// wheel rate k_b on the travel difference: t^2 (k/2 + k_b)) in series with the tires
/// (c_z t^2 / 2).
double axle_roll_stiffness(const AxleParams& a) {
  const double t2 = a.track_m * a.track_m;
  const double suspension = t2 * (0.5 * a.spring_stiffness_npm + a.anti_roll_stiffness_npm);
  const double tires = 0.5 * a.tire.tmeasy.vertical_stiffness_npm * t2;
  return suspension * tires / (suspension + tires);
}

TEST(FrameTorsion, ConfigReadsTheFrameTable) {
  const VehicleParams p = frame_tractor();
  ASSERT_TRUE(p.frame.enabled);
  EXPECT_EQ(p.frame.torsion_stiffness_nmprad, 200000.0);
  EXPECT_EQ(p.frame.torsion_damping_nmsprad, 2500.0);
  EXPECT_EQ(p.frame.split_x_m, -0.4);
  EXPECT_EQ(p.frame.rear_mass_kg, 1800.0);
  EXPECT_EQ(p.frame.rear_cg_x_m, -1.9);
  EXPECT_EQ(p.frame.rear_roll_inertia_kgm2, 1200.0);
  EXPECT_EQ(p.frame.axis_height_m, 0.95);
  EXPECT_FALSE(cab_tractor().frame.enabled);
  VehicleModel m(p, kH);
  const VehicleFramework& f = m.framework();
  EXPECT_EQ(f.size(), 13);  // 6 + 3 x 2 + the twist, stored last
  EXPECT_EQ(f.twist_index(), 12);
  EXPECT_FALSE(f.on_rear_part(0));
  EXPECT_TRUE(f.on_rear_part(1));
  EXPECT_TRUE(f.on_rear_part(2));
}

/// Static axle loads of a rigid sprung mass on equal springs k at x_a: the chassis' weight at
/// x = 0 and the free bodies' at their CGs (their mounts pass it on), W at x_w:
/// n z - S1 theta = W / k, S1 z - S2 theta = W x_w / k; F_a = 2 k (z - x_a theta) + the axle's
/// unsprung weight.
std::vector<double> hand_axle_loads(const VehicleParams& p) {
  double w = p.chassis.mass_kg * kG, wx = 0;
  for (const FreeBodyParams& b : p.free_bodies) {
    w += b.mass_kg * kG;
    wx += b.mass_kg * kG * b.position_m[0];
  }
  double n = 0, s1 = 0, s2 = 0;
  const double k = p.axles[0].spring_stiffness_npm;  // alike on every wheel (config)
  for (const AxleParams& a : p.axles) {
    EXPECT_EQ(a.spring_stiffness_npm, k);
    n += 2, s1 += 2 * a.position_x_m, s2 += 2 * a.position_x_m * a.position_x_m;
  }
  Eigen::Matrix2d lhs;
  lhs << n, -s1, s1, -s2;
  const Eigen::Vector2d zt = lhs.inverse() * Eigen::Vector2d(w / k, wx / k);
  std::vector<double> loads;
  for (const AxleParams& a : p.axles)
    loads.push_back(2 * k * (zt(0) - a.position_x_m * zt(1)) + 2 * a.unsprung_mass_kg * kG);
  return loads;
}

TEST(FrameTorsion, StaticLoadsAreUnchangedByTheFrame) {
  const std::vector<double> hand = hand_axle_loads(frame_tractor());
  std::vector<double> wheel_loads[2];
  int run = 0;
  for (VehicleParams p : {cab_tractor(), frame_tractor()}) {
    // the seat on the centre line: its weight's roll moment (100 kg at y = 0.5 m) would twist
    // the frame at rest and share the left-right split differently (not the axle loads)
    p.free_bodies[2].position_m[1] = 0;
    VehicleModel m(p, kH);
    Signals s = test::all_driver_inputs();
    rest(m, s, 8.0);
    for (int a = 0; a < 3; ++a) {
      const double load = m.wheel_load_n(2 * a) + m.wheel_load_n(2 * a + 1);
      std::printf("%s: axle %d load %.1f N, hand %.1f N (%.4f %%)\n", p.name.c_str(), a + 1, load,
                  hand[static_cast<std::size_t>(a)],
                  100 * (load / hand[static_cast<std::size_t>(a)] - 1));
      // 0.12 % at the last axle: the model's rest state without [frame] already (the hub travels
      // settle 0.03 mm from the design height); the frame changes nothing of it (below)
      EXPECT_NEAR(load, hand[static_cast<std::size_t>(a)],
                  1.5e-3 * hand[static_cast<std::size_t>(a)]);
    }
    for (int i = 0; i < 6; ++i) wheel_loads[run].push_back(m.wheel_load_n(i));
    ++run;
  }
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_NEAR(wheel_loads[1][i], wheel_loads[0][i], 1e-5 * wheel_loads[0][i]) << "wheel " << i;
}

/// Lateral load transfer per axle, (F_right - F_left) / 2, on a bank of slope `bank` (gravity's
/// lateral part g_y = g sin(atan(bank)) acts as a steady lateral acceleration), from the two-part
/// roll model about the ground (the roll centres of axles with vertical hub travel):
///   (c_f - P_f) phi_f + c_t (phi_f - phi_r) = M_f,  (c_r - P_r) phi_r - c_t (phi_f - phi_r) = M_r
/// c_f, c_r the axles' roll stiffnesses (axle_roll_stiffness, the rear part's axles summed),
/// P = sum m g h the parts' rolled weights, M_f = sum m g_y h - V z_a, M_r = ... + V z_a with V
/// the lateral force the frame passes from the front part to the rear at the torsion axis'
/// height z_a: the front part's lateral load less what the front axle's tires take (the tires'
/// lateral stiffnesses c_y share the total as a rigid body on lateral springs: translation and
/// yaw). Front part: its share of the frame, the cab, the engine, the seat (CG heights from the
/// config); rear part: rear_mass_kg at the sprung CG's height. Then per axle
///   dF_a = (c_a phi_part + 2 m_u g_y r_w) / t_a
/// (the unsprung masses' own lateral load at the wheel centres' height r_w). c_t = infinity
/// (`rigid`): one roll angle, (c_f + c_r - P) phi = M_f + M_r.
std::vector<double> hand_transfer(const VehicleParams& p, const VehicleFramework& f, double bank,
                                  bool rigid) {
  const double gy = kG * std::sin(std::atan(bank)), gz = kG * std::cos(std::atan(bank));
  const double h_cg = p.chassis.cg_height_m;
  const double split = p.frame.split_x_m, z_a = p.frame.axis_height_m;
  // the parts: moment of their lateral load, rolled weight, lateral load [per g]
  double mh_f = (p.chassis.mass_kg - p.frame.rear_mass_kg) * h_cg,
         m_f = p.chassis.mass_kg - p.frame.rear_mass_kg;
  const double mh_r = p.frame.rear_mass_kg * h_cg;
  for (const FreeBodyParams& b : p.free_bodies) {
    mh_f += b.mass_kg * (h_cg + b.position_m[2]);
    m_f += b.mass_kg;
  }
  // the tires' lateral forces: a rigid body on lateral springs
  double m_total = p.chassis.mass_kg, mx = 0;
  for (const FreeBodyParams& b : p.free_bodies)
    m_total += b.mass_kg, mx += b.mass_kg * b.position_m[0];
  Eigen::Matrix2d kk = Eigen::Matrix2d::Zero();
  for (const AxleParams& a : p.axles) {
    m_total += 2 * a.unsprung_mass_kg;
    mx += 2 * a.unsprung_mass_kg * a.position_x_m;
    const double c = 2 * a.tire.tmeasy.lateral_stiffness_npm, x = a.position_x_m;
    kk(0, 0) += c, kk(0, 1) += c * x, kk(1, 0) += c * x, kk(1, 1) += c * x * x;
  }
  const Eigen::Vector2d yp = kk.inverse() * Eigen::Vector2d(m_total * gy, mx * gy);
  const AxleParams& front = p.axles[0];
  const double front_axle_force =
      2 * front.tire.tmeasy.lateral_stiffness_npm * (yp(0) + front.position_x_m * yp(1));
  const double v = m_f * gy - (front_axle_force - 2 * front.unsprung_mass_kg * gy);
  const double moment_f = mh_f * gy - v * z_a, moment_r = mh_r * gy + v * z_a;
  double c_f = 0, c_r = 0;
  for (const AxleParams& a : p.axles)
    (a.position_x_m < split ? c_r : c_f) += axle_roll_stiffness(a);
  const double p_f = mh_f * gz, p_r = mh_r * gz, c_t = p.frame.torsion_stiffness_nmprad;
  double phi_f = 0, phi_r = 0;
  if (rigid) {
    phi_f = phi_r = (moment_f + moment_r) / (c_f + c_r - p_f - p_r);
  } else {
    Eigen::Matrix2d a;
    a << c_f - p_f + c_t, -c_t, -c_t, c_r - p_r + c_t;
    const Eigen::Vector2d phi = a.inverse() * Eigen::Vector2d(moment_f, moment_r);
    phi_f = phi(0), phi_r = phi(1);
  }
  std::vector<double> transfer;
  for (int i = 0; i < static_cast<int>(p.axles.size()); ++i) {
    const AxleParams& a = p.axles[static_cast<std::size_t>(i)];
    const double r_w = f.mount(2 * i).z() + h_cg;
    const double phi = a.position_x_m < split ? phi_r : phi_f;
    transfer.push_back((axle_roll_stiffness(a) * phi + 2 * a.unsprung_mass_kg * gy * r_w) /
                       a.track_m);
  }
  return transfer;
}

/// The model's transfer per axle at rest on the bank, after `seconds`.
std::vector<double> measured_transfer(const VehicleParams& p, double seconds) {
  VehicleModel m(p, kH);
  Signals s = test::all_driver_inputs();
  rest(m, s, seconds);
  std::vector<double> out;
  for (int a = 0; a < 3; ++a)
    out.push_back(0.5 * (m.wheel_load_n(2 * a + 1) - m.wheel_load_n(2 * a)));
  return out;
}

TEST(FrameTorsion, LoadTransferDistributionAsTheTwoPartRollModel) {
  const double bank = 0.05;  // g_y = 0.49 m/s^2
  VehicleParams with = frame_tractor();
  with.road.bank = bank;
  with.frame.axis_height_m = 0;  // on the axles' roll axis (see hand_transfer)
  VehicleParams without = with;
  without.frame.enabled = false;  // exactly tractor-6x4-cab.toml on the bank
  VehicleParams stiff = with;
  stiff.frame.torsion_stiffness_nmprad = 1e9;
  const VehicleModel ref(with, kH);
  const std::vector<double> hand_with = hand_transfer(with, ref.framework(), bank, false);
  const std::vector<double> hand_without = hand_transfer(with, ref.framework(), bank, true);
  // the seat sits off the centre line (y = 0.5 m): its roll moment is there on the level too
  VehicleParams level_with = with, level_without = without, level_stiff = stiff;
  level_with.road.bank = level_without.road.bank = level_stiff.road.bank = 0;
  const double seconds = 3.0;
  const std::vector<double> m_with = measured_transfer(with, seconds);
  const std::vector<double> m_without = measured_transfer(without, seconds);
  const std::vector<double> m_stiff = measured_transfer(stiff, seconds);
  const std::vector<double> l_with = measured_transfer(level_with, seconds);
  const std::vector<double> l_without = measured_transfer(level_without, seconds);
  const std::vector<double> l_stiff = measured_transfer(level_stiff, seconds);
  for (std::size_t a = 0; a < 3; ++a) {
    const double w = m_with[a] - l_with[a], wo = m_without[a] - l_without[a];
    const double st = m_stiff[a] - l_stiff[a];
    std::printf(
        "axle %zu: transfer with frame %.1f N (hand %.1f, %.1f %%), without %.1f N (hand %.1f, "
        "%.1f %%), stiff frame %.1f N\n",
        a + 1, w, hand_with[a], 100 * (w / hand_with[a] - 1), wo, hand_without[a],
        100 * (wo / hand_without[a] - 1), st);
    EXPECT_NEAR(w, hand_with[a], 0.10 * std::abs(hand_with[a])) << "axle " << a + 1;
    EXPECT_NEAR(wo, hand_without[a], 0.10 * std::abs(hand_without[a])) << "axle " << a + 1;
    EXPECT_NEAR(st, wo, 0.01 * std::abs(wo)) << "axle " << a + 1;
  }
  // the soft frame moves load transfer to the front axle (the front part's moment stays there)
  EXPECT_GT(m_with[0] - l_with[0], m_without[0] - l_without[0]);
  // the config's torsion axis, 0.95 m above the axles' roll axis: a twist about it moves the
  // rear contacts sideways (0.95 m per rad), which the tires' lateral stiffness resists at rest -
  // a stiffer twist than the frame's alone, so the front's share falls between the two
  VehicleParams high = with, level_high = with;
  high.frame.axis_height_m = level_high.frame.axis_height_m = 0.95;
  level_high.road.bank = 0;
  const double front_high =
      measured_transfer(high, seconds)[0] - measured_transfer(level_high, seconds)[0];
  std::printf("front axle's transfer with the torsion axis at 0.95 m: %.1f N\n", front_high);
  EXPECT_GT(front_high, m_without[0] - l_without[0]);
  EXPECT_LT(front_high, m_with[0] - l_with[0]);
}

/// The mean period of a signal's upward zero crossings (linear interpolation).
double period_s(const std::vector<double>& x, double h) {
  std::vector<double> up;
  for (std::size_t k = 1; k < x.size(); ++k) {
    if (x[k - 1] < 0 && x[k] >= 0)
      up.push_back(h * (static_cast<double>(k - 1) + x[k - 1] / (x[k - 1] - x[k])));
  }
  if (up.size() < 3) return 0;
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

/// The two-part roll model's modes: the front part (its share of the frame's sprung mass and
/// roll inertia) and the rear part, each rolling about the ground (the roll axis of axles with
/// vertical hub travel) on its axles' roll stiffnesses less its rolled weight, joined by c_t:
///   [I_f 0; 0 I_r] phi'' + [c_f - P_f + c_t, -c_t; -c_t, c_r - P_r + c_t] phi = 0,
/// I = I_own + m h^2 about the ground, plus the part's unsprung masses (below). Returns the
/// frequencies [Hz] (low, high) and the high (torsion) mode's shape (phi_f, phi_r).
struct Modes {
  double low_hz = 0, high_hz = 0;
  Eigen::Vector2d torsion_shape;
};
Modes hand_modes(const VehicleParams& p) {
  const double h = p.chassis.cg_height_m;
  const double m_r = p.frame.rear_mass_kg, m_f = p.chassis.mass_kg - m_r;
  const double i_r = p.frame.rear_roll_inertia_kgm2 + m_r * h * h;
  const double i_f = p.chassis.inertia_kgm2[0] - p.frame.rear_roll_inertia_kgm2 + m_f * h * h;
  double c_f = 0, c_r = 0;
  for (const AxleParams& a : p.axles)
    (a.position_x_m < p.frame.split_x_m ? c_r : c_f) += axle_roll_stiffness(a);
  // the unsprung masses move with their part laterally (their hub travel is vertical) and by the
  // quasi-static share of the suspension in series with the tires vertically:
  // 2 m_u (r_w^2 + (rho t/2)^2), rho = c_suspension / (c_suspension + c_tires)
  double i_uf = 0, i_ur = 0;
  for (const AxleParams& a : p.axles) {
    const double t2 = a.track_m * a.track_m;
    const double susp = t2 * (0.5 * a.spring_stiffness_npm + a.anti_roll_stiffness_npm);
    const double rho = susp / (susp + 0.5 * a.tire.tmeasy.vertical_stiffness_npm * t2);
    const double r_w = a.tire.tmeasy.radius_unloaded_m;
    (a.position_x_m < p.frame.split_x_m ? i_ur : i_uf) +=
        2 * a.unsprung_mass_kg * (r_w * r_w + rho * rho * 0.25 * t2);
  }
  const double c_t = p.frame.torsion_stiffness_nmprad;
  Eigen::Matrix2d k, mass;
  k << c_f - m_f * kG * h + c_t, -c_t, -c_t, c_r - m_r * kG * h + c_t;
  mass << i_f + i_uf, 0, 0, i_r + i_ur;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(k, mass);
  Modes out;
  out.low_hz = std::sqrt(es.eigenvalues()(0)) / (2 * kPi);
  out.high_hz = std::sqrt(es.eigenvalues()(1)) / (2 * kPi);
  out.torsion_shape = es.eigenvectors().col(1).normalized();
  return out;
}

/// The torsion mode measured: at rest (no free bodies: the frame's two parts alone; the dampers
/// at a tenth, the frame undamped), the parts put into the hand mode's shape (the front part
/// rolled about the ground, the rear part twisted against it), then the twist's free vibration.
double measured_torsion_hz(VehicleParams p, const Modes& hand, double amplitude_rad) {
  VehicleModel m(p, kH);
  Signals s = test::all_driver_inputs();
  rest(m, s, 1.0);
  auto& y = m.framework().coordinates();
  const Eigen::Index tw = m.framework().twist_index();
  const double rest_twist = y(tw);
  const double phi_f = amplitude_rad * hand.torsion_shape(0);
  const double phi_r = amplitude_rad * hand.torsion_shape(1);
  y(5) += phi_f;
  y(1) -= p.chassis.cg_height_m * phi_f;  // about the ground under the CG
  y(tw) += phi_r - phi_f;
  std::vector<double> twist;
  for (int k = 0; k < 3000; ++k) {
    EXPECT_EQ(m.step(s), StepStatus::kOk);
    twist.push_back(m.state().framework_y(tw) - rest_twist);
  }
  return 1.0 / period_s(twist, kH);
}

VehicleParams bare_frame_tractor() {
  VehicleParams p = frame_tractor();
  p.free_bodies.clear();  // the front part alone: no cab, engine, seat modes in the way
  for (AxleParams& a : p.axles) {
    a.damper_bump_nspm *= 0.1;
    a.damper_rebound_nspm *= 0.1;
  }
  p.frame.torsion_damping_nmsprad = 0;
  return p;
}

TEST(FrameTorsion, TorsionModeFrequencyAsTheTwoMassHandModel) {
  VehicleParams p = bare_frame_tractor();
  p.frame.axis_height_m = 0;  // on the axles' roll axis (see hand_modes)
  const Modes hand = hand_modes(p);
  const double f = measured_torsion_hz(p, hand, 1e-3);
  std::printf("torsion mode %.3f Hz, hand %.3f Hz (%.1f %%); the in-phase roll mode %.3f Hz\n", f,
              hand.high_hz, 100 * (f / hand.high_hz - 1), hand.low_hz);
  EXPECT_NEAR(f, hand.high_hz, 0.05 * hand.high_hz);
  // a stiffer frame: the mode moves up as the hand model says
  VehicleParams stiff = p;
  stiff.frame.torsion_stiffness_nmprad = 1e6;
  const Modes hand_stiff = hand_modes(stiff);
  const double f_stiff = measured_torsion_hz(stiff, hand_stiff, 1e-3);
  std::printf("c_t 1e6 N m/rad: torsion mode %.3f Hz, hand %.3f Hz (%.1f %%)\n", f_stiff,
              hand_stiff.high_hz, 100 * (f_stiff / hand_stiff.high_hz - 1));
  EXPECT_NEAR(f_stiff, hand_stiff.high_hz, 0.05 * hand_stiff.high_hz);
}

/// The circle of config/maneuvers/circle-tractor-frame.toml by hand: 10 m/s, a steady steer.
void circle(VehicleModel& m, Signals& s, double seconds) {
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = m.time_s() > 0.5 ? 2.0 : 0.0;
    s[Signal::kThrottlePedal] = 0.15;
    ASSERT_EQ(m.step(s), StepStatus::kOk)
        << "t = " << m.time_s() << ": " << fault_kind_name(m.last_fault().kind);
  }
}

TEST(FrameTorsion, AnalyticPartialsMatchFiniteDifferences) {
  VehicleModel m(frame_tractor(), kH);
  (void)m.settle(10.0);
  Signals s = test::all_driver_inputs();
  circle(m, s, 3.0);
  auto& fw = m.framework();
  const Eigen::Index n = fw.size(), tw = fw.twist_index();
  Eigen::MatrixXd ay(n, n), az(n, n), fy(n, n), fz(n, n);
  Eigen::VectorXd wy(n), wz(n), q0(n), q1(n);
  ASSERT_TRUE(fw.force_jacobians(fw.coordinates(), fw.speeds(), ay, az));
  solver::finite_difference_force_jacobians<Eigen::Dynamic>(fw, fw.coordinates(), fw.speeds(), fy,
                                                            fz, wy, wz, q0, q1);
  std::printf("twist: dq/dy %.4g (fd %.4g), dq/dz %.4g (fd %.4g)\n", ay(tw, tw), fy(tw, tw),
              az(tw, tw), fz(tw, tw));
  // the twist's own partials: the frame's spring-damper, the rear tires' vertical stiffness and
  // damping through the twist's lever (what is left is gravity and inertia, explicit)
  EXPECT_NEAR(ay(tw, tw), fy(tw, tw), 2e-3 * std::abs(fy(tw, tw)));
  EXPECT_NEAR(az(tw, tw), fz(tw, tw), 2e-2 * std::abs(fz(tw, tw)));
  // the rear hubs against the twist and back (the tires' vertical force through both columns)
  for (const Eigen::Index h : {8, 9, 10, 11}) {
    EXPECT_NEAR(ay(h, tw), fy(h, tw), 2e-3 * std::abs(fy(tw, tw))) << "row " << h;
    EXPECT_NEAR(ay(tw, h), fy(tw, h), 2e-3 * std::abs(fy(tw, tw))) << "column " << h;
    EXPECT_NEAR(az(h, tw), fz(h, tw), 2e-2 * std::abs(fz(tw, tw))) << "row " << h;
  }
  // the body's vertical force and roll moment (speed rows 2, 3) against the twist, and the twist
  // against the body's height and roll angle (coordinate columns 2, 5); the yaw moment's
  // column is not compared: its difference is the rolling radius' change with the penetration
  // (the longitudinal slip of the rear wheels, left against right), which no analytic partial
  // of the framework takes (the body's roll column neither)
  for (const Eigen::Index b : {2, 3})
    EXPECT_NEAR(ay(b, tw), fy(b, tw), 2e-3 * std::abs(fy(tw, tw))) << "row " << b;
  for (const Eigen::Index b : {2, 5})
    EXPECT_NEAR(ay(tw, b), fy(tw, b), 2e-3 * std::abs(fy(tw, tw))) << "column " << b;
  // the front axle does not see the twist
  for (const Eigen::Index h : {6, 7}) EXPECT_EQ(ay(h, tw), 0.0);
}

TEST(FrameTorsion, CircleAtOneMillisecondWithoutAllocation) {
  VehicleModel m(frame_tractor(), kH);
  (void)m.settle(10.0);
  Signals s = test::all_driver_inputs();
  circle(m, s, 1.0);
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  circle(m, s, 5.0);
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  ModelReport r;
  m.fill_report(r);
  const UnitReport& u = r.units[0];
  std::printf("circle: a_y %.3f m/s^2, twist %.5f rad, rate %.5f rad/s, torsion moment %.1f N m\n",
              u.acceleration_mps2[1], u.frame_twist_rad, u.frame_twist_rate_radps,
              u.frame_torsion_moment_nm);
  EXPECT_GT(std::abs(u.acceleration_mps2[1]), 1.0);
  const FrameParams& f = frame_tractor().frame;
  EXPECT_DOUBLE_EQ(u.frame_torsion_moment_nm,
                   f.torsion_stiffness_nmprad * u.frame_twist_rad +
                       f.torsion_damping_nmsprad * u.frame_twist_rate_radps);
  EXPECT_GT(std::abs(u.frame_twist_rad), 1e-4);
}

/// The truck on rigid axles (config/vehicles/truck-3axle-rigid.toml) with a frame split between
/// its front axle and the tandem: the rigid tandem moves with the rear part.
VehicleParams rigid_truck_with_frame() {
  VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/truck-3axle-rigid.toml");
  p.frame.enabled = true;
  p.frame.torsion_stiffness_nmprad = 2e5;
  p.frame.torsion_damping_nmsprad = 2500;
  p.frame.split_x_m = 0.5 * (p.axles[0].position_x_m + p.axles[1].position_x_m);
  p.frame.rear_mass_kg = 0.4 * p.chassis.mass_kg;
  p.frame.rear_cg_x_m = p.frame.split_x_m - 1.0;
  p.frame.rear_roll_inertia_kgm2 = 0.3 * p.chassis.inertia_kgm2[0];
  p.frame.axis_height_m = 0.9;
  return p;
}

TEST(FrameTorsion, RigidAxlesBehindTheSplit) {
  VehicleParams with = rigid_truck_with_frame();
  VehicleParams without = with;
  without.frame.enabled = false;
  // static axle loads: unchanged by the frame (a rigid body on springs, the rigid-axle test's
  // hand formula for equal springs and the CG at x = 0: F_a = W (S2 - x_a S1) / (n S2 - S1^2))
  double s1 = 0, s2 = 0;
  for (const AxleParams& a : with.axles)
    s1 += a.position_x_m, s2 += a.position_x_m * a.position_x_m;
  for (int a = 0; a < 3; ++a) {
    const double x = with.axles[static_cast<std::size_t>(a)].position_x_m;
    const double hand = with.chassis.mass_kg * kG * (s2 - x * s1) / (3 * s2 - s1 * s1) +
                        with.axles[static_cast<std::size_t>(a)].rigid.mass_kg * kG;
    double loads[2];
    int k = 0;
    for (const VehicleParams* p : {&without, &with}) {
      VehicleModel m(*p, kH);
      Signals s = test::all_driver_inputs();
      rest(m, s, 2.0);
      loads[k++] = m.wheel_load_n(2 * a) + m.wheel_load_n(2 * a + 1);
    }
    std::printf("rigid truck: axle %d load %.1f N with frame, %.1f without, hand %.1f\n", a + 1,
                loads[1], loads[0], hand);
    EXPECT_NEAR(loads[1], loads[0], 1e-5 * loads[0]);
    EXPECT_NEAR(loads[1], hand, 1e-3 * hand);
  }
  // a step steer at 60 km/h: the frame twists, the partials of the twist as finite differences
  VehicleModel m(with, kH);
  (void)m.settle(16.67);
  Signals s = test::all_driver_inputs();
  const long n = std::lround(3.0 / kH);
  for (long k = 0; k < n; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = k < 500 ? 0.0 : 0.8;
    s[Signal::kThrottlePedal] = 0.3;
    ASSERT_EQ(m.step(s), StepStatus::kOk) << fault_kind_name(m.last_fault().kind);
  }
  auto& fw = m.framework();
  const Eigen::Index dim = fw.size(), tw = fw.twist_index();
  std::printf("rigid truck, step steer: twist %.5f rad\n", fw.coordinates()(tw));
  EXPECT_GT(std::abs(fw.coordinates()(tw)), 1e-4);
  Eigen::MatrixXd ay(dim, dim), az(dim, dim), fy(dim, dim), fz(dim, dim);
  Eigen::VectorXd wy(dim), wz(dim), q0(dim), q1(dim);
  ASSERT_TRUE(fw.force_jacobians(fw.coordinates(), fw.speeds(), ay, az));
  solver::finite_difference_force_jacobians<Eigen::Dynamic>(fw, fw.coordinates(), fw.speeds(), fy,
                                                            fz, wy, wz, q0, q1);
  std::printf("twist: dq/dy %.4g (fd %.4g), dq/dz %.4g (fd %.4g)\n", ay(tw, tw), fy(tw, tw),
              az(tw, tw), fz(tw, tw));
  const double scale = std::abs(fy(tw, tw));
  // gravity on the twisted masses stays explicit (as the body's roll): its geometric stiffness
  // m g (height above the axis) of the rear part and of the tandem's wheels is in the finite
  // differences only
  double gravity =
      with.frame.rear_mass_kg * kG * (with.chassis.cg_height_m - with.frame.axis_height_m);
  for (int i = 2; i < 6; ++i)
    gravity += with.axles[static_cast<std::size_t>(i / 2)].unsprung_mass_kg * kG *
               (fw.mount(i).z() + with.chassis.cg_height_m - with.frame.axis_height_m);
  std::printf("gravity's geometric stiffness on the twist %.4g N m/rad\n", gravity);
  EXPECT_NEAR(ay(tw, tw) + gravity, fy(tw, tw), 2e-3 * scale);
  EXPECT_NEAR(az(tw, tw), fz(tw, tw), 2e-2 * std::abs(fz(tw, tw)));
  for (const Eigen::Index h : {8, 9, 10, 11}) {  // the tandem's heave and roll
    EXPECT_NEAR(ay(h, tw), fy(h, tw), 2e-3 * scale) << "row " << h;
    EXPECT_NEAR(ay(tw, h), fy(tw, h), 2e-3 * scale) << "column " << h;
  }
  for (const Eigen::Index h : {6, 7}) EXPECT_EQ(ay(h, tw), 0.0);  // the front axle
}

}  // namespace
}  // namespace rig::model::vehicle
