// Generic free bodies (issue 17 item 4): a cab and an engine on mounts, a driver's seat, each
// against hand calculations - natural frequencies of decoupled mount layouts, static
// deflections, the engine torque's reaction, the cab's roll in a steady circle and its phase
// lag under a 0.5 Hz lateral excitation - measured in the model at h = 1 ms; the partials
// against finite differences; the on-stop flag and the through-stops fault; the tractor with
// cab, engine and seat in a maneuver without allocation.
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/solver/finite_difference.h"
#include "model/vehicle/free_body/free_bodies.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

constexpr double kH = 1e-3;
constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;

MountParams mount(double x, double y, double z, const std::array<double, 3>& k,
                  const std::array<double, 3>& c) {
  MountParams m;
  m.body_point_m = {x, y, z};
  m.stiffness_npm = k;
  m.damping_nspm = c;
  m.stop_clearance_m = {0.1, 0.1, 0.1};  // far away unless a test says otherwise
  m.stop_stiffness_npm = {1e6, 1e6, 1e6};
  return m;
}

/// Each mount's chassis point where its body point is at the design position (as the loader's
/// default).
void at_design(FreeBodyParams& p) {
  for (MountParams& m : p.mounts)
    for (std::size_t k = 0; k < 3; ++k) m.chassis_point_m[k] = p.position_m[k] + m.body_point_m[k];
}

/// A cab on four mounts at (+-a, +-b, z_m) from its CG, all alike.
FreeBodyParams cab(double a, double b, double z_m, const std::array<double, 3>& k,
                   const std::array<double, 3>& c) {
  FreeBodyParams p;
  p.name = "cab";
  p.kind = FreeBodyKind::kCab;
  p.mass_kg = 1000;
  p.inertia_kgm2 = {600, 900, 800};
  p.position_m = {1.0, 0.0, 1.0};
  for (const double sx : {1.0, -1.0})
    for (const double sy : {1.0, -1.0}) p.mounts.push_back(mount(sx * a, sy * b, z_m, k, c));
  at_design(p);
  return p;
}

/// An engine on three mounts: two at (0.5, +-0.4), one at (-1, 0) - sum k x = 0, so that
/// bounce, pitch and roll are decoupled.
FreeBodyParams engine(double k, double c) {
  FreeBodyParams p;
  p.name = "engine";
  p.kind = FreeBodyKind::kEngine;
  p.mass_kg = 1200;
  p.inertia_kgm2 = {90, 420, 400};
  p.position_m = {0.9, 0.0, -0.1};
  p.mounts = {mount(0.5, 0.4, 0, {k, k, k}, {c, c, c}), mount(0.5, -0.4, 0, {k, k, k}, {c, c, c}),
              mount(-1.0, 0.0, 0, {k, k, k}, {c, c, c})};
  at_design(p);
  return p;
}

FreeBodyParams seat(double k, double c) {
  FreeBodyParams p;
  p.name = "seat";
  p.kind = FreeBodyKind::kSeat;
  p.mass_kg = 100;
  p.position_m = {1.9, 0.5, 0.6};
  MountParams m;
  m.stiffness_npm[2] = k;
  m.damping_nspm[2] = c;
  m.stop_clearance_m[2] = 0.2;
  m.stop_stiffness_npm[2] = 1e5;
  p.mounts.push_back(m);
  p.through_margin_m = 0.03;
  return p;
}

/// One free body on a chassis that the test holds or moves by hand (the chassis state is
/// state.framework_y/z, as the framework leaves it); the body's stepper as in the vehicle.
struct Bench {
  VehicleParams p;
  road::Road road;
  VehicleState s;
  VehicleWorkspace work;
  PredictedChassis chassis{s, work};
  std::unique_ptr<FreeBody> body;
  std::unique_ptr<Seat> seat_block;
  std::unique_ptr<solver::Stage> stepper;

