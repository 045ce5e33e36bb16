#include "io/config/strict_table.h"

#include <fstream>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/alloc_counter.h"

namespace rig::io {
namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(StrictTable, ReadsValuesAndRejectsUnknownKeysWithLine) {
  const auto file =
      write_file("strict1.toml", "[rig]\nperiod_s = 0.001\npriority = 80\ntypo = 1\n");
  const toml::table root = config::load_toml_file(file);
  config::StrictTable top(root, file, "top");
  config::StrictTable rig = top.table("rig");
  EXPECT_DOUBLE_EQ(rig.number_in("period_s", 1e-6, 1.0), 0.001);
  EXPECT_EQ(rig.integer("priority"), 80);
  const std::string msg = message_of([&] { rig.finish(); });
  EXPECT_EQ(msg, file.string() + ":4: [rig]: unknown key 'typo'");
}

// Every integer key is read with integer_in/integers: a float is an error with file:line, never
// truncated (issue 13: `priority = 80.7` ran at 80).
TEST(StrictTable, IntegerKeysRejectFloats) {
  const auto file = write_file("strict_int.toml",
                               "[rig]\npriority = 80.7\nround = 80.0\ncpu = 3\nbig = 200\n"
                               "bytes = [0, 1]\nmixed = [0,\n 1.0]\n");
  const toml::table root = config::load_toml_file(file);
  config::StrictTable top(root, file, "top");
  config::StrictTable rig = top.table("rig");
  EXPECT_EQ(message_of([&] { (void)rig.integer_in("priority", 1, 99); }),
            file.string() + ":2: [rig] priority: expected an integer, not 80.7 (a float)");
  EXPECT_EQ(message_of([&] { (void)rig.integer_in("round", 1, 99); }),
            file.string() + ":3: [rig] round: expected an integer, not 80 (a float)");
  EXPECT_EQ(rig.integer_in("cpu", -1, -1, 1023), 3);
  EXPECT_EQ(rig.integer_in("absent", -1, -1, 1023), -1);
  EXPECT_EQ(message_of([&] { (void)rig.integer_in("big", 1, 99); }),
            file.string() + ":5: [rig] big: value 200 out of range [1, 99]");
  EXPECT_EQ(rig.integers("bytes"), (std::vector<long long>{0, 1}));
  // the element's own line
  EXPECT_EQ(message_of([&] { (void)rig.integers("mixed"); }),
            file.string() + ":8: [rig] mixed: expected an array of integers");
}

TEST(StrictTable, LocationNamesTheKeysLine) {
  const auto file = write_file("strict_loc.toml", "[routing]\n\nassist_torque_nm = \"can\"\n");
  const toml::table root = config::load_toml_file(file);
  config::StrictTable top(root, file, "top");
  const config::StrictTable routing = top.table("routing");
  EXPECT_EQ(routing.location("assist_torque_nm"), file.string() + ":3");
}

TEST(StrictTable, ParseErrorCarriesFileAndLine) {
  const auto file = write_file("strict2.toml", "a = 1\nb = = 2\n");
  const std::string msg = message_of([&] { (void)config::load_toml_file(file); });
  EXPECT_NE(msg.find(file.string() + ":2:"), std::string::npos) << msg;
}

TEST(StrictTable, MissingFileIsAConfigError) {
  const std::string msg = message_of([] { (void)config::load_toml_file("/nonexistent/rig.toml"); });
  EXPECT_EQ(msg, "/nonexistent/rig.toml:1: cannot read file (missing or not a regular file)");
}

TEST(StrictTable, RangeAndChoiceErrors) {
  const auto file = write_file("strict3.toml", "period_s = -1\npolicy = \"sometimes\"\n");
  const toml::table root = config::load_toml_file(file);
  config::StrictTable t(root, file, "[rig]");
  EXPECT_EQ(message_of([&] { (void)t.number_in("period_s", 1e-6, 1.0); }),
            file.string() + ":1: [rig] period_s: value -1 out of range [1e-06, 1]");
  EXPECT_EQ(message_of([&] {
              (void)t.choice("policy", "skip", {"skip", "catch-up"});
            }),
            file.string() +
                ":2: [rig] policy: unknown value 'sometimes' (expected one of: skip, catch-up)");
  EXPECT_EQ(message_of([&] { (void)t.number("absent"); }),
            file.string() + ":1: [rig] absent: missing required key");
}

TEST(StrictTable, FallbacksAndArrays) {
  const auto file =
      write_file("strict4.toml", "xs = [1, 2.5, 3]\n[[axle]]\nm = 1\n[[axle]]\nm = 2\n");
  const toml::table root = config::load_toml_file(file);
  config::StrictTable t(root, file, "top");
  EXPECT_EQ(t.numbers("xs"), (std::vector<double>{1, 2.5, 3}));
  EXPECT_DOUBLE_EQ(t.number("missing", 7.0), 7.0);
  auto axles = t.tables("axle");
  ASSERT_EQ(axles.size(), 2u);
  EXPECT_DOUBLE_EQ(axles[1].number("m"), 2.0);
  EXPECT_THROW(axles[0].finish(), config::ConfigError);  // m of axle 0 was never read
}

TEST(AllocationCounter, CountsThisThreadsAllocations) {
  test::AllocationCounter counter;
  auto* v = new std::vector<int>(100);
  EXPECT_GE(counter.count(), 2u);
  delete v;
}

}  // namespace
}  // namespace rig::io
