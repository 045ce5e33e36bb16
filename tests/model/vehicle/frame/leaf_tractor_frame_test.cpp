// Frame torsion on the leaf-sprung 6x4 tractor (config/vehicles/tractor-6x4-leaf.toml's [frame],
// issue 17 items 5 and 7): its rigid tandem on five-link leaves behind the frame's split. Against
// hand calculations: (a) the torsion mode's frequency from the two-part roll model of rigid axles
// (each part rolling about its axles' roll centre on the suspension's roll stiffness in series
// with the tires'), (b) the static axle loads unchanged by the frame; and the twist's analytic
// partials against finite differences in a step steer, at h = 1 ms without allocation.
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

VehicleParams leaf_tractor() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-leaf.toml");
}

TEST(LeafTractorFrame, ConfigHasTheLadderFrameWithTheTandemBehindTheSplit) {
  const VehicleParams p = leaf_tractor();
  ASSERT_TRUE(p.frame.enabled);
  EXPECT_EQ(p.frame.torsion_stiffness_nmprad, 200000.0);
  EXPECT_EQ(p.frame.split_x_m, -0.4);
  EXPECT_EQ(p.frame.rear_mass_kg, 1800.0);
  VehicleModel m(p, kH);
  const VehicleFramework& f = m.framework();
  EXPECT_EQ(f.size(), 13);  // 6 + 3 axles' heave and roll + the twist, stored last
  EXPECT_EQ(f.twist_index(), 12);
  EXPECT_FALSE(f.on_rear_part(0));
  EXPECT_TRUE(f.on_rear_part(1));
  EXPECT_TRUE(f.on_rear_part(2));
}

/// The static axle loads with and without the frame, standing braked: a symmetric load does not
/// twist the frame (the seat put on the centre line: its weight's roll moment would twist it
/// at rest and share the left-right split differently, not the axle loads).
TEST(LeafTractorFrame, StaticLoadsAreUnchangedByTheFrame) {
  std::vector<double> wheel_loads[2];
  int run = 0;
  for (const bool frame : {false, true}) {
    VehicleParams p = leaf_tractor();
    p.frame.enabled = frame;
    p.free_bodies[2].position_m[1] = 0;
    VehicleModel m(p, kH);
    Signals s = test::all_driver_inputs();
    test::rest(m, s, 3.0);
    for (int i = 0; i < 6; ++i) wheel_loads[run].push_back(m.wheel_load_n(i));
    if (frame) {
      const double twist = m.state().framework_y(m.framework().twist_index());
      std::printf("twist at rest %.2e rad\n", twist);
      EXPECT_LT(std::abs(twist), 1e-5);
    }
    ++run;
  }
  for (std::size_t i = 0; i < 6; ++i) {
    std::printf("wheel %zu: %.1f N with frame, %.1f N without\n", i, wheel_loads[1][i],
                wheel_loads[0][i]);
    EXPECT_NEAR(wheel_loads[1][i], wheel_loads[0][i], 1e-4 * wheel_loads[0][i]) << "wheel " << i;
  }
}

/// One rigid axle's roll stiffness against the ground [N m/rad] split as the hand model needs
/// it: the suspension about the roll centre (the two leaves' vertical rates k at +-s/2: k s^2 / 2,
/// and the bar) and the tires (c_z t^2 / 2) in series.
struct AxleRoll {
  double suspension = 0, tires = 0, roll_centre_m = 0;
  [[nodiscard]] double series() const { return suspension * tires / (suspension + tires); }
  /// the axle's share of its part's roll (quasi-static: c_s (phi - phi_a) = c_w phi_a)
  [[nodiscard]] double share() const { return suspension / (suspension + tires); }
};
AxleRoll axle_roll(const AxleParams& a) {
  const double s = a.rigid.spring_track_m, t = a.track_m;
  return {0.5 * a.spring_stiffness_npm * s * s + a.rigid.anti_roll_stiffness_nmprad,
          0.5 * a.tire.tmeasy.vertical_stiffness_npm * t * t, a.rigid.roll_centre_height_m};
}

