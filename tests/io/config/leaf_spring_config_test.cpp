// [axle.leaf_spring] (issue 17 item 2): the van's leaf file gives the constant the model tests
// use, and bad keys or values are `file:line:` errors naming the key.
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/config_error.h"
#include "io/config/leaf_spring_config.h"
#include "tests/model/vehicle/leaf_spring/van_leaf_params.h"

namespace rig::io::config {
namespace {

const std::filesystem::path kVanLeaf =
    std::filesystem::path(RIG_SOURCE_DIR) / "tests/model/vehicle/leaf_spring/van_leaf.toml";

std::string van_leaf_text() {
  std::ifstream in(kVanLeaf);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The van's file with `from` replaced by `to`; the error message of loading it.
std::string message_with(const std::string& from, const std::string& to) {
  std::string text = van_leaf_text();
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const auto path = std::filesystem::temp_directory_path() / "leaf_spring_config_test.toml";
  std::ofstream(path) << text;
  try {
    (void)load_leaf_spring_file(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LeafSpringConfig, TheVansFileIsTheTestsConstant) {
  const LeafSpringConfig c = load_leaf_spring_file(kVanLeaf);
  const auto p = rig::test::van_rear_leaf();
  EXPECT_EQ(c.params.eye_to_eye_m, p.eye_to_eye_m);
  EXPECT_EQ(c.params.seat_from_front_eye_m, p.seat_from_front_eye_m);
  EXPECT_EQ(c.params.free_camber_m, p.free_camber_m);
  EXPECT_EQ(c.params.seat_length_m, p.seat_length_m);
  EXPECT_EQ(c.params.leaf_above_axle_m, p.leaf_above_axle_m);
  EXPECT_EQ(c.params.front_bending_stiffness_nm2, p.front_bending_stiffness_nm2);
  EXPECT_EQ(c.params.rear_bending_stiffness_nm2, p.rear_bending_stiffness_nm2);
  EXPECT_EQ(c.params.shackle_length_m, p.shackle_length_m);
  EXPECT_EQ(c.params.shackle_angle_free_rad, p.shackle_angle_free_rad);
  EXPECT_EQ(c.params.eye_bushing_x_npm, p.eye_bushing_x_npm);
  EXPECT_EQ(c.params.eye_bushing_z_npm, p.eye_bushing_z_npm);
  EXPECT_EQ(c.params.max_iterations, 4);  // the default
  EXPECT_EQ(c.spring_track_m, rig::test::kVanSpringTrackM);
}

// As the axle loader calls it: on an [[axle]] table, with or without a leaf spring.
TEST(LeafSpringConfig, TheAxleLoadersCall) {
  const auto path = std::filesystem::temp_directory_path() / "leaf_spring_axles.toml";
  std::ofstream(path) << "[[axle]]\nx_m = 1.5\n[[axle]]\nx_m = -1.8\n"
                      << van_leaf_text().substr(van_leaf_text().find("[axle.leaf_spring]"));
  const toml::table root = load_toml_file(path);
  StrictTable top(root, path, "top");
  std::vector<StrictTable> axles = top.tables("axle");
  ASSERT_EQ(axles.size(), 2U);
  EXPECT_FALSE(read_axle_leaf_spring(axles[0]).has_value());
  const auto rear = read_axle_leaf_spring(axles[1]);
  ASSERT_TRUE(rear.has_value());
  EXPECT_EQ(rear->params.free_camber_m, 0.10);
  EXPECT_EQ(rear->spring_track_m, rig::test::kVanSpringTrackM);
}

TEST(LeafSpringConfig, SolverKeysAreOptionalAndChecked) {
  EXPECT_EQ(message_with("spring_track_m = 1.10", "spring_track_m = 1.10\nmax_iterations = 3"),
            "(no error)");
  const std::string m =
      message_with("spring_track_m = 1.10", "spring_track_m = 1.10\nmax_iterations = 4.0");
  EXPECT_NE(m.find("leaf_spring_config_test.toml:17:"), std::string::npos) << m;
  EXPECT_NE(m.find("max_iterations"), std::string::npos) << m;
}

TEST(LeafSpringConfig, BadValuesNameFileLineAndKey) {
  std::string m = message_with("free_camber_m = 0.10", "free_camber_m = nan");
  EXPECT_NE(m.find("leaf_spring_config_test.toml:7:"), std::string::npos) << m;
  EXPECT_NE(m.find("[axle.leaf_spring] free_camber_m"), std::string::npos) << m;
  m = message_with("free_camber_m = 0.10", "free_camber_m = 0.30");
  EXPECT_NE(m.find(":7:"), std::string::npos) << m;
  EXPECT_NE(m.find("at most half the shorter arm"), std::string::npos) << m;
  m = message_with("seat_from_front_eye_m = 0.60", "seat_from_front_eye_m = 1.38");
  EXPECT_NE(m.find(":6:"), std::string::npos) << m;
  EXPECT_NE(m.find("longer than 0.05 m"), std::string::npos) << m;
  m = message_with("shackle_length_m = 0.12", "shackle_length_m = -0.12");
  EXPECT_NE(m.find(":12:"), std::string::npos) << m;
  m = message_with("eye_bushing_x_npm = 1.0e7", "eye_bushing_x_n = 1.0e7");
  EXPECT_NE(m.find(":4: [axle.leaf_spring] eye_bushing_x_npm: missing required key"),
            std::string::npos)
      << m;
  m = message_with("eye_bushing_z_npm = 1.0e7", "eye_bushing_z_npm = 1.0e7\neye_bushing_y_npm = 1");
  EXPECT_NE(m.find(":16: [axle.leaf_spring]: unknown key 'eye_bushing_y_npm'"), std::string::npos)
      << m;
  m = message_with("spring_track_m = 1.10", "");
  EXPECT_NE(m.find("spring_track_m"), std::string::npos) << m;
}

}  // namespace
}  // namespace rig::io::config
