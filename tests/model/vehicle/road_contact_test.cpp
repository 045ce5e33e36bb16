// The tire's contact on uneven ground (issue 16): TMeasy's four-probe local road plane
// (model/vehicle/local_road_plane.h) against hand values on a tilted plane and on a step, the
// vehicle on a real tilted surface against the same slope as tilted gravity, the road's cost
// (four queries per wheel per step, no allocation), and the outputs.
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/vehicle/local_road_plane.h"
#include "model/vehicle/vehicle_model.h"
#include "model/vehicle/wheel_contact.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

/// z = a x + b y + c, counting its queries.
class TiltedPlane final : public road::Surface {
 public:
  TiltedPlane(double a, double b, double c) : a_(a), b_(b), c_(c) {}
  road::SurfaceHeight height(double x, double y, road::SurfaceHint& hint) const noexcept override {
    ++queries;
    hint.i = 0;
    return {a_ * x + b_ * y + c_, a_, b_};
  }
  mutable long queries = 0;

 private:
  double a_, b_, c_;
};

/// A bar across the road: z = height for x0 <= x < x0 + width, else 0.
class Bar final : public road::Surface {
 public:
  Bar(double x0, double width, double height) : x0_(x0), w_(width), h_(height) {}
  road::SurfaceHeight height(double x, double, road::SurfaceHint&) const noexcept override {
    return {x >= x0_ && x < x0_ + w_ ? h_ : 0.0, 0, 0};
  }

 private:
  double x0_, w_, h_;
};

/// mu = 0.3 for x >= 0, else 1 (a mu jump across the road).
class MuJump final : public road::FrictionField {
 public:
  double mu(double x, double, double base) const noexcept override { return x >= 0 ? 0.3 : base; }
};

road::Road road_over(std::shared_ptr<const road::Surface> s,
                     std::shared_ptr<const road::FrictionField> f = nullptr) {
  road::RoadParams p;
  p.surface = std::move(s);
  p.friction_field = std::move(f);
  return road::Road(p);
}

constexpr ContactProbes kProbes{0.035, 0.06};

TEST(LocalRoadPlane, OnATiltedPlaneIsThatPlane) {
  const double a = 0.1, b = -0.05, c = 0.2;
  auto surface = std::make_shared<TiltedPlane>(a, b, c);
  const road::Road road = road_over(surface);
  ProbeHints hints;
  // any heading: 30 deg from x, tilted up a little (only its horizontal direction counts)
  const Vec3 heading(std::cos(0.5236), std::sin(0.5236), 0.2);
  const LocalRoadPlane plane =
      local_road_plane(road, Vec3(3, 1, 99), heading, kProbes, false, hints);
  const double norm = std::sqrt(1 + a * a + b * b);
  EXPECT_NEAR(plane.normal.x(), -a / norm, 1e-15);
  EXPECT_NEAR(plane.normal.y(), -b / norm, 1e-15);
  EXPECT_NEAR(plane.normal.z(), 1 / norm, 1e-15);
  EXPECT_NEAR(plane.point_m.x(), 3, 1e-15);  // the probes' mean: the static contact point
  EXPECT_NEAR(plane.point_m.y(), 1, 1e-15);
  EXPECT_NEAR(plane.point_m.z(), a * 3 + b * 1 + c, 1e-15);
  EXPECT_EQ(plane.mu, 1.0);
  EXPECT_EQ(surface->queries, 4);
  for (const auto& h : hints) EXPECT_EQ(h.i, 0);  // each probe's own hint was handed on

  // a wheel centre 0.3 m straight above (3, 1): its distance from the plane is 0.3 / norm
  const double r0 = 0.3469;
  const Vec3 centre(3, 1, a * 3 + b * 1 + c + 0.3);
  const WheelContact wc = wheel_contact(plane, Mat3::Identity(), Vec3::Zero(), Vec3(10, 0, 0),
                                        Vec3::Zero(), centre, Vec3::Zero(), Vec3::UnitY(), r0);
  EXPECT_NEAR(wc.penetration_m, r0 - 0.3 / norm, 1e-14);
  // the contact point is on the plane, straight along its normal below the centre
  const Vec3 p = wc.lever_m;
  EXPECT_NEAR(p.z(), a * p.x() + b * p.y() + c, 1e-14);
  EXPECT_NEAR((centre - p).normalized().dot(plane.normal), 1.0, 1e-14);
  // moving along x at 10 m/s up the slope a: the tire is pressed in at 10 a / norm
  EXPECT_NEAR(wc.penetration_rate_mps, 10 * a / norm, 1e-12);
}

