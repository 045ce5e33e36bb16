#include "io/lcm/lcm_settings.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include <arpa/inet.h>
#include <netinet/in.h>

namespace rig::io::lcm {

namespace {

constexpr double kMaxRateHz = 1.0e6;

bool valid_channel_prefix(const std::string& prefix) {
  return std::all_of(prefix.begin(), prefix.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.' ||
           c == '/';
  });
}

/// A whole decimal number in [0, max], or -1.
long long whole_number(std::string_view text, long long max) {
  if (text.empty() || text.size() > 12) return -1;
  long long v = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return -1;
    v = v * 10 + (c - '0');
  }
  return v <= max ? v : -1;
}

std::string udpm_target_problem(std::string_view target) {
  if (target.empty()) return "";  // LCM's default group and port
  const auto colon = target.find(':');
  if (colon == std::string_view::npos) return "udpm needs GROUP:PORT, e.g. 239.255.76.67:7667";
  in_addr group{};
  const std::string host(target.substr(0, colon));
  if (inet_pton(AF_INET, host.c_str(), &group) != 1 || (ntohl(group.s_addr) >> 28) != 0xE)
    return "'" + host + "' is not an IPv4 multicast group (224.0.0.0 - 239.255.255.255)";
  if (whole_number(target.substr(colon + 1), 65535) < 1)
    return "port '" + std::string(target.substr(colon + 1)) + "' is not in 1..65535";
  return "";
}

std::string option_problem(std::string_view provider, std::string_view option) {
  const auto eq = option.find('=');
  if (eq == std::string_view::npos || eq == 0)
    return "option '" + std::string(option) + "' is not key=value";
  if (provider != "udpm" && provider != "mpudpm") return "";
  const std::string_view key = option.substr(0, eq);
  const std::string_view value = option.substr(eq + 1);
  if (key == "ttl")
    return whole_number(value, 255) < 0 ? "ttl '" + std::string(value) + "' is not in 0..255" : "";
  if (key == "recv_buf_size")
    return whole_number(value, 1LL << 31) < 1 ? "recv_buf_size must be a positive integer" : "";
  if (provider == "udpm")
    return "unknown udpm option '" + std::string(key) + "' (ttl, recv_buf_size)";
  return "";
}

}  // namespace

std::string lcm_url_problem(const std::string& url) {
  const auto sep = url.find("://");
  if (sep == std::string::npos)
    return "an LCM URL looks like provider://address?options, e.g. " + std::string(kDefaultLcmUrl);
  const std::string provider = url.substr(0, sep);
  if (provider != "udpm" && provider != "mpudpm" && provider != "file" && provider != "memq" &&
      provider != "tcpq")
    return "unknown LCM provider '" + provider + "' (udpm, mpudpm, file, memq, tcpq)";
  const std::string_view rest = std::string_view(url).substr(sep + 3);
  const auto query = rest.find('?');
  const std::string_view target = rest.substr(0, query);
  if (provider == "udpm") {
    if (std::string problem = udpm_target_problem(target); !problem.empty()) return problem;
  }
  if (query == std::string_view::npos) return "";
  std::string_view options = rest.substr(query + 1);
  while (true) {
    const auto amp = options.find('&');
    if (std::string problem = option_problem(provider, options.substr(0, amp)); !problem.empty())
      return problem;
    if (amp == std::string_view::npos) return "";
    options.remove_prefix(amp + 1);
  }
}

int lcm_url_ttl(const std::string& url) {
  if (!url.starts_with("udpm://") && !url.starts_with("mpudpm://")) return 0;
  const auto at = url.find("ttl=", url.find('?'));
  if (url.find('?') == std::string::npos || at == std::string::npos) return 0;
  const auto end = url.find('&', at);
  return static_cast<int>(std::max(0LL, whole_number(url.substr(at + 4, end - at - 4), 255)));
}

std::string lcm_url_warning(const std::string& url) {
  const int ttl = lcm_url_ttl(url);
  if (ttl <= 0) return "";
  return "rig: warning: LCM URL " + url + " has ttl=" + std::to_string(ttl) +
         ": the rig's LCM traffic leaves this host (up to " + std::to_string(ttl) + " router hop" +
         (ttl == 1 ? "" : "s") + "); ttl=0 keeps it here";
}

LcmSettings read_lcm_settings(config::StrictTable& lcm_table,
                              const std::shared_ptr<const signals::Catalogue>& catalogue) {
  LcmSettings settings;
  settings.url = lcm_table.string("url", settings.url);
  if (std::string problem = lcm_url_problem(settings.url); !problem.empty())
    throw lcm_table.error("url", problem);
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
  if (lcm_table.has("signals")) {
    const signals::Catalogue& c = catalogue ? *catalogue : signals::Catalogue::two_axle_vehicle();
    for (const auto& [name, node] : lcm_table.strings("signals", c.entries().size())) {
      const signals::Entry* e = c.find(name);
      if (e == nullptr) throw lcm_table.error_at(*node, "signals", c.unknown_message(name));
      settings.signals.push_back({name, e->unit, e->binding});
    }
    if (settings.signals.empty()) throw lcm_table.error("signals", "names no signal");
  }
  lcm_table.finish();
  return settings;
}

}  // namespace rig::io::lcm