/// The two-part roll model of rigid axles (frame_torsion_test's, with roll centres above the
/// ground): each part of the sprung mass rolls by phi about its axles' roll centre (height h_rc)
/// while the axles roll by rho phi on their tires about the ground, so the part's CG (height h)
/// moves sideways by ((h - h_rc) + rho h_rc) phi and drops as m g ((h - h_rc) + rho^2 h_rc)
/// phi^2 / 2; the axles add (I_a + m_a r_w^2) rho^2. The frame's spring c_t between the parts:
///   [I_f 0; 0 I_r] phi'' + [c_f - P_f + c_t, -c_t; -c_t, c_r - P_r + c_t] phi = 0.
/// Returns the torsion (high) mode's frequency [Hz] and shape (phi_f, phi_r).
struct Mode {
  double hz = 0;
  Eigen::Vector2d shape;
};
Mode hand_torsion_mode(const VehicleParams& p) {
  const double h = p.chassis.cg_height_m;
  const double m_r = p.frame.rear_mass_kg;
  const double mass[2] = {p.chassis.mass_kg - m_r, m_r};
  double inertia[2] = {p.chassis.inertia_kgm2[0] - p.frame.rear_roll_inertia_kgm2,
                       p.frame.rear_roll_inertia_kgm2};
  double stiffness[2] = {0, 0}, rc[2] = {0, 0}, rho[2] = {0, 0};
  int count[2] = {0, 0};
  for (const AxleParams& a : p.axles) {
    const int part = a.position_x_m < p.frame.split_x_m ? 1 : 0;
    const AxleRoll r = axle_roll(a);
    const double rw = a.tire.tmeasy.radius_unloaded_m;
    stiffness[part] += r.series();
    inertia[part] +=
        (a.rigid.roll_inertia_kgm2 + a.rigid.mass_kg * rw * rw) * r.share() * r.share();
    rc[part] += r.roll_centre_m;
    rho[part] += r.share();
    ++count[part];
  }
  for (int i = 0; i < 2; ++i) {  // the part's own terms about its axles' (mean) roll centre
    const double hrc = rc[i] / count[i], s = rho[i] / count[i];
    const double arm = (h - hrc) + s * hrc;
    inertia[i] += mass[i] * arm * arm;
    stiffness[i] -= mass[i] * kG * ((h - hrc) + s * s * hrc);
  }
  const double c_t = p.frame.torsion_stiffness_nmprad;
  Eigen::Matrix2d k, m;
  k << stiffness[0] + c_t, -c_t, -c_t, stiffness[1] + c_t;
  m << inertia[0], 0, 0, inertia[1];
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(k, m);
  return {std::sqrt(es.eigenvalues()(1)) / (2 * kPi), es.eigenvectors().col(1).normalized()};
}

