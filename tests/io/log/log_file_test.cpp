#include "io/log/log_file.h"

#include <gtest/gtest.h>

#include <cstring>

namespace rig::io::log {
namespace {

LogRecord event(const char* name) {
  LogRecord r;
  std::strncpy(r.name.data(), name, r.name.size() - 1);
  return r;
}

// /dev/full fails every write with ENOSPC: a full disk. Each lost line is counted and the
// error kept, nothing is silent.
TEST(LogFile, WritesOnAFullDiskAreCounted) {
  LogFile file("/dev/full", 10);
  file.write(event("start"));
  file.write(event("stop"));
  file.write_lost(3);
  file.close();
  EXPECT_EQ(file.write_failures(), 3u);
  EXPECT_EQ(file.write_error(), std::strerror(ENOSPC));
}

TEST(LogFile, NoPathWritesNothingAndFailsNothing) {
  LogFile file("", 10);
  file.write(event("start"));
  EXPECT_EQ(file.write_failures(), 0u);
  EXPECT_EQ(file.write_error(), "");
}

}  // namespace
}  // namespace rig::io::log
