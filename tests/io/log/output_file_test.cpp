#include "io/log/output_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rig::io::log {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class OutputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("rig_output_file_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }
  /// One run's output: opens `name` and writes `text` into it.
  void write(const std::string& name, const std::string& text, int keep) {
    const int fd = open_output_file({"--out", path(name)}, keep);
    ASSERT_EQ(::write(fd, text.data(), text.size()), static_cast<ssize_t>(text.size()));
    ::close(fd);
  }
  [[nodiscard]] std::string read(const std::string& name) const {
    std::ifstream in(path(name));
    return {std::istreambuf_iterator<char>(in), {}};
  }
  static std::string error_of(const std::vector<OutputPath>& outputs,
                              const std::vector<fs::path>& inputs = {}) {
    try {
      check_output_paths(outputs, inputs);
    } catch (const OutputFileError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(OutputFile, EarlierRunsAreRotatedUpToKeep) {
  for (const char* run : {"1", "2", "3", "4"}) write("out.log", run, 2);
  EXPECT_EQ(read("out.log"), "4");
  EXPECT_EQ(read("out.log.1"), "3");
  EXPECT_EQ(read("out.log.2"), "2");
  EXPECT_FALSE(fs::exists(path("out.log.3")));
}

TEST_F(OutputFile, KeepZeroReplaces) {
  write("out.log", "1", 0);
  write("out.log", "2", 0);
  EXPECT_EQ(read("out.log"), "2");
  EXPECT_FALSE(fs::exists(path("out.log.1")));
}

TEST_F(OutputFile, SymbolicLinkIsRefusedAndItsTargetKept) {
  std::ofstream(path("target")) << "precious";
  fs::create_symlink(path("target"), path("link"));
  EXPECT_THROW((void)open_output_file({"--out", path("link")}, 10), OutputFileError);
  EXPECT_THAT(error_of({{"--out", path("link")}}), HasSubstr("is a symbolic link"));
  EXPECT_EQ(read("target"), "precious");
  EXPECT_TRUE(fs::is_symlink(path("link")));
}

TEST_F(OutputFile, SamePathTwiceAndInputsAreRefused) {
  EXPECT_THAT(error_of({{"--a", path("x")}, {"--b", dir_.string() + "/./x"}}),
              HasSubstr("the same file as --a " + path("x")));
  std::ofstream(path("config.toml")) << "[rig]\n";
  fs::create_hard_link(path("config.toml"), path("alias"));
  EXPECT_THAT(error_of({{"--a", path("alias")}}, {path("config.toml")}),
              HasSubstr("is an input of this run"));
  EXPECT_THAT(error_of({{"--a", path("none/x")}}), HasSubstr("does not exist"));
  EXPECT_THAT(error_of({{"--a", dir_.string()}}), HasSubstr("is a directory"));
  EXPECT_EQ(error_of({{"--a", "/dev/null"}, {"--b", "/dev/null"}, {"--c", ""}}), "");
  EXPECT_EQ(error_of({{"--a", path("x")}, {"--b", path("y")}}, {path("config.toml")}), "");
}

}  // namespace
}  // namespace rig::io::log