/// The mean period [s] of x from its upward zero crossings.
double period_s(const std::vector<double>& x, double h) {
  std::vector<double> up;
  for (std::size_t k = 1; k < x.size(); ++k) {
    if (x[k - 1] < 0 && x[k] >= 0)
      up.push_back(h * (static_cast<double>(k - 1) + x[k - 1] / (x[k - 1] - x[k])));
  }
  if (up.size() < 3) return 0;
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

/// The torsion mode measured as frame_torsion_test does: at rest (no free bodies, the dampers at
/// a tenth, the frame undamped), the two parts put into the hand mode's shape (each rolled about
/// its roll centre), then the twist's free vibration.
double measured_torsion_hz(VehicleParams p, const Mode& hand, double amplitude_rad) {
  VehicleModel m(p, kH);
  Signals s = test::all_driver_inputs();
  test::rest(m, s, 1.0);
  auto& y = m.framework().coordinates();
  const Eigen::Index tw = m.framework().twist_index();
  const double rest_twist = y(tw);
  const double phi_f = amplitude_rad * hand.shape(0);
  const double phi_r = amplitude_rad * hand.shape(1);
  y(5) += phi_f;
  y(1) -= (p.chassis.cg_height_m - p.frame.axis_height_m) * phi_f;  // about the roll axis
  y(tw) += phi_r - phi_f;
  // each axle rolled by its share rho of its part's roll (the springs in series with the tires)
  for (std::size_t a = 0; a < p.axles.size(); ++a) {
    const bool rear = p.axles[a].position_x_m < p.frame.split_x_m;
    const Eigen::Index roll = 7 + 2 * static_cast<Eigen::Index>(a);
    y(roll) += (axle_roll(p.axles[a]).share() - 1) * (rear ? phi_r : phi_f);
  }
  std::vector<double> twist;
  for (int k = 0; k < 3000; ++k) {
    EXPECT_EQ(m.step(s), StepStatus::kOk);
    twist.push_back(m.state().framework_y(tw) - rest_twist);
  }
  return 1.0 / period_s(twist, kH);
}

/// The leaf tractor's frame alone: no cab, engine, seat modes in the way; dampers at a tenth,
/// the frame undamped; every axle's roll centre (the leaves' eyes: rigid_axle.h) and the torsion
/// axis at the tandem's 0.67 m (the steer axle's 0.64 m moved up), so that the two parts roll
/// about one axis.
VehicleParams bare_leaf_frame_tractor() {
  VehicleParams p = leaf_tractor();
  p.free_bodies.clear();
  for (AxleParams& a : p.axles) {
    a.damper_bump_nspm *= 0.1;
    a.damper_rebound_nspm *= 0.1;
    a.tire.tmeasy.vertical_damping_nspm *= 0.1;
    a.rigid.roll_centre_height_m = 0.67;  // the leaves' eyes: the tandem's 0.67 m
  }
  p.frame.torsion_damping_nmsprad = 0;
  p.frame.axis_height_m = 0.67;
  return p;
}

TEST(LeafTractorFrame, TorsionModeFrequencyAsTheTwoPartHandModel) {
  const VehicleParams p = bare_leaf_frame_tractor();
  const Mode hand = hand_torsion_mode(p);
  const double f = measured_torsion_hz(p, hand, 1e-3);
  std::printf("leaf tractor: torsion mode %.3f Hz, hand %.3f Hz (%.1f %%), shape (%.3f, %.3f)\n", f,
              hand.hz, 100 * (f / hand.hz - 1), hand.shape(0), hand.shape(1));
  EXPECT_NEAR(f, hand.hz, 0.05 * hand.hz);
  // a stiffer frame (2.5 x): the mode moves up as the hand model says (at 1e6 N m/rad the hand
  // model is 6 % high: the mode nears the axles' roll on their tires, which the quasi-static
  // share rho leaves out)
  VehicleParams stiff = p;
  stiff.frame.torsion_stiffness_nmprad = 5e5;
  const Mode hand_stiff = hand_torsion_mode(stiff);
  const double f_stiff = measured_torsion_hz(stiff, hand_stiff, 1e-3);
  std::printf("c_t 5e5 N m/rad: torsion mode %.3f Hz, hand %.3f Hz (%.1f %%)\n", f_stiff,
              hand_stiff.hz, 100 * (f_stiff / hand_stiff.hz - 1));
  EXPECT_NEAR(f_stiff, hand_stiff.hz, 0.05 * hand_stiff.hz);
}

/// A step steer at 60 km/h, h = 1 ms, without allocation: the frame twists, the leaf tandem on
/// the rear part follows it (the twist's partials of the rear axles' heave and roll rows as
/// finite differences: the axles' leaves and tires act through the twisted levers).
TEST(LeafTractorFrame, StepSteerTwistsTheFrameAndItsPartialsMatchFiniteDifferences) {
  const VehicleParams p = leaf_tractor();
  VehicleModel m(p, kH);
  (void)m.settle(16.67);
  Signals s = test::all_driver_inputs();
  const long n = std::lround(3.0 / kH);
  const test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  for (long k = 0; k < n; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = k < 500 ? 0.0 : 0.8;
    s[Signal::kThrottlePedal] = 0.3;
    ASSERT_EQ(m.step(s), StepStatus::kOk) << fault_kind_name(m.last_fault().kind);
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  auto& fw = m.framework();
  const Eigen::Index dim = fw.size(), tw = fw.twist_index();
  std::printf("leaf tractor, step steer: twist %.5f rad\n", fw.coordinates()(tw));
  EXPECT_GT(std::abs(fw.coordinates()(tw)), 1e-4);
  Eigen::MatrixXd ay(dim, dim), az(dim, dim), fy(dim, dim), fz(dim, dim);
  Eigen::VectorXd wy(dim), wz(dim), q0(dim), q1(dim);
  ASSERT_TRUE(fw.force_jacobians(fw.coordinates(), fw.speeds(), ay, az));
  solver::finite_difference_force_jacobians<Eigen::Dynamic>(fw, fw.coordinates(), fw.speeds(), fy,
                                                            fz, wy, wz, q0, q1);
  std::printf("twist: dq/dy %.4g (fd %.4g), dq/dz %.4g (fd %.4g)\n", ay(tw, tw), fy(tw, tw),
              az(tw, tw), fz(tw, tw));
  const double scale = std::abs(fy(tw, tw));
  // gravity's geometric stiffness on the twisted masses stays explicit (in the differences
  // only: ~4e3 N m/rad of the rear part and the tandem)
  EXPECT_NEAR(ay(tw, tw), fy(tw, tw), 2e-3 * scale);
  EXPECT_NEAR(az(tw, tw), fz(tw, tw), 2e-2 * std::abs(fz(tw, tw)));
  for (const Eigen::Index h : {8, 9, 10, 11}) {  // the tandem's heave and roll
    std::printf("row/column %ld: %.4g (fd %.4g) / %.4g (fd %.4g)\n", static_cast<long>(h),
                ay(h, tw), fy(h, tw), ay(tw, h), fy(tw, h));
    EXPECT_NEAR(ay(h, tw), fy(h, tw), 2e-3 * scale) << "row " << h;
    EXPECT_NEAR(ay(tw, h), fy(tw, h), 2e-3 * scale) << "column " << h;
  }
  for (const Eigen::Index h : {6, 7}) EXPECT_EQ(ay(h, tw), 0.0);  // the steer axle
}

}  // namespace
}  // namespace rig::model::vehicle
