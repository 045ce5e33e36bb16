// --set KEY=VALUE (io/config/overrides.h): the key path scheme, the values put into a parsed
// file (with their "--set" source, named by StrictTable's errors), and the malformed paths.

#include "io/config/overrides.h"

#include <gtest/gtest.h>

#include <string>

#include "io/config/config_error.h"
#include "io/config/strict_table.h"
#include "tests/support/config_error_of.h"

namespace rig::io::config {
namespace {

std::string message_of(auto&& f) { return test::config_error_of(f); }

toml::table patched(const std::string& text, const std::vector<std::string>& sets) {
  toml::table doc = toml::parse(std::string_view(text), std::string("file.toml"));
  apply_overrides(Overrides(sets).of_file(0), doc, "file.toml");
  return doc;
}

TEST(Overrides, KeyPathsNameTheFileAndTheKey) {
  const Override a = parse_override("vehicle.chassis.mass_kg=1600");
  EXPECT_EQ(a.file, 1);
  EXPECT_TRUE(a.vehicle_prefix);
  ASSERT_EQ(a.path.size(), 2u);
  EXPECT_EQ(a.path[0].name, "chassis");
  EXPECT_EQ(a.path[1].name, "mass_kg");
  EXPECT_EQ(a.value, "1600");
  const Override b = parse_override("unit2.axle[1].track_m=1.6");
  EXPECT_EQ(b.file, 2);
  EXPECT_FALSE(b.vehicle_prefix);
  ASSERT_EQ(b.path.size(), 2u);
  EXPECT_EQ(b.path[0].name, "axle");
  EXPECT_EQ(b.path[0].index, 1u);
  const Override c = parse_override("rig.duration_s=2=3");  // the first '=' splits
  EXPECT_EQ(c.file, 0);
  EXPECT_EQ(c.key, "rig.duration_s");
  EXPECT_EQ(c.value, "2=3");
  EXPECT_EQ(parse_override("model.unit_count=1").file, 0);  // "unit_count" is not unit<k>
}

TEST(Overrides, MalformedPathsAreNamed) {
  EXPECT_NE(message_of([] { parse_override("rig.duration_s"); })
                .find("--set rig.duration_s: "
                      "expected KEY=VALUE"),
            std::string::npos);
  EXPECT_NE(message_of([] { parse_override("duration_s=1"); }).find("is not SECTION.KEY"),
            std::string::npos);
  EXPECT_NE(message_of([] { parse_override("vehicle=x"); }).find("names a file, not a key"),
            std::string::npos);
  EXPECT_NE(message_of([] { parse_override("rig..x=1"); }).find("not a bare TOML key"),
            std::string::npos);
  EXPECT_NE(message_of([] { parse_override("kpi[x].max=1"); }).find("NAME[i]"), std::string::npos);
  EXPECT_NE(message_of([] { parse_override("unit5.chassis.mass_kg=1"); }).find("at most 4 units"),
            std::string::npos);
}

TEST(Overrides, ValuesAreTomlOrElseText) {
  const toml::table t = patched("[rig]\nduration_s = 20.0\n[driver]\npath = \"straight\"\n",
                                {"rig.duration_s=8", "driver.path=circle", "rig.offline=true",
                                 "rig.list=[1, 2]", "rig.text=\"a \\\"b\\\"\"", "rig.bad=1 2"});
  EXPECT_EQ(t["rig"]["duration_s"].value_exact<int64_t>(), 8);
  EXPECT_EQ(t["driver"]["path"].value_exact<std::string>(), "circle");
  EXPECT_EQ(t["rig"]["offline"].value_exact<bool>(), true);
  EXPECT_EQ(t["rig"]["list"].as_array()->size(), 2u);
  EXPECT_EQ(t["rig"]["text"].value_exact<std::string>(), "a \"b\"");
  EXPECT_EQ(t["rig"]["bad"].value_exact<std::string>(), "1 2");  // not TOML: a string
}

TEST(Overrides, MissingTablesAreCreatedWithTheSetSource) {
  const toml::table t = patched("[rig]\n", {"road.kind=crg", "lcm.channel_prefix=A_"});
  EXPECT_EQ(t["road"]["kind"].value_exact<std::string>(), "crg");
  // the created table and its key are located at the --set, not at a line of file.toml
  StrictTable top(t, "file.toml", "top level");
  EXPECT_EQ(top.location("road"), "--set road.kind=crg");
  StrictTable lcm = top.table("lcm");
  EXPECT_EQ(lcm.error("channel_prefix", "bad").what(),
            std::string("--set lcm.channel_prefix=A_: [lcm] channel_prefix: bad"));
  // a key of the file keeps its line
  EXPECT_EQ(top.location("rig"), "file.toml:1");
}

TEST(Overrides, ArraysOfTablesAreIndexedFromZero) {
  const std::string file = "[[axle]]\ntrack_m = 1.5\n[[axle]]\ntrack_m = 1.6\nlist = [1, 2, 3]\n";
  const toml::table t = patched(file, {"axle[1].track_m=1.7", "axle[1].list[2]=9"});
  EXPECT_EQ(t["axle"][0]["track_m"].value_exact<double>(), 1.5);
  EXPECT_EQ(t["axle"][1]["track_m"].value_exact<double>(), 1.7);
  EXPECT_EQ(t["axle"][1]["list"][2].value_exact<int64_t>(), 9);
  EXPECT_NE(message_of([&] {
              patched(file, {"axle[2].track_m=1"});
            }).find("--set axle[2].track_m=1: 'axle[2]': axle in file.toml has 2 entries"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              patched(file, {"axle[0].track_m.x=1"});
            }).find("'axle[0].track_m' in file.toml is a number, not a table"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              patched(file, {"axle[0].track_m[0]=1"});
            }).find("is a number, not an array to index"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              patched(file, {"wheel[0].x=1"});
            }).find("'wheel' does not exist, so it has no entry [0]"),
            std::string::npos);
}

TEST(Overrides, FilesMustExistInTheConfiguration) {
  const Overrides vehicle({"vehicle.chassis.mass_kg=1"});
  EXPECT_NO_THROW(vehicle.check_files(1, false));
  EXPECT_NE(message_of([&] { vehicle.check_files(2, true); }).find("its units are unit1..unit2"),
            std::string::npos);
  EXPECT_NE(message_of([&] { vehicle.check_files(0, false); }).find("has no vehicle file"),
            std::string::npos);
  const Overrides unit3({"unit3.chassis.mass_kg=1"});
  EXPECT_NO_THROW(unit3.check_files(3, true));
  EXPECT_NE(message_of([&] { unit3.check_files(2, true); }).find("has 2 units (unit1..unit2)"),
            std::string::npos);
  EXPECT_EQ(Overrides({"rig.x=1", "unit1.a.b=2", "vehicle.c.d=3"}).of_file(1).size(), 2u);
}

TEST(Overrides, ALaterOverrideWins) {
  const toml::table t =
      patched("[rig]\nduration_s = 1\n", {"rig.duration_s=2", "rig.duration_s=3"});
  EXPECT_EQ(t["rig"]["duration_s"].value_exact<int64_t>(), 3);
}

}  // namespace
}  // namespace rig::io::config