  explicit Bench(const FreeBodyParams& b, double gravity = kG) : p(with(b, gravity)), road(p.road) {
    s.framework_y = Eigen::VectorXd::Zero(6);
    s.framework_z = Eigen::VectorXd::Zero(6);
    s.framework_y(2) = 1.0;
    work.lookahead_s = kH;  // as VehicleBlocks::update_contacts sets it for the step
    if (b.kind == FreeBodyKind::kSeat) {
      seat_block = std::make_unique<Seat>(p.free_bodies[0], road, s, work, 0, chassis);
      stepper = std::make_unique<solver::MechanicalStepper<1>>(*seat_block);
    } else {
      body = std::make_unique<FreeBody>(p.free_bodies[0], road, s, work, 0, chassis);
      stepper = std::make_unique<solver::MechanicalStepper<6>>(*body);
    }
    place_free_bodies(p, s);
  }
  static VehicleParams with(const FreeBodyParams& b, double gravity) {
    VehicleParams v;
    v.road.gravity_mps2 = gravity;
    v.free_bodies = {b};
    return v;
  }
  [[nodiscard]] RelativeMotion motion() const { return free_body_motion(p.free_bodies[0], 0, s); }
  void run(double seconds) {
    const int n = static_cast<int>(std::lround(seconds / kH));
    for (int k = 0; k < n; ++k) stepper->advance(kH);
  }
};

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

/// Frequency of the free vibration in coordinate `index` from the static position + `kick`.
double measured_hz(const FreeBodyParams& b, int index, double kick, double static_z) {
  Bench bench(b);
  Vec6& y = bench.s.free_body_y[0];
  y(2) += static_z;
  const double rest = y(index);
  y(index) += kick;
  std::vector<double> x;
  for (int k = 0; k < 5000; ++k) {
    bench.stepper->advance(kH);
    x.push_back(bench.s.free_body_y[0](index) - rest);
  }
  return 1.0 / period_s(x, kH);
}

TEST(FreeBody, CabBouncePitchRollFrequenciesAsHandCalculation) {
  const double kz = 5e4, a = 0.8, b = 0.5;
  const FreeBodyParams p = cab(a, b, 0.0, {1e5, 8e4, kz}, {0, 0, 0});  // mounts at CG height
  const double sag = -p.mass_kg * kG / (4 * kz);
  // decoupled modes of the symmetric layout: f = sqrt(k_total / m) / 2 pi, sqrt(k sum a^2 / I) / 2
  // pi
  const double bounce = std::sqrt(4 * kz / p.mass_kg) / (2 * kPi);
  const double pitch = std::sqrt(4 * kz * a * a / p.inertia_kgm2[1]) / (2 * kPi);
  const double roll = std::sqrt(4 * kz * b * b / p.inertia_kgm2[0]) / (2 * kPi);
  const double f_bounce = measured_hz(p, 2, 0.005, sag);
  const double f_pitch = measured_hz(p, 4, 0.005, sag);
  const double f_roll = measured_hz(p, 5, 0.005, sag);
  std::printf("cab: bounce %.4f Hz (hand %.4f), pitch %.4f (%.4f), roll %.4f (%.4f)\n", f_bounce,
              bounce, f_pitch, pitch, f_roll, roll);
  EXPECT_NEAR(f_bounce, bounce, 0.05 * bounce);
  EXPECT_NEAR(f_pitch, pitch, 0.05 * pitch);
  EXPECT_NEAR(f_roll, roll, 0.05 * roll);
  EXPECT_NEAR(f_bounce, bounce, 0.01 * bounce);  // in fact within 1 %
}

TEST(FreeBody, EngineBouncePitchRollFrequenciesAsHandCalculation) {
  const double k = 1e6;
  const FreeBodyParams p = engine(k, 0);
  const double sag = -p.mass_kg * kG / (3 * k);
  const double bounce = std::sqrt(3 * k / p.mass_kg) / (2 * kPi);
  const double pitch = std::sqrt(k * (0.25 + 0.25 + 1.0) / p.inertia_kgm2[1]) / (2 * kPi);
  const double roll = std::sqrt(k * (0.16 + 0.16) / p.inertia_kgm2[0]) / (2 * kPi);
  const double f_bounce = measured_hz(p, 2, 0.001, sag);
  const double f_pitch = measured_hz(p, 4, 0.001, sag);
  const double f_roll = measured_hz(p, 5, 0.001, sag);
  std::printf("engine: bounce %.4f Hz (hand %.4f), pitch %.4f (%.4f), roll %.4f (%.4f)\n", f_bounce,
              bounce, f_pitch, pitch, f_roll, roll);
  EXPECT_NEAR(f_bounce, bounce, 0.05 * bounce);
  EXPECT_NEAR(f_pitch, pitch, 0.05 * pitch);
  EXPECT_NEAR(f_roll, roll, 0.05 * roll);
}

