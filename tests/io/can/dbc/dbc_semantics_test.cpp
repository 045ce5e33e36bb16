#include "io/can/dbc/dbc_semantics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "io/can/dbc/dbc_parser.h"

namespace rig::io::can::dbc {
namespace {

using ::testing::HasSubstr;

/// The config::ConfigError message of parsing "BU_: A B\n" + `messages`, or "" if it parsed.
std::string error_of(const std::string& messages) {
  try {
    (void)parse_dbc("BU_: A B\n" + messages, "t.dbc");
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(DbcSemantics, CanFdLengths) {
  for (std::uint32_t n : {0u, 1u, 8u, 12u, 16u, 20u, 24u, 32u, 48u, 64u})
    EXPECT_TRUE(is_can_fd_length(n)) << n;
  for (std::uint32_t n : {9u, 10u, 13u, 33u, 63u}) EXPECT_FALSE(is_can_fd_length(n)) << n;
  EXPECT_EQ(error_of("BO_ 1 M: 10 A\n SG_ S : 0|8@1+ (1,0) [0|0] \"\" B\n"),
            "t.dbc:2: message M has length 10, not a CAN FD frame length (0-8, 12, 16, 20, 24, "
            "32, 48 or 64 bytes)");
  EXPECT_EQ(error_of("BO_ 1 M: 12 A\n SG_ S : 0|8@1+ (1,0) [0|0] \"\" B\n"), "");
}

TEST(DbcSemantics, OverlappingSignalsNameBoth) {
  EXPECT_EQ(error_of("BO_ 1 M: 8 A\n SG_ S : 0|16@1+ (1,0) [0|0] \"\" B\n"
                     " SG_ T : 15|1@1+ (1,0) [0|0] \"\" B\n"),
            "t.dbc:4: signal T overlaps signal S (line 3) in message M (bit 7 of byte 1)");
  // Motorola: MSB at bit 7 of byte 0, 16 bits: bytes 0 and 1 whole
  EXPECT_THAT(error_of("BO_ 1 M: 8 A\n SG_ S : 7|16@0+ (1,0) [0|0] \"\" B\n"
                       " SG_ T : 8|8@1+ (1,0) [0|0] \"\" B\n"),
              HasSubstr("t.dbc:4: signal T overlaps signal S"));
  // adjacent, not overlapping
  EXPECT_EQ(error_of("BO_ 1 M: 8 A\n SG_ S : 7|16@0+ (1,0) [0|0] \"\" B\n"
                     " SG_ T : 16|8@1+ (1,0) [0|0] \"\" B\n"),
            "");
}

TEST(DbcSemantics, MultiplexedPagesMayShareBitsButNotWithThePlainOnes) {
  const std::string mux = "BO_ 1 M: 8 A\n SG_ P M : 0|2@1+ (1,0) [0|3] \"\" B\n";
  EXPECT_EQ(error_of(mux + " SG_ S m0 : 8|16@1+ (1,0) [0|0] \"\" B\n"
                           " SG_ T m1 : 8|8@1+ (1,0) [0|0] \"\" B\n"),
            "");
  EXPECT_THAT(error_of(mux + " SG_ S m0 : 8|16@1+ (1,0) [0|0] \"\" B\n"
                             " SG_ T m0 : 8|8@1+ (1,0) [0|0] \"\" B\n"),
              HasSubstr("t.dbc:5: signal T overlaps signal S"));
  EXPECT_THAT(error_of(mux + " SG_ S m0 : 1|8@1+ (1,0) [0|0] \"\" B\n"),
              HasSubstr("t.dbc:4: signal S overlaps signal P"));
  // a plain signal after the pages still collides with them
  EXPECT_THAT(error_of(mux + " SG_ S m0 : 8|8@1+ (1,0) [0|0] \"\" B\n"
                             " SG_ U : 12|8@1+ (1,0) [0|0] \"\" B\n"),
              HasSubstr("t.dbc:4: signal S overlaps signal U (line 5)"));
}

TEST(DbcSemantics, UnreachablePageValues) {
  const std::string mux = "BO_ 1 M: 8 A\n SG_ P M : 0|2@1+ (1,0) [0|3] \"\" B\n";
  EXPECT_EQ(error_of(mux + " SG_ S m3 : 8|8@1+ (1,0) [0|0] \"\" B\n"), "");
  EXPECT_EQ(error_of(mux + " SG_ S m4 : 8|8@1+ (1,0) [0|0] \"\" B\n"),
            "t.dbc:4: multiplexed signal S (m4) is unreachable: multiplexor P of message M has "
            "too few bits");
  EXPECT_THAT(error_of("BO_ 1 M: 8 A\n SG_ P M : 0|4@1+ (1,0) [0|2] \"\" B\n"
                       " SG_ S m3 : 8|8@1+ (1,0) [0|0] \"\" B\n"),
              HasSubstr("has a smaller [min|max] range"));
}

TEST(DbcSemantics, InvertedRange) {
  EXPECT_EQ(error_of("BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1,0) [10|-10] \"\" B\n"),
            "t.dbc:3: signal S has an inverted range [10|-10] (minimum above maximum)");
  EXPECT_EQ(error_of("BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1,0) [0|0] \"\" B\n"), "");  // no range
}

TEST(DbcSemantics, TheBenchDbcIsClean) {
  EXPECT_NO_THROW((void)load_dbc(RIG_CAN_CONFIG_DIR "/steering-bench.dbc"));
}

}  // namespace
}  // namespace rig::io::can::dbc
