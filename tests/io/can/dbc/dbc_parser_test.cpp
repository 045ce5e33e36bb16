#include "io/can/dbc/dbc_parser.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace rig::io::can::dbc {
namespace {

using ::testing::HasSubstr;

const char* const kHeader = R"(VERSION "1.2"
NS_ :
	CM_
	BA_DEF_

BS_:
BU_: A B
)";

/// The config::ConfigError message of parsing `text`, or "" if it parsed.
std::string error_of(const std::string& text) {
  try {
    (void)parse_dbc(text, "t.dbc");
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(DbcParser, HeaderVersionNodes) {
  const Database db = parse_dbc(kHeader, "t.dbc");
  EXPECT_EQ(db.version, "1.2");
  EXPECT_EQ(db.nodes, (std::vector<std::string>{"A", "B"}));
  EXPECT_TRUE(db.messages.empty());
  EXPECT_TRUE(db.warnings.empty());
}

TEST(DbcParser, MessageAndSignalFields) {
  const Database db = parse_dbc(std::string(kHeader) + R"(
BO_ 291 Msg: 8 A
 SG_ Intel : 3|12@1+ (0.5,-10) [-10|2037.5] "km/h" B,A
 SG_ Moto : 23|9@0- (1e-3,2.5E+1) [-1|1] "" Vector__XXX
)",
                                "t.dbc");
  ASSERT_EQ(db.messages.size(), 1u);
  const MessageDef& m = db.messages[0];
  EXPECT_EQ(m.id, 291u);
  EXPECT_FALSE(m.extended);
  EXPECT_EQ(m.name, "Msg");
  EXPECT_EQ(m.length_bytes, 8u);
  EXPECT_EQ(m.sender, "A");
  EXPECT_EQ(m.line, 9);
  ASSERT_EQ(m.signals.size(), 2u);
  const SignalDef& a = m.signals[0];
  EXPECT_EQ(a.start_bit, 3u);
  EXPECT_EQ(a.length_bits, 12u);
  EXPECT_EQ(a.byte_order, ByteOrder::kIntel);
  EXPECT_FALSE(a.is_signed);
  EXPECT_EQ(a.factor, 0.5);
  EXPECT_EQ(a.offset, -10.0);
  EXPECT_EQ(a.minimum, -10.0);
  EXPECT_EQ(a.maximum, 2037.5);
  EXPECT_EQ(a.unit, "km/h");
  EXPECT_EQ(a.receivers, (std::vector<std::string>{"B", "A"}));
  const SignalDef& b = m.signals[1];
  EXPECT_EQ(b.byte_order, ByteOrder::kMotorola);
  EXPECT_TRUE(b.is_signed);
  EXPECT_EQ(b.factor, 1e-3);
  EXPECT_EQ(b.offset, 25.0);
  EXPECT_EQ(b.line, 11);
}

TEST(DbcParser, ExtendedIdAndCanFdLength) {
  const Database db = parse_dbc(R"(BO_ 2566848770 Ext: 64 A
 SG_ S : 504|8@1+ (1,0) [0|0] "" B
)",
                                "t.dbc");
  ASSERT_EQ(db.messages.size(), 1u);
  EXPECT_TRUE(db.messages[0].extended);
  EXPECT_EQ(db.messages[0].id, 0x18FF0102u);
  EXPECT_EQ(db.messages[0].dbc_id(), 2566848770u);
  EXPECT_TRUE(db.messages[0].is_fd());
  EXPECT_FALSE(db.messages[0].signals[0].has_range());
  EXPECT_NE(db.find_message(0x18FF0102u, true), nullptr);
  EXPECT_EQ(db.find_message(0x18FF0102u, false), nullptr);
}

TEST(DbcParser, VFrameFormatMarksShortCanFdFrames) {
  const Database db = parse_dbc(R"(BO_ 1 Fd8: 8 A
BO_ 2 Classic: 8 A
BO_ 3 FdByName: 4 A
BA_DEF_ BO_ "VFrameFormat" ENUM "StandardCAN","ExtendedCAN","reserved","J1939PG","reserved","reserved","reserved","reserved","reserved","reserved","reserved","reserved","reserved","reserved","StandardCAN_FD","ExtendedCAN_FD";
BA_DEF_DEF_ "VFrameFormat" "StandardCAN";
BA_ "VFrameFormat" BO_ 1 14;
BA_ "VFrameFormat" BO_ 2 0;
BA_ "VFrameFormat" BO_ 3 "StandardCAN_FD";
)",
                                "t.dbc");
  ASSERT_EQ(db.messages.size(), 3u);
  EXPECT_TRUE(db.messages[0].is_fd());   // 8 bytes, but an FD frame
  EXPECT_FALSE(db.messages[1].is_fd());  // classic
  EXPECT_TRUE(db.messages[2].is_fd());
}