TEST(FreeBody, SeatFrequencyAsHandCalculation) {
  const FreeBodyParams p = seat(10100, 0);
  Bench bench(p);
  const double sag = -p.mass_kg * kG / 10100;
  bench.s.seat_y[0](0) += sag + 0.01;
  std::vector<double> x;
  for (int k = 0; k < 8000; ++k) {
    bench.stepper->advance(kH);
    x.push_back(bench.motion().position_m.z() - sag);
  }
  const double hand = std::sqrt(10100 / p.mass_kg) / (2 * kPi);
  const double f = 1.0 / period_s(x, kH);
  std::printf("seat: %.4f Hz (hand %.4f)\n", f, hand);
  EXPECT_NEAR(f, hand, 0.02 * hand);
}

TEST(FreeBody, StaticDeflectionsAreWeightOverStiffness) {
  const double kz = 5e4;
  Bench c(cab(0.8, 0.5, -0.5, {1e5, 8e4, kz}, {2000, 2000, 2000}));
  c.run(30);
  EXPECT_NEAR(c.motion().position_m.z(), -1000 * kG / (4 * kz), 1e-12);
  EXPECT_NEAR(c.motion().angles_rad.norm(), 0, 1e-12);
  Bench e(engine(1e6, 3000));
  e.run(10);
  EXPECT_NEAR(e.motion().position_m.z(), -1200 * kG / 3e6, 1e-12);
  Bench s(seat(10100, 600));
  s.run(30);
  EXPECT_NEAR(s.motion().position_m.z(), -100 * kG / 10100, 1e-12);
}

TEST(FreeBody, EngineTorqueReactsOnTheMounts) {
  Bench e(engine(1e6, 3000));
  const double torque = 800;  // N m, drive torque of the engine
  e.work.engine_torque_nm = torque;
  e.run(10);
  // the mounts' moments about the crankshaft (x) balance the reaction -T on the block
  const Mat3 to_body = body_to_road(e.s.free_body_y[0](3), e.s.free_body_y[0](4),
                                    e.s.free_body_y[0](5))
                           .transpose();  // chassis level and unturned
  double moment_x = 0, force_z = 0;
  for (int i = 0; i < e.body->mount_count(); ++i) {
    const Vec3 f = to_body * e.body->mount_force_now(i).force_n;
    moment_x += e.body->mount(i).body_point.cross(f).x();
    force_z += e.body->mount_force_now(i).force_n.z();
  }
  EXPECT_NEAR(moment_x, torque, 1e-6 * torque);
  EXPECT_NEAR(force_z, 1200 * kG, 1e-6 * 1200 * kG);
  // roll of the block: T / (k sum y^2); and the chassis: +T and the mounts' reactions cancel
  EXPECT_NEAR(e.motion().angles_rad.x(), -torque / (1e6 * 0.32), 0.01 * torque / 3.2e5);
  const Vec6 load = e.body->chassis_load(rigid_pose(e.s.framework_y, e.s.framework_z));
  EXPECT_NEAR(load(3), 0, 1e-6 * torque);
  EXPECT_NEAR(load(2), -1200 * kG, 1e-6 * 1200 * kG);
}

/// Cab roll stiffness of the mounts about the mount plane with the CG h above it: vertical
/// springs sum k b^2 less the pendulum term m g h (its weight on the tilted mounts).
double roll_stiffness(const FreeBodyParams& p, double b, double h) {
  return 4 * p.mounts[0].stiffness_npm[2] * b * b - p.mass_kg * kG * h;
}

