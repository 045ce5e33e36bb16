// The KPI room (rig/kpi): the computations on series whose answers are known by hand, the strict
// [[kpi]] parsing, and the summary's `kpis` JSON shape.
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/config_error.h"
#include "rig/kpi/kpi_recorder.h"
#include "rig/kpi/kpi_spec.h"
#include "rig/kpi/steering_kpis.h"
#include "tests/support/config_error_of.h"

namespace rig::kpi {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SteeringKpis, PeakAbsIsTheLargestMagnitude) {
  const std::vector<double> y{0.5, -3.25, 2.0, 1.0};
  EXPECT_DOUBLE_EQ(peak_abs(y), 3.25);
  EXPECT_TRUE(std::isnan(peak_abs({})));
}

// An ellipse x = a cos t, y = b sin t, two turns: x falls through 0 at t = pi/2 (y = +b) and
// rises through it at 3 pi/2 (y = -b): the width at x = 0 is 2 b; likewise x versus y at y = 0
// gives 2 a.
TEST(SteeringKpis, LoopWidthOfAnEllipseIsItsAxis) {
  const double a = 2.0, b = 0.75;
  std::vector<double> x, y;
  for (int i = 0; i <= 2000; ++i) {
    const double t = 4 * kPi * i / 2000.0 + 0.1;
    x.push_back(a * std::cos(t));
    y.push_back(b * std::sin(t));
  }
  EXPECT_NEAR(loop_width(x, y, 0.0), 2 * b, 1e-4);
  EXPECT_NEAR(loop_width(y, x, 0.0), 2 * a, 1e-3);
  // at x = a/2 the ellipse's y is +-b sqrt(1 - 1/4)
  EXPECT_NEAR(loop_width(x, y, a / 2), 2 * b * std::sqrt(0.75), 1e-4);
  const std::vector<double> rising{-1.0, 0.0, 1.0};
  EXPECT_TRUE(std::isnan(loop_width(rising, rising, 0.5)));  // never falls through 0.5
}

// y = 3 x + 0.4 sign(dx/dt) (a loop of constant width) over a sine of x: the fit over both
// branches gives the slope 3, not the width.
TEST(SteeringKpis, GradientOfALoopIsItsMeanSlope) {
  std::vector<double> x, y;
  for (int i = 0; i < 4000; ++i) {
    const double t = 2 * kPi * i / 1000.0;
    x.push_back(std::sin(t));
    y.push_back(3.0 * x.back() + (std::cos(t) >= 0 ? 0.4 : -0.4));
  }
  EXPECT_NEAR(gradient(x, y, 0.0, 0.2), 3.0, 1e-3);
  // a parabola y = x^2: slope 2 x0 at x0
  std::vector<double> px, py;
  for (int i = -1000; i <= 1000; ++i) {
    px.push_back(i / 500.0);
    py.push_back(px.back() * px.back());
  }
  EXPECT_NEAR(gradient(px, py, 1.0, 0.101), 2.0, 1e-9);  // samples 0.9..1.1, symmetric
  EXPECT_TRUE(std::isnan(gradient(px, py, 5.0, 0.1)));   // no sample in the band
}

TEST(SteeringKpis, ResidualFractionOfADecay) {
  std::vector<double> t, y;
  for (int i = 0; i <= 5000; ++i) {
    t.push_back(i * 1e-3);
    y.push_back(i * 1e-3 < 1.0 ? 1.5 : 1.5 * std::exp(-(i * 1e-3 - 1.0) / 0.8));
  }
  EXPECT_NEAR(residual_fraction(t, y, 1.0, 4.0), std::exp(-3.0 / 0.8), 1e-9);
}

std::vector<KpiSpec> parse(const std::string& text) {
  const toml::table doc = toml::parse(text);
  io::config::StrictTable top(doc, "m.toml", "top level");
  auto specs = read_kpis(top, io::signals::Catalogue::two_axle_vehicle());
  return specs;
}

std::string message_of(const std::function<void()>& f) { return test::config_error_of(f); }