TEST(DbcParser, MultiplexedSignals) {
  const Database db = parse_dbc(R"(BO_ 1 M: 8 A
 SG_ Sw M : 0|4@1+ (1,0) [0|15] "" B
 SG_ P0 m0 : 8|8@1+ (1,0) [0|0] "" B
 SG_ P12 m12 : 8|16@1+ (1,0) [0|0] "" B
)",
                                "t.dbc");
  const auto& s = db.messages[0].signals;
  EXPECT_EQ(s[0].mux_role, MuxRole::kMultiplexor);
  EXPECT_EQ(s[1].mux_role, MuxRole::kMultiplexed);
  EXPECT_EQ(s[1].mux_value, 0u);
  EXPECT_EQ(s[2].mux_value, 12u);
}

TEST(DbcParser, CommentsValuesAttributesValueTypes) {
  const Database db = parse_dbc(R"(BO_ 1 M: 12 A
 SG_ F : 0|32@1- (1,0) [0|0] "" B
 SG_ D : 32|64@1- (1,0) [0|0] "" B
BO_ 2 N: 8 A
 SG_ E : 0|8@1+ (1,0) [0|3] "" B
CM_ "network";
CM_ BO_ 1 "first line
second \"quoted\" line";
CM_ SG_ 2 E "enum; with semicolon";
BA_DEF_ BO_ "GenMsgCycleTime" INT 0 10000;
BA_DEF_ SG_ "GenSigStartValue" INT 0 100;
BA_DEF_ "DBName" STRING ;
BA_DEF_DEF_ "GenMsgCycleTime" 100;
BA_DEF_DEF_ "GenSigStartValue" 3;
BA_DEF_DEF_ "DBName" "";
BA_ "DBName" "bench";
BA_ "GenMsgCycleTime" BO_ 2 20;
BA_ "GenSigStartValue" SG_ 2 E 2;
VAL_ 2 E 3 "Fault" 2 "Assist" -1 "Neg" 0 "Off" ;
SIG_VALTYPE_ 1 F : 1;
SIG_VALTYPE_ 1 D : 2;
)",
                                "t.dbc");
  const MessageDef& m = db.messages[0];
  const MessageDef& n = db.messages[1];
  EXPECT_EQ(m.comment, "first line\nsecond \"quoted\" line");
  EXPECT_EQ(n.signals[0].comment, "enum; with semicolon");
  EXPECT_EQ(m.cycle_time_ms, 100u);  // BA_DEF_DEF_ default
  EXPECT_EQ(n.cycle_time_ms, 20u);
  EXPECT_EQ(m.signals[0].start_value_raw, 3.0);
  EXPECT_EQ(n.signals[0].start_value_raw, 2.0);
  ASSERT_EQ(n.signals[0].value_descriptions.size(), 4u);
  EXPECT_EQ(n.signals[0].value_descriptions[2].value, -1);
  EXPECT_EQ(n.signals[0].value_descriptions[1].text, "Assist");
  EXPECT_EQ(m.signals[0].value_type, ValueType::kFloat32);
  EXPECT_EQ(m.signals[1].value_type, ValueType::kFloat64);
  EXPECT_EQ(db.attribute_definitions.size(), 3u);
  EXPECT_EQ(db.attribute_definitions[0].default_value, "100");
}

TEST(DbcParser, UnknownSectionsAreSkippedWithWarning) {
  const Database db = parse_dbc(R"(BO_ 1 M: 8 A
 SG_ S : 0|8@1+ (1,0) [0|0] "" B
BO_TX_BU_ 1 : A,B;
SG_MUL_VAL_ 1 S S 0-1;
EV_ X: 0 [0|1] "" 0 1 DUMMY_NODE_VECTOR0 Vector__XXX;
VAL_TABLE_ T 1 "one ; two" 0 "zero" ;
BO_ 2 N: 8 A
)",
                                "t.dbc");
  EXPECT_EQ(db.messages.size(), 2u);
  ASSERT_EQ(db.warnings.size(), 4u);
  EXPECT_THAT(db.warnings[0], HasSubstr("t.dbc:3: section 'BO_TX_BU_'"));
  EXPECT_THAT(db.warnings[3], HasSubstr("t.dbc:6: section 'VAL_TABLE_'"));
}

TEST(DbcParser, IndependentSignalPseudoMessageIsSkipped) {
  const Database db = parse_dbc(R"(BO_ 3221225472 VECTOR__INDEPENDENT_SIG_MSG: 0 Vector__XXX
 SG_ Orphan : 0|8@1+ (1,0) [0|0] "" Vector__XXX
)",
                                "t.dbc");
  EXPECT_TRUE(db.messages.empty());
  EXPECT_EQ(db.warnings.size(), 1u);
}

TEST(DbcParser, ExampleDatabaseLoads) {
  const Database db = load_dbc(std::string(RIG_CAN_CONFIG_DIR) + "/steering-bench.dbc");
  EXPECT_EQ(db.messages.size(), 8u);
  EXPECT_TRUE(db.warnings.size() == 1u);  // VAL_TABLE_
  for (const auto& m : db.messages) EXPECT_GT(m.cycle_time_ms, 0u) << m.name;
}

struct BadInput {
  const char* text;
  const char* error;
};

class DbcParserErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(DbcParserErrors, NameFileAndLine) {
  EXPECT_THAT(error_of(GetParam().text), HasSubstr(GetParam().error));
}

const BadInput kBadInputs[] = {
    {"BO_ x M: 8 A\n", "t.dbc:1: expected an unsigned integer for message id"},
    {"\nBO_ 1 : 8 A\n", "t.dbc:2: expected a message name"},
    {"BO_ 1 M 8 A\n", "t.dbc:1: expected ':' after the message name"},
    {"BO_ 1 M: 65 A\n", "t.dbc:1: bad message length '65'"},
    {"BO_ 2048 M: 8 A\n", "t.dbc:1: message id 2048 of M is out of range"},
    {"BO_ 1 M: 8 A B\n", "t.dbc:1: unexpected 'B' after BO_ M"},
    {"BO_ 1 M: 8 A\nBO_ 1 N: 8 A\n", "t.dbc:2: duplicate message id 1 (N, first M at line 1)"},
    {"BO_ 1 M: 8 A\nBO_ 2 M: 8 A\n", "t.dbc:2: duplicate message name M"},
    {" SG_ S : 0|8@1+ (1,0) [0|0] \"\" B\n", "t.dbc:1: SG_ outside a BO_ block"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@2+ (1,0) [0|0] \"\" B\n", "t.dbc:2: expected byte order 0 or 1"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1* (1,0) [0|0] \"\" B\n", "t.dbc:2: expected '+' or '-'"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1.2.3,0) [0|0] \"\" B\n",
     "t.dbc:2: bad number '1.2.3' for the factor"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1,0) [0|1e999] \"\" B\n", "t.dbc:2: bad number '1e999'"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (0,0) [0|0] \"\" B\n", "t.dbc:2: signal S has factor 0"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|0@1+ (1,0) [0|0] \"\" B\n", "t.dbc:2: signal S has length 0"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|65@1+ (1,0) [0|0] \"\" B\n", "t.dbc:2: bad signal length '65'"},
    {"BO_ 1 M: 8 A\n SG_ S : 60|8@1+ (1,0) [0|0] \"\" B\n",
     "t.dbc:2: signal S (start bit 60, length 8, Intel) does not fit in message M of 8 bytes"},
    {"BO_ 1 M: 8 A\n SG_ S : 59|8@0+ (1,0) [0|0] \"\" B\n",
     "t.dbc:2: signal S (start bit 59, length 8, Motorola) does not fit"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1,0) [0|0] \"\" B\n SG_ S : 8|8@1+ (1,0) [0|0] \"\" B\n",
     "t.dbc:3: duplicate signal S in message M"},
    {"BO_ 1 M: 8 A\n SG_ S m1 : 0|8@1+ (1,0) [0|0] \"\" B\n",
     "t.dbc:2: multiplexed signal S in message M which has no multiplexor"},
    {"BO_ 1 M: 8 A\n SG_ S m1M : 0|8@1+ (1,0) [0|0] \"\" B\n", "extended multiplexing"},
    {"BO_ 1 M: 8 A\n SG_ S X : 0|8@1+ (1,0) [0|0] \"\" B\n", "t.dbc:2: bad multiplexer indicator"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1,0) [0|0] \"unit B\n\n", "t.dbc:2: unterminated string"},
    {"VERSION \"x\"\nCM_ BO_ 1 \"never\nclosed;\n", "t.dbc:2: unterminated string"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1,0) [0|0] \"\" B\nCM_ SG_ 1 S \"c\"\n",
     "t.dbc:4: expected ';' to end CM_"},
    {"BO_ 1 M: 8 A\n SG_ S : 0|8@1+ (1,0) [0|0] \"\" B\nSIG_VALTYPE_ 1 S : 1;\n",
     "t.dbc:3: float signal S must be 32 bits long"},
    {"SIG_VALTYPE_ 1 S : 1;\n", "t.dbc:1: SIG_VALTYPE_ refers to unknown signal S"},
    {"BA_DEF_ BO_ \"GenMsgCycleTime\" INT 0 10;\nBO_ 1 M: 8 A\nBA_ \"GenMsgCycleTime\" BO_ 1 -5;\n",
     "t.dbc:3: GenMsgCycleTime -5 is not a whole number"},
    {"BO_ 1 M: 8 A\nVAL_ 1 S 1 \"a\" x \"b\";\n", "t.dbc:2: bad integer 'x' for a VAL_ value"},
    {"BO_ 1 M: 8 A\nVAL_ 1 S 1 \"a\"\n", "t.dbc:2: VAL_ not terminated by ';'"},
    {"BO_ 1 M: 8 A\n!\n", "t.dbc:2: expected a section keyword, found '!'"},
};

INSTANTIATE_TEST_SUITE_P(Malformed, DbcParserErrors, ::testing::ValuesIn(kBadInputs));

TEST(DbcParser, MissingFileIsConfigError) {
  EXPECT_THROW((void)load_dbc("/nonexistent/x.dbc"), config::ConfigError);
}

}  // namespace
}  // namespace rig::io::can::dbc