TEST(LocalRoadPlane, OnAStepTiltsAsEachProbeClimbsIt) {
  // a 20 mm step at x = 5 m, heading +x, probes 35 mm fore and aft, 60 mm left and right
  const double height = 0.02, dx = kProbes.fore_aft_m, dy = kProbes.lateral_m;
  const road::Road road = road_over(std::make_shared<Bar>(5.0, 100.0, height));
  ProbeHints hints;
  const auto at = [&](double x) {
    return local_road_plane(road, Vec3(x, 0, 0), Vec3::UnitX(), kProbes, false, hints);
  };
  // (Q_fore - Q_aft) x (Q_left - Q_right) = (2 dx, 0, dz) x (0, 2 dy, 0) ~ (-dz, 0, 2 dx)
  const double tilt = std::hypot(height, 2 * dx);
  // 1. only the fore probe up: the plane through H/4, tilted back
  LocalRoadPlane p = at(5.0 - 0.02);
  EXPECT_NEAR(p.point_m.z(), height / 4, 1e-15);
  EXPECT_NEAR(p.normal.x(), -height / tilt, 4e-15);
  EXPECT_NEAR(p.normal.y(), 0, 1e-15);
  EXPECT_NEAR(p.normal.z(), 2 * dx / tilt, 4e-15);
  // a centre 0.3 m above the probes' mean at x: distance 0.3 - H/4 along z, times n_z
  const WheelContact c1 =
      wheel_contact(p, Mat3::Identity(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(),
                    Vec3(5.0 - 0.02, 0, 0.3), Vec3::Zero(), Vec3::UnitY(), 0.3469);
  EXPECT_NEAR(c1.penetration_m, 0.3469 - (0.3 - height / 4) * 2 * dx / tilt, 1e-14);
  // 2. fore and both lateral probes up, the aft one not: through 3H/4, the same tilt
  p = at(5.0 + 0.01);
  EXPECT_NEAR(p.point_m.z(), 3 * height / 4, 1e-15);
  EXPECT_NEAR(p.normal.x(), -height / tilt, 4e-15);
  // 3. all four up: the level plane at H
  p = at(5.0 + dx + 0.001);
  EXPECT_NEAR(p.point_m.z(), height, 1e-15);
  EXPECT_EQ(p.normal, Vec3::UnitZ());
  // 4. across the step (heading +y): the step lies under the fore-aft line, tilts sideways
  p = local_road_plane(road, Vec3(5.0 - 0.02, 0, 0), Vec3::UnitY(), kProbes, false, hints);
  // left = -x side (0), right = +x side (up): (0, 2dx, 0) x (-2dy, 0, -H) ~ (-H, 0, 2 dy) / ...
  const double tilt_y = std::hypot(height, 2 * dy);
  EXPECT_NEAR(p.point_m.z(), height / 4, 1e-15);
  EXPECT_NEAR(p.normal.x(), -height / tilt_y, 4e-15);
  EXPECT_NEAR(p.normal.z(), 2 * dy / tilt_y, 4e-15);
}

TEST(LocalRoadPlane, MuIsTheProbesMeanAndThePlaneSplitStays) {
  road::RoadParams rp;
  rp.surface = std::make_shared<TiltedPlane>(0, 0, 0);
  rp.friction = 0.9;
  rp.friction_right = 0.5;
  rp.friction_field = std::make_shared<MuJump>();
  const road::Road road(rp);
  ProbeHints hints;
  // fore probe on the low-mu side of x = 0: (0.3 + 3 x base) / 4
  LocalRoadPlane p =
      local_road_plane(road, Vec3(-0.01, 0, 0), Vec3::UnitX(), kProbes, false, hints);
  EXPECT_NEAR(p.mu, (0.3 + 3 * 0.9) / 4, 1e-15);
  p = local_road_plane(road, Vec3(-0.01, 0, 0), Vec3::UnitX(), kProbes, true, hints);
  EXPECT_NEAR(p.mu, (0.3 + 3 * 0.5) / 4, 1e-15);  // the right-hand base
  p = local_road_plane(road, Vec3(1, 0, 0), Vec3::UnitX(), kProbes, true, hints);
  EXPECT_NEAR(p.mu, 0.3, 1e-15);
}

VehicleParams sedan() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}

/// Steps with the signals as they are; fails on a bad step.
void run(VehicleModel& m, Signals& s, double seconds) {
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
}

