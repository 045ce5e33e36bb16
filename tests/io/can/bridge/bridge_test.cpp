// Host tests of the bridge's configuration and factory (the bridge on vcan: tests/io/can/vcan).
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/can/bridge/can_settings.h"
#include "io/can/transport/socket_can_transport.h"
#include "io/config/config_error.h"

namespace rig::io::can {
namespace {

namespace fs = std::filesystem;

fs::path write_rig_toml(const std::string& text) {
  // one folder per test: ctest runs the tests of this file in parallel processes
  const fs::path dir =
      fs::temp_directory_path() /
      ("rig_can_bridge_test_" +
       std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
       std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::copy_file(fs::path(RIG_SOURCE_DIR) / "config/can/steering-bench.toml",
                dir / "steering-bench.toml", fs::copy_options::overwrite_existing);
  fs::copy_file(fs::path(RIG_SOURCE_DIR) / "config/can/steering-bench.dbc",
                dir / "steering-bench.dbc", fs::copy_options::overwrite_existing);
  const fs::path file = dir / "rig.toml";
  std::ofstream(file) << text;
  return file;
}

can::bridge::CanSettings settings_from(const fs::path& file) {
  const toml::table root = config::load_toml_file(file);
  config::StrictTable rig(root, file, "root");
  config::StrictTable can = rig.table("can");
  return can::bridge::read_can_settings(can);
}

TEST(CanSettings, ReadsTheCanSectionWithPathsRelativeToTheFile) {
  const fs::path file = write_rig_toml(
      "[can]\ninterface = \"can0\"\nmapping = \"steering-bench.toml\"\n"
      "dbc = \"steering-bench.dbc\"\nkernel_filter = true\n");
  const can::bridge::CanSettings s = settings_from(file);
  EXPECT_EQ(s.interface, "can0");
  EXPECT_EQ(s.mapping_file.filename(), "steering-bench.toml");
  EXPECT_TRUE(s.mapping_file.is_absolute() || fs::exists(s.mapping_file));
  ASSERT_TRUE(s.dbc_file.has_value());
  EXPECT_TRUE(s.kernel_filter);
  EXPECT_TRUE(s.fd);
}

TEST(CanSettings, UnknownKeyIsAnErrorWithFileAndLine) {
  const fs::path file = write_rig_toml(
      "[can]\ninterface = \"vcan0\"\nmapping = \"steering-bench.toml\"\nbitrate = 500000\n");
  try {
    (void)settings_from(file);
    FAIL() << "expected config::ConfigError";
  } catch (const config::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("rig.toml:"), std::string::npos) << what;
    EXPECT_NE(what.find("bitrate"), std::string::npos) << what;
  }
}

TEST(CanSettings, MissingMappingFileIsAnError) {
  const fs::path file = write_rig_toml("[can]\nmapping = \"nope.toml\"\n");
  EXPECT_THROW((void)settings_from(file), config::ConfigError);
}

TEST(MakeCanIo, WithoutSocketCanFailsWithAClearTransportError) {
  if (can::transport::can_sockets_available()) GTEST_SKIP() << "this kernel has AF_CAN";
  const fs::path file =
      write_rig_toml("[can]\ninterface = \"vcan0\"\nmapping = \"steering-bench.toml\"\n");
  try {
    (void)can::bridge::make_can_io(settings_from(file), InputSet{});
    FAIL() << "expected can::transport::TransportError";
  } catch (const can::transport::TransportError& e) {
    EXPECT_NE(std::string(e.what()).find("--can none"), std::string::npos) << e.what();
  }
}

TEST(MakeCanIo, OnVcanOpensTheBusAndReportsItUp) {
  if (!can::transport::can_sockets_available())
    GTEST_SKIP() << "needs AF_CAN and vcan0 (run via with-vcan)";
  const fs::path file = write_rig_toml(
      "[can]\ninterface = \"vcan0\"\nmapping = \"steering-bench.toml\"\nkernel_filter = true\n");
  const auto io = can::bridge::make_can_io(settings_from(file), InputSet{});
  ASSERT_NE(io, nullptr);
  IoCounters c;
  io->read_counters(c);
  EXPECT_EQ(c.bus_state, BusState::kUp);
  model::Signals s{};
  io->receive(0, s);
  const model::ModelReport report{};
  io->transmit(0, {s, report});  // t = 0: every TX message is due at the loop start
  io->read_counters(c);
  EXPECT_EQ(c.frames_sent, 5u);  // the five [[tx]] messages of steering-bench.toml
}

}  // namespace
}  // namespace rig::io::can
