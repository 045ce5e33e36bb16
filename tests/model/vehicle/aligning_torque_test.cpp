// The aligning torque on the steering (issue 12, part 6): the vehicle file's caster trail and
// pneumatic-trail tables, the old [steering] trail_m, and the trail falling with the slip.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "io/config/strict_table.h"
#include "io/config/vehicle_file.h"
#include "model/tire/tmeasy_tire.h"

namespace rig::model::vehicle {
namespace {

std::string sedan_text() {
  std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The sedan file with `from` replaced by `to`, written to a temporary file of this process.
std::filesystem::path sedan_with(const std::string& from, const std::string& to) {
  std::string text = sedan_text();
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const auto file = std::filesystem::temp_directory_path() /
                    ("rig_aligning_test_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << text;
  return file;
}

TEST(AligningTorque, VehicleFileReadsCasterAndTrail) {
  const VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  EXPECT_DOUBLE_EQ(p.axles[0].caster_trail_m, 0.020);
  EXPECT_DOUBLE_EQ(p.axles[1].caster_trail_m, 0.0);
  EXPECT_DOUBLE_EQ(p.axles[0].tire.tmeasy.trail.zero_slip_nominal, 0.22);
  EXPECT_DOUBLE_EQ(p.axles[0].tire.tmeasy.trail.end_slip_double, 1.0);
  // an old file: [steering] trail_m is the caster trail of the steered axle that gives none
  const auto old_file = sedan_with("caster_trail_m = 0.020\n", "");
  {
    std::string text = sedan_text();
    text.erase(text.find("caster_trail_m = 0.020\n"), 23);
    text.insert(text.find("tie_rod_stiffness_npm"), "trail_m = 0.04\n");
    std::ofstream(old_file) << text;
  }
  const VehicleParams q = io::config::load_vehicle_file(old_file);
  EXPECT_DOUBLE_EQ(q.axles[0].caster_trail_m, 0.04);
  EXPECT_DOUBLE_EQ(q.axles[1].caster_trail_m, 0.0);  // not steered
  // a bad trail table: file:line and the key
  const auto bad =
      sedan_with("zero_slip = 0.22, end_slip = 0.8", "zero_slip = 0.9, end_slip = 0.8");
  try {
    (void)io::config::load_vehicle_file(bad);
    FAIL() << "no error";
  } catch (const io::config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.filename().string() + ":"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("end_slip"), std::string::npos) << e.what();
  }
  std::filesystem::remove(old_file);
  std::filesystem::remove(bad);
}

// The trail -M_z / F_y of the sedan's front tire at its static load: (n/L)_0 L at zero slip
// (Rill 2011 sec. 3.4.3: L = sqrt(8 r_0 F_z / c_z)), half of it near the peak's slip, zero at
// s_y0 = 1.1 s_yM: the rack force levels off as the front tires near their limit.
TEST(AligningTorque, PneumaticTrailFallsWithTheLateralSlip) {
  const VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  const tire::TmeasyParams& t = p.axles[0].tire.tmeasy;
  const double load_n = 4148.0, r_m = 0.31, v_mps = 20.0;
  const double contact_length_m =
      std::sqrt(8 * t.radius_unloaded_m * load_n / t.vertical_stiffness_npm);
  const double q = load_n / t.nominal_load_n;
  const double n0_over_l =
      t.trail.trail_over_length_nominal +
      (t.trail.trail_over_length_double - t.trail.trail_over_length_nominal) * (q - 1);
  const double sy0 =
      t.trail.zero_slip_nominal + (t.trail.zero_slip_double - t.trail.zero_slip_nominal) * (q - 1);
  const auto trail = [&](double lat_slip) {
    const tire::TireKinematics k{v_mps, -lat_slip * v_mps, v_mps / r_m, r_m};
    return -tire::aligning_torque_nm(t, k, load_n, 1.0);
  };
  std::printf("front trail at 4148 N: %.4f m at s_y 0, %.4f at 0.05, %.4f at 0.1, %.4f at s_y0\n",
              trail(0.0), trail(0.05), trail(0.1), trail(sy0));
  EXPECT_NEAR(trail(0.0), n0_over_l * contact_length_m, 1e-4);
  EXPECT_NEAR(trail(0.0), 0.041, 0.001);  // the old constant trail_m was about this alone
  EXPECT_LT(trail(0.1), 0.6 * trail(0.0));
  EXPECT_NEAR(trail(sy0), 0.0, 1e-4);  // (v_N in the slip: a hair short of s_y0)
}

}  // namespace
}  // namespace rig::model::vehicle