TEST(FreeBody, CabRollInSteadyCircleAsMountsPredict) {
  const double b = 0.6, h = 1.0;
  const FreeBodyParams p = cab(0.8, b, -h, {2e6, 2e6, 6e4}, {4000, 4000, 2000});
  Bench bench(p);
  const double v = 15, yaw_rate = 0.2, radius = v / yaw_rate;  // a_y = 3 m/s^2
  auto place_chassis = [&](double t) {
    const double yaw = yaw_rate * t;
    bench.s.framework_y << radius * std::sin(yaw), radius * (1 - std::cos(yaw)), 1.0, yaw, 0, 0;
    bench.s.framework_z << v, 0, 0, 0, 0, yaw_rate;
  };
  place_chassis(0);
  place_free_bodies(bench.p, bench.s);
  double roll = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    place_chassis(k * kH);
    bench.stepper->advance(kH);
    place_chassis((k + 1) * kH);
    if (k >= n - 2000) roll += bench.motion().angles_rad.x() / 2000;
  }
  const double a_y = v * yaw_rate;
  const double predicted = p.mass_kg * a_y * h / roll_stiffness(p, b, h);
  std::printf("cab roll in the circle %.5f rad, predicted %.5f (springs alone %.5f)\n", roll,
              predicted, p.mass_kg * a_y * h / (4 * 6e4 * b * b));
  EXPECT_GT(roll, 0);  // a left turn: the cab leans out, to the right
  EXPECT_NEAR(roll, predicted, 0.10 * predicted);
}

TEST(FreeBody, CabRollPhaseLagUnderHalfHertzSineAsSingleDof) {
  const double b = 0.6, h = 1.0, c_z = 2000;
  const FreeBodyParams p = cab(0.8, b, -h, {2e6, 2e6, 6e4}, {4000, 4000, c_z});
  Bench bench(p);
  const double w = 2 * kPi * 0.5, amp = 3.0;  // a_y = amp sin(w t) of the chassis
  auto place_chassis = [&](double t) {
    bench.s.framework_y << 0, -amp / (w * w) * std::sin(w * t), 1.0, 0, 0, 0;
    bench.s.framework_z << 0, -amp / w * std::cos(w * t), 0, 0, 0, 0;
  };
  place_chassis(0);
  place_free_bodies(bench.p, bench.s);
  double sin_part = 0, cos_part = 0;
  const int settle = 12000, periods = 8000;  // 12 s of transient, then 4 periods
  for (int k = 0; k < settle + periods; ++k) {
    place_chassis(k * kH);
    bench.stepper->advance(kH);
    place_chassis((k + 1) * kH);
    if (k < settle) continue;
    const double t = (k + 1) * kH;
    sin_part += bench.motion().angles_rad.x() * std::sin(w * t) * 2.0 / periods;
    cos_part += bench.motion().angles_rad.x() * std::cos(w * t) * 2.0 / periods;
  }
  // single DOF about the (laterally stiff) mount plane: (I + m h^2) phi'' + C phi' + K phi =
  // m h a_y; lag psi = atan2(C w, K - I w^2)
  const double inertia = p.inertia_kgm2[0] + p.mass_kg * h * h;
  const double damping = 4 * c_z * b * b, stiffness = roll_stiffness(p, b, h);
  const double lag = std::atan2(damping * w, stiffness - inertia * w * w);
  const double gain = p.mass_kg * h * amp / std::hypot(stiffness - inertia * w * w, damping * w);
  const double measured_lag = std::atan2(-cos_part, sin_part);
  std::printf("cab roll lag %.3f deg (single DOF %.3f), amplitude %.5f rad (%.5f)\n",
              measured_lag * 180 / kPi, lag * 180 / kPi, std::hypot(sin_part, cos_part), gain);
  EXPECT_NEAR(measured_lag, lag, 0.10 * lag);
  EXPECT_NEAR(std::hypot(sin_part, cos_part), gain, 0.10 * gain);
}

