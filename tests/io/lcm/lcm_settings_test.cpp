#include "io/lcm/lcm_settings.h"

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/lcm/multicast_route.h"

namespace rig::io {
namespace {

lcm::LcmSettings read(const std::string& name, const std::string& toml_text) {
  const auto file = std::filesystem::temp_directory_path() / name;
  std::ofstream(file) << toml_text;
  const toml::table root = config::load_toml_file(file);
  config::StrictTable top(root, file, "top");
  config::StrictTable lcm = top.table("lcm");
  return lcm::read_lcm_settings(lcm);
}

std::string error_of(const std::string& name, const std::string& toml_text) {
  try {
    read(name, toml_text);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(LcmSettings, DefaultsWhenTheSectionIsEmpty) {
  const lcm::LcmSettings s = read("lcm_settings_empty.toml", "[lcm]\n");
  EXPECT_EQ(s.url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(s.state_channel(), "RIG_STATE");
  EXPECT_EQ(s.status_channel(), "RIG_STATUS");
  EXPECT_EQ(s.signals_channel(), "RIG_SIGNALS");
  EXPECT_EQ(s.state_rate_hz, 1000.0);
  EXPECT_EQ(s.status_rate_hz, 10.0);
  EXPECT_EQ(s.signals_rate_hz, 100.0);
}

TEST(LcmSettings, ReadsEveryKey) {
  const lcm::LcmSettings s = read("lcm_settings_all.toml",
                                  "[lcm]\nurl = \"udpm://239.255.76.68:7668?ttl=1\"\n"
                                  "channel_prefix = \"BENCH2_\"\nstate_rate_hz = 500\n"
                                  "status_rate_hz = 2.5\nsignals_rate_hz = 0\n");
  EXPECT_EQ(s.url, "udpm://239.255.76.68:7668?ttl=1");
  EXPECT_EQ(s.state_channel(), "BENCH2_RIG_STATE");
  EXPECT_EQ(s.signals_channel(), "BENCH2_RIG_SIGNALS");
  EXPECT_EQ(s.state_rate_hz, 500.0);
  EXPECT_EQ(s.status_rate_hz, 2.5);
  EXPECT_EQ(s.signals_rate_hz, 0.0);
}

TEST(LcmSettings, RejectsBadValuesWithFileAndLine) {
  const auto dir = std::filesystem::temp_directory_path().string() + "/";
  EXPECT_EQ(error_of("lcm_bad_key.toml", "[lcm]\nurl = \"udpm://\"\nrate = 3\n"),
            dir + "lcm_bad_key.toml:3: [lcm]: unknown key 'rate'");
  EXPECT_NE(
      error_of("lcm_bad_rate.toml", "[lcm]\nstate_rate_hz = -1\n").find("lcm_bad_rate.toml:2:"),
      std::string::npos);
  EXPECT_NE(
      error_of("lcm_bad_url.toml", "[lcm]\nurl = \"239.255.76.67\"\n").find("lcm_bad_url.toml:2:"),
      std::string::npos);
  EXPECT_NE(error_of("lcm_bad_prefix.toml", "[lcm]\nchannel_prefix = \"a b\"\n")
                .find("lcm_bad_prefix.toml:2:"),
            std::string::npos);
}

// A malformed URL is an error (it used to switch LCM off at start, silently); ttl > 0 warns.
TEST(LcmUrl, MalformedUrlsAreNamed) {
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67:7667?ttl=0"), "");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://"), "");  // LCM's default group and port
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67:7667?ttl=1&recv_buf_size=2097152"), "");
  EXPECT_EQ(lcm::lcm_url_problem("file:///tmp/x.lcm?mode=w"), "");
  EXPECT_NE(lcm::lcm_url_problem("garbage").find("provider://address"), std::string::npos);
  EXPECT_EQ(lcm::lcm_url_problem("udp://239.255.76.67:7667"),
            "unknown LCM provider 'udp' (udpm, mpudpm, file, memq, tcpq)");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://10.0.0.1:7667"),
            "'10.0.0.1' is not an IPv4 multicast group (224.0.0.0 - 239.255.255.255)");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67:0"), "port '0' is not in 1..65535");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67:70000"), "port '70000' is not in 1..65535");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67"),
            "udpm needs GROUP:PORT, e.g. 239.255.76.67:7667");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67:7667?ttl=256"),
            "ttl '256' is not in 0..255");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67:7667?tll=1"),
            "unknown udpm option 'tll' (ttl, recv_buf_size)");
  EXPECT_EQ(lcm::lcm_url_problem("udpm://239.255.76.67:7667?ttl"), "option 'ttl' is not key=value");
}

TEST(LcmUrl, TtlAboveZeroGivesOneWarning) {
  EXPECT_EQ(lcm::lcm_url_ttl("udpm://239.255.76.67:7667?ttl=0"), 0);
  EXPECT_EQ(lcm::lcm_url_ttl("udpm://239.255.76.67:7667?recv_buf_size=9&ttl=3"), 3);
  EXPECT_EQ(lcm::lcm_url_warning("udpm://239.255.76.67:7667?ttl=0"), "");
  EXPECT_EQ(lcm::lcm_url_warning("udpm://239.255.76.67:7667?ttl=1"),
            "rig: warning: LCM URL udpm://239.255.76.67:7667?ttl=1 has ttl=1: the rig's LCM "
            "traffic leaves this host (up to 1 router hop); ttl=0 keeps it here");
}

TEST(MulticastRoute, ParsesUdpmUrls) {
  const auto a = lcm::parse_udpm_url("udpm://239.255.76.67:7667?ttl=0");
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->group, "239.255.76.67");
  EXPECT_EQ(a->port, 7667);
  const auto b = lcm::parse_udpm_url("udpm://");
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->group, "239.255.76.67");
  EXPECT_FALSE(lcm::parse_udpm_url("memq://").has_value());
  EXPECT_EQ(lcm::check_multicast_route("memq://"), "");
}

TEST(MulticastRoute, AdviceNamesTheCommand) {
  EXPECT_NE(lcm::multicast_route_advice().find("ip route add 224.0.0.0/4 dev lo"),
            std::string::npos);
}

}  // namespace
}  // namespace rig::io
