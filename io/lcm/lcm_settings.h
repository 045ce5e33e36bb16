#pragma once
/// @file
/// Settings of the LCM publisher and log writer: the optional [lcm] section of the rig config.

#include <memory>
#include <string>
#include <vector>

#include "io/config/strict_table.h"
#include "io/signals/catalogue.h"

namespace rig::io::lcm {

/// Default LCM URL: UDP multicast that stays on the host (ttl=0) unless the user opens it.
inline constexpr const char* kDefaultLcmUrl = "udpm://239.255.76.67:7667?ttl=0";

/// One signal RIG_SIGNALS carries: its name as configured, and its catalogue binding.
struct LcmSignal {
  std::string name;
  std::string unit;
  signals::Binding binding;
};

struct LcmSettings {
  std::string url = kDefaultLcmUrl;
  /// Prepended to every channel name so that several rigs can share a network ("RIG2_").
  std::string channel_prefix;
  /// Publication rates; 0 disables a channel. A rate at or above the loop rate means every
  /// snapshot. The loop rate is divided by an integer, so e.g. 300 Hz at 1 kHz gives 333 Hz.
  double state_rate_hz = 1000.0;
  double status_rate_hz = 10.0;
  double signals_rate_hz = 100.0;
  /// `signals = ["name", ...]`: what RIG_SIGNALS carries, catalogue names or aliases in that
  /// order. Empty (the default): the slots of model/signals.h's enum by their names, as always.
  std::vector<LcmSignal> signals;

  [[nodiscard]] std::string state_channel() const { return channel_prefix + "RIG_STATE"; }
  [[nodiscard]] std::string status_channel() const { return channel_prefix + "RIG_STATUS"; }
  [[nodiscard]] std::string signals_channel() const { return channel_prefix + "RIG_SIGNALS"; }
};

/// What is wrong with an LCM URL, "" if nothing: `provider://target?key=value&...` with a
/// provider LCM knows (udpm, mpudpm, file, memq, tcpq); for udpm a literal IPv4 multicast group
/// (224.0.0.0/4) with a port 1..65535 (or nothing: LCM's default) and the options ttl (0..255)
/// and recv_buf_size. A malformed URL is a configuration error, never LCM silently off.
std::string lcm_url_problem(const std::string& url);

/// The ttl of a udpm/mpudpm URL (0 if it gives none).
int lcm_url_ttl(const std::string& url);

/// One warning line when the URL lets LCM traffic leave this host (ttl > 0), else "".
std::string lcm_url_warning(const std::string& url);

/// Reads the [lcm] table (keys url, channel_prefix, state_rate_hz, status_rate_hz,
/// signals_rate_hz, signals; all optional; `signals` names entries of `catalogue`, nullptr: the
/// two-axle vehicle's) and rejects unknown keys (calls finish()). Throws config::ConfigError with
/// `file:line` on bad values and unknown signal names (with the closest ones).
LcmSettings read_lcm_settings(config::StrictTable& lcm_table,
                              const std::shared_ptr<const signals::Catalogue>& catalogue = nullptr);

}  // namespace rig::io::lcm