TEST(KpiSpec, ReadsEveryKeyAndDerivesUnits) {
  const auto specs = parse(R"(
[[kpi]]
name = "g0"
kind = "gradient"
signal = "torsion_bar_torque_nm"
versus = "lateral_accel_mps2"
at = 0.5
band = 0.2
from_s = 7
to_s = 20
min = 0.1
[[kpi]]
name = "peak"
kind = "peak_abs"
signal = "rack_force_n"
max = 5000
)");
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].kind, KpiKind::kGradient);
  EXPECT_EQ(specs[0].unit, "N m/(m/s^2)");
  EXPECT_DOUBLE_EQ(specs[0].at, 0.5);
  EXPECT_DOUBLE_EQ(specs[0].band, 0.2);
  EXPECT_DOUBLE_EQ(specs[0].from_s, 7.0);
  EXPECT_EQ(specs[0].min, 0.1);
  EXPECT_FALSE(specs[0].max);
  EXPECT_EQ(specs[1].unit, "N");
  EXPECT_EQ(specs[1].max, 5000.0);
}

TEST(KpiSpec, BadInputNamesTheKey) {
  const std::string head = "[[kpi]]\nname = \"k\"\n";
  EXPECT_NE(
      message_of([&] { parse(head + "signal = \"rack_force_n\"\n"); }).find("'kind' is required"),
      std::string::npos);
  EXPECT_NE(message_of([&] {
              parse(head + "kind = \"peak\"\nsignal = \"rack_force_n\"\n");
            }).find("unknown value 'peak'"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              parse(head + "kind = \"gradient\"\nsignal = \"rack_force_n\"\n");
            }).find("needs 'versus'"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              parse(head + "kind = \"peak_abs\"\nsignal = \"rack_force_n\"\nmin = 2\nmax = 1\n");
            }).find("'min' must not exceed 'max'"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              parse(head + "kind = \"peak_abs\"\nsignal = \"rack_forse_n\"\n");
            }).find("rack_force_n"),  // the closest name
            std::string::npos);
  EXPECT_NE(message_of([&] {
              parse(head + "kind = \"peak_abs\"\nsignal = \"rack_force_n\"\nmax_n = 3\n");
            }).find("max_n"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              parse(head + "kind = \"residual_fraction\"\nsignal = \"rack_force_n\"\nto_s = 3\n");
            }).find("needs 'from_s'"),
            std::string::npos);
  const std::string one = head + "kind = \"peak_abs\"\nsignal = \"rack_force_n\"\n";
  EXPECT_NE(message_of([&] { parse(one + one); }).find("duplicate kpi name 'k'"),
            std::string::npos);
}

TEST(KpiJson, ListsNameValueUnitLimitsPassed) {
  KpiSpec bounded;
  bounded.name = "peak";
  bounded.unit = "N";
  bounded.max = 10.0;
  Series s;
  s.y = {1.0, -12.0};
  const KpiResult over = evaluate(bounded, s);
  EXPECT_DOUBLE_EQ(over.value, 12.0);
  EXPECT_FALSE(over.passed);
  KpiSpec free = bounded;
  free.name = "free";
  free.max.reset();
  free.min = -1.0;
  const KpiResult ok = evaluate(free, s);
  EXPECT_TRUE(ok.passed);
  Series empty;
  const KpiResult none = evaluate(free, empty);
  EXPECT_FALSE(none.passed);  // no value: not passed, null in JSON
  EXPECT_EQ(kpis_json({over, ok, none}),
            "[\n    {\"name\": \"peak\", \"value\": 12, \"unit\": \"N\", \"limits\": {\"min\": "
            "null, \"max\": 10}, \"passed\": false},\n"
            "    {\"name\": \"free\", \"value\": 12, \"unit\": \"N\", \"limits\": {\"min\": -1, "
            "\"max\": null}, \"passed\": true},\n"
            "    {\"name\": \"free\", \"value\": null, \"unit\": \"N\", \"limits\": {\"min\": -1, "
            "\"max\": null}, \"passed\": false}\n  ]");
  EXPECT_EQ(kpis_json({}), "[]");
}

}  // namespace
}  // namespace rig::kpi
