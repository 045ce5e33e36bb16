#include "io/lcm/lcm_settings.h"

#include <algorithm>
#include <cctype>

namespace rig::io::lcm {

namespace {

constexpr double kMaxRateHz = 1.0e6;

bool valid_channel_prefix(const std::string& prefix) {
  return std::all_of(prefix.begin(), prefix.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.' ||
           c == '/';
  });
}

}  // namespace

LcmSettings read_lcm_settings(config::StrictTable& lcm_table) {
  LcmSettings settings;
  settings.url = lcm_table.string("url", settings.url);
  if (settings.url.find("://") == std::string::npos) {
    throw lcm_table.error(
        "url", "an LCM URL looks like provider://address, e.g. " + std::string(kDefaultLcmUrl));
  }
  settings.channel_prefix = lcm_table.string("channel_prefix", "");
  if (!valid_channel_prefix(settings.channel_prefix)) {
    throw lcm_table.error("channel_prefix",
                          "channel_prefix may hold letters, digits and _ - . / only");
  }
  settings.state_rate_hz =
      lcm_table.number_in("state_rate_hz", settings.state_rate_hz, 0.0, kMaxRateHz);
  settings.status_rate_hz =
      lcm_table.number_in("status_rate_hz", settings.status_rate_hz, 0.0, kMaxRateHz);
  settings.signals_rate_hz =
      lcm_table.number_in("signals_rate_hz", settings.signals_rate_hz, 0.0, kMaxRateHz);
  lcm_table.finish();
  return settings;
}

}  // namespace rig::io::lcm