TEST(RoadContact, SedanOnATiltedSurfaceStandsAsOnTheTiltedGravityPlane) {
  // 10 % up in x and 4 % up to the left, once as a real surface, once as the plane road whose
  // grade and bank tilt gravity: in the body's own axes the two are the same situation
  const double grade = 0.10, bank = 0.04;
  VehicleParams on_plane = sedan();
  on_plane.road.grade = grade;
  on_plane.road.bank = bank;
  VehicleParams on_surface = sedan();
  on_surface.road.surface = std::make_shared<TiltedPlane>(grade, bank, 1.5);
  VehicleModel a(on_plane, 1e-3), b(on_surface, 1e-3);
  // the start is on the surface's height and slope
  const auto& yb = b.state().framework_y;
  EXPECT_NEAR(yb(4), -std::atan(grade), 1e-12);  // nose up
  EXPECT_NEAR(yb(5), std::asin(bank / std::sqrt(1 + grade * grade + bank * bank)), 1e-12);
  EXPECT_NEAR(yb(2),
              1.5 + on_surface.chassis.cg_height_m * std::sqrt(1 + grade * grade + bank * bank),
              1e-12);
  // (the gravity plane tilts by the grade, then the bank; the surface's normal is (-a, -b, 1):
  // the two differ by (a b)^2 / 2 ~ 1e-5 relative, well below the tolerances)
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;
  s[Signal::kBrakePressureFront] = 3e6;
  s[Signal::kBrakePressureRear] = 3e6;
  a.settle(0);
  b.settle(0);
  run(a, s, 1.0);
  run(b, s, 1.0);
  double total_a = 0, total_b = 0;
  for (int i = 0; i < 4; ++i) {
    total_a += a.wheel_load_n(i);
    total_b += b.wheel_load_n(i);
    std::printf("wheel %d: tilted gravity %.1f N, tilted surface %.1f N\n", i, a.wheel_load_n(i),
                b.wheel_load_n(i));
  }
  const double mg = a.framework().total_mass_kg() * 9.81;
  // normal loads: m g over the surface's normal factor (m g n_z) in both
  EXPECT_NEAR(total_b, mg / std::sqrt(1 + grade * grade + bank * bank), 0.003 * mg);
  EXPECT_NEAR(total_a, total_b, 0.003 * mg);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(a.wheel_load_n(i), b.wheel_load_n(i), 0.01 * mg / 4);
  // the outputs: the road under each wheel is the surface, its normal and mu
  ModelReport r;
  b.fill_report(r);
  const double norm = std::sqrt(1 + grade * grade + bank * bank);
  for (int i = 0; i < 4; ++i) {
    const WheelReport& w = r.units[0].wheels[static_cast<std::size_t>(i)];
    EXPECT_NEAR(w.road_normal_x, -grade / norm, 1e-12);
    EXPECT_NEAR(w.road_normal_y, -bank / norm, 1e-12);
    EXPECT_NEAR(w.road_normal_z, 1 / norm, 1e-12);
    EXPECT_EQ(w.road_mu, 1.0);
  }
  // the wheel's road height: the surface's under the wheel (at the probes' centre, the static
  // contact point, r0 below the centre in the wheel plane); the contact point, the centre's foot
  // on the local plane, lies on the surface too
  const auto& y = b.state().framework_y;
  const Mat3 rot = body_to_road(y(3), y(4), y(5));
  for (int i = 0; i < 4; ++i) {
    const Vec3 under = b.workspace().wheels[static_cast<std::size_t>(i)].road.point_m;
    const Vec3 centre = y.head<3>() + rot * b.framework().wheel_centre(i, y(6 + i));
    const WheelReport& w = r.units[0].wheels[static_cast<std::size_t>(i)];
    EXPECT_NEAR(w.road_z_m, grade * under.x() + bank * under.y() + 1.5, 1e-12);
    // r0 below the centre in the wheel plane: off the vertical by the roll (and camber) only
    EXPECT_LT(std::hypot(under.x() - centre.x(), under.y() - centre.y()),
              0.316 * (std::abs(std::sin(y(5))) + 0.02));
    const WheelContact c = b.framework().contact(y, b.state().framework_z, i);
    const Vec3 contact = y.head<3>() + rot * c.lever_m;
    EXPECT_NEAR(contact.z(), grade * contact.x() + bank * contact.y() + 1.5, 1e-12);
  }
}

TEST(RoadContact, FourQueriesPerWheelPerStepAndNoAllocation) {
  VehicleParams p = sedan();
  auto surface = std::make_shared<TiltedPlane>(0.02, 0.01, 0.0);
  p.road.surface = surface;
  p.road.friction_field = std::make_shared<MuJump>();  // mu 0.3 from x = 0 on
  VehicleModel m(p, 1e-3);
  m.settle(10.0);
  Signals s = test::all_driver_inputs();
  s[Signal::kThrottlePedal] = 0.3;
  s[Signal::kSteeringWheelAngleCmd] = 0.2;
  run(m, s, 0.2);  // first steps outside the counter
  const long before = surface->queries;
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  run(m, s, 2.0);
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  // four probes per wheel, and the fault check's body points (8: the default box) per step
  EXPECT_EQ(surface->queries - before, 2000 * (4 * 4 + 8));
  ModelReport r;
  m.fill_report(r);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(r.units[0].wheels[static_cast<std::size_t>(i)].road_mu, 0.3);
}

TEST(RoadContact, ThePlaneRoadReportsItsLevelPlaneAndSplitMu) {
  VehicleParams p = sedan();
  p.road.grade = 0.1;  // tilts gravity, not the road frame's plane
  p.road.friction = 0.8;
  p.road.friction_right = 0.4;
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  run(m, s, 0.1);
  ModelReport r;
  m.fill_report(r);
  for (int i = 0; i < 4; ++i) {
    const WheelReport& w = r.units[0].wheels[static_cast<std::size_t>(i)];
    EXPECT_EQ(w.road_z_m, 0.0);
    EXPECT_EQ(w.road_normal_x, 0.0);
    EXPECT_EQ(w.road_normal_y, 0.0);
    EXPECT_EQ(w.road_normal_z, 1.0);
    EXPECT_EQ(w.road_mu, i % 2 == 1 ? 0.4 : 0.8);
  }
}

}  // namespace
}  // namespace rig::model::vehicle