TEST(FreeBody, AnalyticPartialsMatchFiniteDifferences) {
  for (const bool on_stop : {false, true}) {
    FreeBodyParams p = cab(0.8, 0.5, -0.6, {1e5, 8e4, 5e4}, {3000, 2500, 2000});
    p.mounts[1].orientation_rad = {0.1, -0.2, 0.3};  // one turned mount
    if (on_stop) p.mounts[0].stop_clearance_m = {0.1, 0.1, 0.002};
    Bench bench(p);
    bench.s.framework_y << 3, 2, 1.1, 0.4, 0.02, -0.03;
    bench.s.framework_z << 5, 0.1, 0.02, 0.01, -0.02, 0.1;
    place_free_bodies(bench.p, bench.s);
    Vec6& y = bench.s.free_body_y[0];
    Vec6& z = bench.s.free_body_z[0];
    y += (Vec6() << 0.001, -0.002, -0.004, 0.002, 0.001, -0.003).finished();
    z += (Vec6() << 0.01, -0.02, 0.03, 0.01, -0.01, 0.02).finished();
    Mat6 dy, dz, fy, fz;
    Vec6 wy, wz, q0, q1;
    ASSERT_TRUE(bench.body->force_jacobians(y, z, dy, dz));
    solver::finite_difference_force_jacobians<6>(*bench.body, y, z, fy, fz, wy, wz, q0, q1);
    // the explicit terms (method.md sec. 6): -w x m v and -w x I w
    const Vec3 v = z.head<3>(), w = z.tail<3>();
    const Vec3 iw = Vec3(p.inertia_kgm2[0], p.inertia_kgm2[1], p.inertia_kgm2[2]).cwiseProduct(w);
    Mat6 gyro = Mat6::Zero();
    gyro.block<3, 3>(0, 0) = -p.mass_kg * skew(w);
    gyro.block<3, 3>(0, 3) = p.mass_kg * skew(v);
    gyro.block<3, 3>(3, 3) =
        -skew(w) * Vec3(p.inertia_kgm2[0], p.inertia_kgm2[1], p.inertia_kgm2[2]).asDiagonal() +
        skew(iw);
    fz -= gyro;
    EXPECT_LT((dy - fy).norm(), 0.01 * fy.norm()) << "on_stop " << on_stop << "\n"
                                                  << dy << "\n\n"
                                                  << fy;
    EXPECT_LT((dz - fz).norm(), 0.01 * fz.norm()) << dz << "\n\n" << fz;
    // the chassis side: d(chassis load)/d(chassis coordinates) = dq/ds K
    const Eigen::VectorXd yc = bench.s.framework_y;
    const RigidPose chassis = rigid_pose(yc, bench.s.framework_z);
    Mat6 cs = Mat6::Zero(), cz = Mat6::Zero(), cy;
    bench.body->chassis_jacobians(chassis, cs, cz);
    cy.leftCols<3>() = cs.leftCols<3>() * chassis.rot.transpose();
    cy.rightCols<3>() = cs.rightCols<3>() * body_rates_from_euler_rates(yc(4), yc(5));
    Mat6 fc;
    const Vec6 load0 = bench.body->chassis_load(chassis);
    for (int j = 0; j < 6; ++j) {
      Eigen::VectorXd yp = yc;
      const double d = 1e-7;
      yp(j) += d;
      fc.col(j) = (bench.body->chassis_load(rigid_pose(yp, bench.s.framework_z)) - load0) / d;
    }
    EXPECT_LT((cy - fc).norm(), 0.01 * fc.norm()) << cy << "\n\n" << fc;
  }
}

VehicleParams tractor_with_cab() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-cab.toml");
}

TEST(FreeBody, OnStopFlagAndThroughStopsFault) {
  const VehicleParams p = tractor_with_cab();
  ASSERT_EQ(p.free_bodies.size(), 3u);
  VehicleState s = make_state(p, 4);
  place_free_bodies(p, s);
  const FaultCheck check(p);
  ModelReport r;
  fill_free_body_report(p, s, r);
  EXPECT_EQ(r.body_count, 3);
  EXPECT_EQ(r.bodies[0].on_stop, 0);
  EXPECT_EQ(check.check(s, 0).kind, FaultKind::kNone);
  const double clearance = 0.060, margin = 0.015;   // the cab's vertical stop, config
  s.free_body_y[0](2) -= clearance + 0.5 * margin;  // on its stops
  fill_free_body_report(p, s, r);
  EXPECT_EQ(r.bodies[0].on_stop, 1);
  EXPECT_EQ(r.bodies[1].on_stop, 0);
  EXPECT_NEAR(r.bodies[0].position_m[2], -(clearance + 0.5 * margin), 1e-12);
  EXPECT_EQ(check.check(s, 0).kind, FaultKind::kNone);
  s.free_body_y[0](2) -= margin;  // through them
  const ModelFault f = check.check(s, 1.5);
  EXPECT_EQ(f.kind, FaultKind::kFreeBodyStops);
  EXPECT_EQ(f.index, 0);
  EXPECT_NEAR(f.value, 1.5 * margin, 1e-12);
  EXPECT_EQ(f.limit, margin);
  EXPECT_EQ(fault_kind_name(f.kind), "free_body_stops");
}

