#include "io/lcm/multicast_route.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rig::io::lcm {

std::optional<MulticastAddress> parse_udpm_url(const std::string& url) {
  constexpr std::string_view kScheme = "udpm://";
  if (url.rfind(kScheme, 0) != 0) return std::nullopt;
  std::string rest = url.substr(kScheme.size());
  rest = rest.substr(0, rest.find('?'));
  MulticastAddress address{"239.255.76.67", 7667};  // LCM's defaults for an empty udpm://
  if (rest.empty()) return address;
  const auto colon = rest.find(':');
  address.group = rest.substr(0, colon);
  if (colon != std::string::npos) {
    try {
      address.port = std::stoi(rest.substr(colon + 1));
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  return address;
}

std::string multicast_route_advice() {
  return "Add a multicast route, e.g. for this host only: `sudo ip route add 224.0.0.0/4 dev lo` "
         "(and `sudo ip link set lo up` if lo is down; or `dev <interface>` to reach other "
         "machines on that network). "
         "The rig runs on without LCM.";
}

std::string check_multicast_route(const std::string& url) {
  const auto address = parse_udpm_url(url);
  if (!address) return {};
  sockaddr_in destination{};
  destination.sin_family = AF_INET;
  destination.sin_port = htons(static_cast<std::uint16_t>(address->port));
  if (inet_pton(AF_INET, address->group.c_str(), &destination.sin_addr) != 1) {
    return {};  // not a literal IPv4 group: leave the judgement to LCM
  }
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) return {};
  // A UDP connect() sends nothing; it only asks the kernel for a route to the group.
  const int rc = ::connect(fd, reinterpret_cast<const sockaddr*>(&destination), sizeof destination);
  const int error = errno;
  ::close(fd);
  if (rc == 0) return {};
  return "rig: LCM disabled: no route to multicast group " + address->group + " of " + url + " (" +
         std::strerror(error) + "). " + multicast_route_advice();
}

}  // namespace rig::io::lcm
