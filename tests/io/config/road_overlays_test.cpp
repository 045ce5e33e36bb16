// [[road.obstacle]] and [[road.friction_zone]]: the loaders build the model objects the keys
// describe (heights and mu at known points), and refuse bad keys with `file:line:`.
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>

#include <gtest/gtest.h>

#include "io/config/config_error.h"
#include "io/config/road_friction_zones.h"
#include "io/config/road_obstacles.h"

namespace rig::io::config {
namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

/// Loads `text` as a run configuration and hands its [road] table to `use`.
void with_road(const std::string& name, const std::string& text,
               const std::function<void(StrictTable&)>& use) {
  const auto file = write_file(name, text);
  const toml::table root = load_toml_file(file);
  StrictTable top(root, file, "top");
  StrictTable road = top.table("road");
  use(road);
}

std::string message_of(const std::string& name, const std::string& text) {
  try {
    with_road(name, text, [](StrictTable& road) {
      (void)load_obstacles(road);
      (void)load_friction_zones(road);
      road.finish();
    });
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RoadOverlays, ObstaclesAreBuiltAsTheKeysSay) {
  with_road(
      "obstacles.toml",
      "[road]\n"
      "[[road.obstacle]]\nkind = \"cleat\"\ns_m = 20.0\nlength_m = 0.02\nheight_m = 0.02\n"
      "[[road.obstacle]]\nkind = \"bump\"\nx_m = 1.0\ny_m = 2.0\nheading_rad = 1.5707963267948966\n"
      "length_m = 4.0\nwidth_m = 3.0\nheight_m = 0.1\n"
      "[[road.obstacle]]\nkind = \"ramp\"\ns_m = 50.0\nlength_m = 10.0\nrise_m = 2.0\n"
      "height_m = 0.2\n"
      "[[road.obstacle]]\nkind = \"sine\"\ns_m = 100.0\nlength_m = 6.0\nwavelength_m = 3.0\n"
      "height_m = 0.05\n"
      "[[road.obstacle]]\nkind = \"pothole\"\ns_m = 200.0\nlength_m = 0.4\nwidth_m = 0.5\n"
      "height_m = -0.06\n",
      [](StrictTable& road) {
        const auto obstacles = load_obstacles(road);
        road.finish();
        ASSERT_NE(obstacles, nullptr);
        ASSERT_EQ(obstacles->obstacles().size(), 5u);
        model::road::SurfaceHint hint;
        auto z = [&](double x, double y) { return obstacles->height(x, y, hint).z_m; };
        EXPECT_EQ(z(20.01, 100.0), 0.02);         // the cleat spans the road
        EXPECT_NEAR(z(1.2, 4.0), 0.1, 1e-15);     // the bump's crest, 2 m up +y
        EXPECT_EQ(z(2.6, 4.0), 0.0);              // beside it (width 3 m)
        EXPECT_NEAR(z(51.0, 0.0), 0.1, 1e-15);    // half way up the ramp
        EXPECT_NEAR(z(58.0, 0.0), 0.2, 1e-15);    // no fall: flat to its end
        EXPECT_NEAR(z(101.5, 0.0), 0.05, 1e-15);  // a sine crest
        EXPECT_EQ(z(200.2, 0.25), -0.06);         // the pothole's wall
        EXPECT_EQ(z(200.2, 0.26), 0.0);
      });
}

TEST(RoadOverlays, FrictionZonesAreBuiltAsTheKeysSay) {
  with_road("zones.toml",
            "[road]\n"
            "[[road.friction_zone]]\nmu = 0.2\nv_to_m = 0.0\n"
            "[[road.friction_zone]]\nmu = 0.9\ns_from_m = 100.0\n"
            "[[road.friction_zone]]\nmu = 0.5\npoints_m = [[10.0, -2.0], [14.0, -2.0], "
            "[14.0, 2.0], [10.0, 2.0]]\n",
            [](StrictTable& road) {
              const auto zones = load_friction_zones(road);
              road.finish();
              ASSERT_NE(zones, nullptr);
              EXPECT_EQ(zones->size(), 3u);
              EXPECT_EQ(zones->mu(5, -1, 1.0), 0.2);    // split: right
              EXPECT_EQ(zones->mu(5, 1, 1.0), 1.0);     // left: the road's
              EXPECT_EQ(zones->mu(150, -1, 1.0), 0.9);  // the jump wins over the split
              EXPECT_EQ(zones->mu(12, -1, 1.0), 0.5);   // the patch wins over both
            });
}

TEST(RoadOverlays, NoneGiveNull) {
  with_road("none.toml", "[road]\nkind = \"plane\"\n", [](StrictTable& road) {
    EXPECT_EQ(load_obstacles(road), nullptr);
    EXPECT_EQ(load_friction_zones(road), nullptr);
  });
}

TEST(RoadOverlays, BadKeysAreErrorsAtTheirLine) {
  struct Case {
    std::string name, text, message;  // message after "FILE:"
  };
  const std::string o = "[road]\n[[road.obstacle]]\n";
  const std::string z = "[road]\n[[road.friction_zone]]\n";
  const std::vector<Case> cases{
      {"no_kind", o + "length_m = 1.0\nheight_m = 0.1\n",
       "2: [road].obstacle[0] kind: missing required key (cleat, pothole, ramp, bump or sine)"},
      {"bad_kind", o + "kind = \"speedbump\"\nlength_m = 1.0\nheight_m = 0.1\n",
       "3: [road].obstacle[0] kind: unknown value 'speedbump' (expected one of: cleat, pothole, "
       "ramp, bump, sine)"},
      {"cleat_down", o + "kind = \"cleat\"\nlength_m = 1.0\nheight_m = -0.1\n",
       "5: [road].obstacle[0] height_m: a cleat stands up: must be > 0 (a hole is kind = "
       "\"pothole\")"},
      {"pothole_up", o + "kind = \"pothole\"\nlength_m = 1.0\nheight_m = 0.1\n",
       "5: [road].obstacle[0] height_m: a pothole goes down: must be < 0 (its depth)"},
      {"zero_height", o + "kind = \"bump\"\nlength_m = 1.0\nheight_m = 0.0\n",
       "5: [road].obstacle[0] height_m: must not be 0"},
      {"nan_length", o + "kind = \"bump\"\nlength_m = nan\nheight_m = 0.1\n",
       "4: [road].obstacle[0] length_m: value nan out of range [0.0001, 100000]"},
      {"foreign_key", o + "kind = \"cleat\"\nlength_m = 1.0\nheight_m = 0.1\nwavelength_m = 2\n",
       "6: [road].obstacle[0] wavelength_m: is a key of kind \"sine\", not of \"cleat\""},
      {"ramp_too_long",
       o + "kind = \"ramp\"\nlength_m = 1.0\nheight_m = 0.1\nrise_m = 0.7\n"
           "fall_m = 0.5\n",
       "7: [road].obstacle[0] fall_m: rise_m + fall_m = 1.200000 m is longer than length_m"},
      {"half_wave", o + "kind = \"sine\"\nlength_m = 5.0\nheight_m = 0.1\nwavelength_m = 2.0\n",
       "4: [road].obstacle[0] length_m: must be a whole number of wavelengths (2.500000 of "
       "wavelength_m)"},
      {"unknown_key", o + "kind = \"bump\"\nlength_m = 1.0\nheight_m = 0.1\nhieght_m = 0.1\n",
       "6: [road].obstacle[0]: unknown key 'hieght_m'"},
      {"too_high", o + "kind = \"bump\"\nlength_m = 1.0\nheight_m = 2.0\n",
       "5: [road].obstacle[0] height_m: value 2 out of range [-1, 1]"},
      {"mu_negative", z + "mu = -0.1\n",
       "3: [road].friction_zone[0] mu: value -0.1 out of range [0, 10]"},
      {"no_mu", z + "s_from_m = 1.0\n", "2: [road].friction_zone[0] mu: missing required key"},
      {"empty_range", z + "mu = 0.5\ns_from_m = 10.0\ns_to_m = 5.0\n",
       "5: [road].friction_zone[0] s_to_m: s_from_m must be below s_to_m (an empty zone)"},
      {"both", z + "mu = 0.5\nx_m = 1.0\npoints_m = [[0, 0], [1, 0], [1, 1]]\n",
       "4: [road].friction_zone[0] x_m: a zone is a polygon (points_m) or a rectangle along a "
       "line, not both"},
      {"two_corners", z + "mu = 0.5\npoints_m = [[0, 0], [1, 0]]\n",
       "4: [road].friction_zone[0] points_m: 2 corners: a polygon needs 3 or more"},
      {"bad_corner", z + "mu = 0.5\npoints_m = [[0, 0], [1, 0, 2], [1, 1]]\n",
       "4: [road].friction_zone[0] points_m: expected an array of [2 numbers]"},
      {"inf_corner", z + "mu = 0.5\npoints_m = [[0, 0], [inf, 0], [1, 1]]\n",
       "4: [road].friction_zone[0] points_m: a corner is not finite or beyond 1e7 m"},
      {"not_tables", "[road]\nobstacle = 3\n", "2: [road] obstacle: expected an array of tables"},
  };
  for (const Case& c : cases) {
    const std::string file =
        (std::filesystem::temp_directory_path() / ("ov_" + c.name + ".toml")).string();
    EXPECT_EQ(message_of("ov_" + c.name + ".toml", c.text), file + ":" + c.message) << c.name;
  }
}

TEST(RoadOverlays, ListsAreBounded) {
  std::string text = "[road]\n";
  for (std::size_t i = 0; i <= kMaxObstacles; ++i)
    text += "[[road.obstacle]]\nkind = \"bump\"\nlength_m = 1.0\nheight_m = 0.1\n";
  const std::string message = message_of("ov_many.toml", text);
  EXPECT_NE(message.find("[road] obstacle: 1001 entries, at most 1000"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace rig::io::config