void run(VehicleModel& m, Signals& s, double seconds, double steer_rad) {
  const int n = static_cast<int>(std::lround(seconds / m.step_size_s()));
  for (int k = 0; k < n; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = m.time_s() > 1.0 ? steer_rad : 0.0;
    ASSERT_EQ(m.step(s), StepStatus::kOk)
        << "t = " << m.time_s() << ": " << fault_kind_name(m.last_fault().kind) << " "
        << m.last_fault().index << " " << m.last_fault().value;
  }
}

TEST(FreeBody, TractorWithCabRunsAtOneMillisecondWithoutAllocation) {
  const VehicleParams p = tractor_with_cab();
  VehicleModel m(p, kH);
  m.settle(60 / 3.6);
  EXPECT_EQ(m.last_fault().kind, FaultKind::kNone)
      << fault_kind_name(m.last_fault().kind) << " " << m.last_fault().index << " "
      << m.last_fault().value;
  Signals s = test::all_driver_inputs();
  s[Signal::kThrottlePedal] = 0.3;
  ModelReport r;
  m.fill_report(r);
  EXPECT_EQ(r.body_count, 3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(r.bodies[static_cast<std::size_t>(i)].on_stop, 0);
  run(m, s, 0.5, 0.0);
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  run(m, s, 5.5, 1.0);  // a step steer of 1 rad at the steering wheel from t = 1 s
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  m.fill_report(r);
  const double a_y = r.units[0].acceleration_mps2[1];
  std::printf(
      "tractor with cab at %.1f m/s: a_y %.3f m/s^2, cab roll %.5f rad, engine roll "
      "%.5f rad, seat z %.4f m\n",
      r.units[0].velocity_mps[0], a_y, r.bodies[0].orientation_rad[0],
      r.bodies[1].orientation_rad[0], r.bodies[2].position_m[2]);
  EXPECT_GT(std::abs(a_y), 1.0);
  // the cab leans out of the turn relative to the frame, as its mounts predict for the lateral
  // specific force in the frame's axes (a_y less gravity's part in the rolled frame): m h f_y /
  // (4 k_z b^2 - m g h), mounts 1.0 m below its CG at b = 0.5 m, k_z = 80 kN/m (config)
  const auto& o = r.units[0].orientation_rad;
  const double g_y = (body_to_road(o[2], o[1], o[0]).transpose() * Vec3(0, 0, -kG)).y();
  const double cab_m = 1100, h = 1.0;
  const double predicted = cab_m * h * (a_y - g_y) / (4 * 80000 * 0.25 - cab_m * kG * h);
  std::printf("cab roll relative to the frame %.5f rad, the mounts' prediction %.5f\n",
              r.bodies[0].orientation_rad[0], predicted);
  EXPECT_GT(r.bodies[0].orientation_rad[0] * a_y, 0);
  EXPECT_NEAR(r.bodies[0].orientation_rad[0], predicted, 0.10 * std::abs(predicted));
}

TEST(FreeBody, WeightsRestOnTheAxles) {
  // the springs are preloaded for the free bodies too: at rest the chassis stays at its design
  // height and the tire loads add up to the whole weight
  const VehicleParams p = tractor_with_cab();
  VehicleModel m(p, kH);
  m.settle(0);
  double mass = p.chassis.mass_kg, loads = 0;
  for (const auto& a : p.axles) mass += 2 * a.unsprung_mass_kg;
  for (const auto& b : p.free_bodies) mass += b.mass_kg;
  for (int i = 0; i < 6; ++i) loads += m.wheel_load_n(i);
  EXPECT_NEAR(loads, mass * kG, 1e-3 * mass * kG);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(m.state().framework_y(6 + i), 0, 1e-3);
}

}  // namespace
}  // namespace rig::model::vehicle
