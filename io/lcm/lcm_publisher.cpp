#include "io/lcm/lcm_publisher.h"

#include <lcm/lcm.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

#include "io/lcm/multicast_route.h"

namespace rig::io::lcm {

LcmPublisher::LcmPublisher(LcmSettings settings) : encoder_(std::move(settings)) {}

LcmPublisher::~LcmPublisher() {
  if (lcm_ != nullptr) lcm_destroy(lcm_);
}

void LcmPublisher::disable(const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  std::fflush(stderr);
  if (lcm_ != nullptr) {
    lcm_destroy(lcm_);
    lcm_ = nullptr;
  }
}

void LcmPublisher::start(const RunInfo& info) {
  encoder_.start(info);
  const std::string& url = encoder_.settings().url;
  // Check the route ourselves first: LCM would print its own multi-line complaint.
  if (std::string problem = check_multicast_route(url); !problem.empty()) {
    disable(problem);
    return;
  }
  lcm_ = lcm_create(url.c_str());
  if (lcm_ == nullptr) {
    disable("rig: LCM disabled: lcm_create(\"" + url + "\") failed. " +
            (parse_udpm_url(url) ? multicast_route_advice() : "The rig runs on without LCM."));
  }
}

void LcmPublisher::consume(const Snapshot& snapshot, std::uint64_t dropped_before) {
  if (lcm_ == nullptr) return;
  EncodedMessage messages[3];
  const std::size_t n = encoder_.encode(snapshot, dropped_before, messages);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& m = messages[i];
    errno = 0;
    if (lcm_publish(lcm_, m.channel->c_str(), m.data, static_cast<unsigned int>(m.size)) == 0) {
      ++published_;
      continue;
    }
    const int error = errno;
    if (error == ENOBUFS || error == EAGAIN || error == EINTR) {
      ++send_failures_;  // a full socket buffer: lose this message, keep going
      continue;
    }
    const bool no_route =
        error == ENETUNREACH || error == EHOSTUNREACH || error == ENODEV || error == EADDRNOTAVAIL;
    disable("rig: LCM disabled: publishing on " + *m.channel + " failed (" +
            (error != 0 ? std::strerror(error) : "unknown error") + "). " +
            (no_route ? multicast_route_advice() : "The rig runs on without LCM."));
    return;
  }
}

void LcmPublisher::stop() {
  if (lcm_ != nullptr) {
    lcm_destroy(lcm_);
    lcm_ = nullptr;
  }
}

}  // namespace rig::io::lcm
