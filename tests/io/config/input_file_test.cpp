#include "io/config/input_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/config/config_error.h"

namespace rig::io::config {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

std::string error_of(const fs::path& file, std::size_t max_bytes = kMaxInputFileBytes) {
  try {
    (void)read_input_file(file, max_bytes);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

fs::path temp(const std::string& name) {
  return fs::temp_directory_path() / ("rig_input_file_" + std::to_string(::getpid()) + name);
}

TEST(InputFile, ReadsARegularFileWhole) {
  const fs::path p = temp(".toml");
  std::ofstream(p) << "[rig]\nperiod_s = 0.001\n";
  EXPECT_EQ(read_input_file(p), "[rig]\nperiod_s = 0.001\n");
  EXPECT_THAT(error_of(p, 10), HasSubstr(":1: cannot read file: larger than 10 bytes"));
  fs::remove(p);
}

// A device would be read until memory runs out, a FIFO would block forever, a directory would
// read as empty: each is refused by name, and the FIFO without waiting for a writer.
TEST(InputFile, RefusesWhatIsNotARegularFile) {
  EXPECT_EQ(error_of("/dev/zero"),
            "/dev/zero:1: cannot read file: it is a character device, not a regular file");
  const fs::path dir = temp("_dir");
  fs::create_directories(dir);
  EXPECT_THAT(error_of(dir), HasSubstr(":1: cannot read file: it is a directory"));
  fs::remove(dir);
  const fs::path fifo = temp(".fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(error_of(fifo), HasSubstr(":1: cannot read file: it is a FIFO"));
  fs::remove(fifo);
  EXPECT_EQ(error_of("/nonexistent/rig.toml"),
            "/nonexistent/rig.toml:1: cannot read file (missing or not a regular file)");
}

}  // namespace
}  // namespace rig::io::config
