#pragma once
/// @file
/// Checks, before LCM is created, that a UDP multicast URL has a route, so that a host without
/// one gets a single clear message instead of LCM's own noise.

#include <optional>
#include <string>

namespace rig::io::lcm {

/// Host and port of a `udpm://HOST:PORT?...` URL; nullopt for other providers.
struct MulticastAddress {
  std::string group;
  int port = 0;
};
std::optional<MulticastAddress> parse_udpm_url(const std::string& url);

/// Empty if the kernel has a route to the URL's group (or the URL is not udpm); otherwise the
/// message to print: what failed and how to add the route.
std::string check_multicast_route(const std::string& url);

/// The advice given whenever LCM cannot be used for want of a multicast route.
std::string multicast_route_advice();

}  // namespace rig::io::lcm
