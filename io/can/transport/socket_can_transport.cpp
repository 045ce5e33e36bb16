#include "io/can/transport/socket_can_transport.h"

#include "io/can/transport/transport_error.h"

#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <utility>

namespace rig::io::can::transport {
namespace {

// SO_RXQ_OVFL is not in every libc's headers.
#ifndef SO_RXQ_OVFL
#define SO_RXQ_OVFL 40
#endif

constexpr std::size_t kControlBytes =
    CMSG_SPACE(sizeof(struct timespec)) + CMSG_SPACE(sizeof(std::uint32_t));

/// The interface's MTU (CAN_MTU: classic only, CANFD_MTU: FD too), 0 if it cannot be read.
int interface_mtu(const std::string& name);

bool is_down_errno(int err) { return err == ENETDOWN || err == ENODEV || err == ENXIO; }

/// Fills `req` with the interface name; false if it does not fit.
bool set_name(ifreq& req, const std::string& name) {
  std::memset(&req, 0, sizeof(req));
  if (name.empty() || name.size() >= sizeof(req.ifr_name)) return false;
  std::memcpy(req.ifr_name, name.data(), name.size());
  return true;
}

int interface_mtu(const std::string& name) {
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return 0;
  ifreq req{};
  int mtu = 0;
  if (set_name(req, name) && ::ioctl(fd, SIOCGIFMTU, &req) == 0) mtu = req.ifr_mtu;
  ::close(fd);
  return mtu;
}

}  // namespace

struct SocketCanTransport::RecvBuffers {
  std::array<mmsghdr, kBatch> msgs{};
  std::array<iovec, kBatch> iovs{};
  std::array<canfd_frame, kBatch> frames{};
  alignas(cmsghdr) std::array<std::array<unsigned char, kControlBytes>, kBatch> control{};
};

bool can_sockets_available(std::string* why) {
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    if (why != nullptr) {
      *why = std::string("socket(PF_CAN, SOCK_RAW, CAN_RAW) failed: ") + std::strerror(errno);
    }
    return false;
  }
  ::close(fd);
  return true;
}

SocketCanTransport::SocketCanTransport(TransportSettings settings)
    : settings_(std::move(settings)), rx_(std::make_unique<RecvBuffers>()) {
  const std::string& ifname = settings_.interface;
  std::string why;
  if (!can_sockets_available(&why)) {
    throw TransportError("CAN interface '" + ifname + "': this kernel has no SocketCAN (" + why +
                         "); load the can and can-raw modules, use scripts/with-vcan for tests, "
                         "or run without CAN (--can none)");
  }
  ifreq req{};
  if (!set_name(req, ifname)) {
    throw TransportError("CAN interface name '" + ifname + "' is empty or too long");
  }
  if (settings_.use_filter) {
    for (std::uint32_t id : settings_.filter_ids) {
      if (id > CAN_SFF_MASK) {
        throw TransportError("CAN filter id " + std::to_string(id) + " is not an 11-bit id");
      }
      filters_.push_back({id, CAN_SFF_MASK | CAN_EFF_FLAG | CAN_RTR_FLAG});
    }
    for (std::uint32_t id : settings_.extended_filter_ids) {
      if (id > CAN_EFF_MASK) {
        throw TransportError("CAN filter id " + std::to_string(id) + " is not a 29-bit id");
      }
      filters_.push_back({id | CAN_EFF_FLAG, CAN_EFF_MASK | CAN_EFF_FLAG | CAN_RTR_FLAG});
    }
  }
  for (std::size_t i = 0; i < kBatch; ++i) {
    rx_->iovs[i].iov_base = &rx_->frames[i];
    rx_->iovs[i].iov_len = sizeof(canfd_frame);
    rx_->msgs[i].msg_hdr.msg_iov = &rx_->iovs[i];
    rx_->msgs[i].msg_hdr.msg_iovlen = 1;
  }
  fd_capable_ = interface_mtu(ifname) >= static_cast<int>(CANFD_MTU);
  const int fd = open_socket();
  if (fd < 0) {
    const int err = -fd;
    if (err == ENODEV) {
      throw TransportError("CAN interface '" + ifname +
                           "' does not exist (create it, e.g. `ip link add dev " + ifname +
                           " type vcan`, or fix [can] interface / --can)");
    }
    if (err != ENETDOWN) {
      throw TransportError("CAN interface '" + ifname +
                           "': cannot open a raw socket: " + std::strerror(err));
    }
    // Exists but is down: start flagged down; service() reopens once it is up.
    state_ = BusState::kDown;
    return;
  }
  fd_ = fd;
  state_ = BusState::kUp;
}

SocketCanTransport::~SocketCanTransport() {
  if (fd_ >= 0) ::close(fd_);
}

int SocketCanTransport::open_socket() noexcept {
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return -errno;
  auto fail = [fd](int err) {
    ::close(fd);
    return -err;
  };
  ifreq req{};
  if (!set_name(req, settings_.interface)) return fail(EINVAL);
  if (::ioctl(fd, SIOCGIFFLAGS, &req) < 0) return fail(errno);
  if ((req.ifr_flags & IFF_UP) == 0) return fail(ENETDOWN);
  if (::ioctl(fd, SIOCGIFINDEX, &req) < 0) return fail(errno);
  const int ifindex = req.ifr_ifindex;

  const int on = 1;
  if (settings_.fd && ::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &on, sizeof(on)) < 0) {
    return fail(errno);
  }
  if (settings_.use_filter) {
    // An empty filter list means "receive no data frames" (error frames still arrive).
    const auto bytes = static_cast<socklen_t>(filters_.size() * sizeof(::can_filter));
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, filters_.empty() ? nullptr : filters_.data(),
                     bytes) < 0) {
      return fail(errno);
    }
  }
  const can_err_mask_t err_mask = CAN_ERR_MASK;
  if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask, sizeof(err_mask)) < 0) {
    return fail(errno);
  }
  if (::setsockopt(fd, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof(on)) < 0) return fail(errno);
  // Kernel drop counter; optional (older kernels), so a failure is ignored.
  (void)::setsockopt(fd, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof(on));
  if (settings_.receive_buffer_bytes > 0) {
    (void)::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &settings_.receive_buffer_bytes,
                       sizeof(settings_.receive_buffer_bytes));
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifindex;
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)) < 0) return fail(errno);
  return fd;
}

void SocketCanTransport::go_down() noexcept {
  if (state_ == BusState::kUp) ++counters_.bus_down_events;
  state_ = BusState::kDown;
  counters_.send_dropped += retry_.clear();
  // The socket stays open until the reopen replaces it; reads on it just fail.
}

void SocketCanTransport::on_error_frame(const ::canfd_frame& frame) noexcept {
  ++counters_.error_frames;
  last_error_class_ = frame.can_id & CAN_ERR_MASK;
  last_error_ctrl_ = frame.len > 1 ? frame.data[1] : 0;
  if ((last_error_class_ & CAN_ERR_BUSOFF) != 0) {
    controller_ = BusState::kBusOff;
  } else if ((last_error_class_ & CAN_ERR_RESTARTED) != 0) {
    controller_ = BusState::kUp;
  } else if ((last_error_class_ & CAN_ERR_CRTL) != 0 && last_error_ctrl_ == CAN_ERR_CRTL_ACTIVE) {
    if (controller_ == BusState::kErrorPassive) controller_ = BusState::kUp;
  } else if (controller_ == BusState::kUp) {
    controller_ = BusState::kErrorPassive;  // bus-off ends only with a restart
  }
}

void SocketCanTransport::service(std::int64_t monotonic_ns) noexcept {
  if (state_ == BusState::kDown) {
    if (monotonic_ns < next_reopen_ns_) return;
    next_reopen_ns_ = monotonic_ns + settings_.reopen_interval_ns;
    const int fd = open_socket();
    if (fd < 0) return;
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
    last_overflow_ = 0;
    state_ = BusState::kUp;
    controller_ = BusState::kUp;  // a link down/up restarts the controller (error-active)
    ++counters_.reopens;
    return;
  }
  if (retry_.size() > 0) {
    // ENOBUFS rule: one retry, then drop.
    counters_.send_dropped +=
        retry_.retry_all([this](const TransportFrame& f) { return send_now(f) == Raw::kSent; });
  }
}

bool SocketCanTransport::read_batch(std::size_t& got) noexcept {
  got = 0;
  if (state_ != BusState::kUp || fd_ < 0) return false;
  for (std::size_t i = 0; i < kBatch; ++i) {
    msghdr& hdr = rx_->msgs[i].msg_hdr;
    hdr.msg_name = nullptr;
    hdr.msg_namelen = 0;
    hdr.msg_control = rx_->control[i].data();
    hdr.msg_controllen = kControlBytes;
    hdr.msg_flags = 0;
  }
  const int n =
      ::recvmmsg(fd_, rx_->msgs.data(), static_cast<unsigned>(kBatch), MSG_DONTWAIT, nullptr);
  if (n < 0) {
    const int err = errno;
    if (err == EAGAIN || err == EWOULDBLOCK || err == EINTR) return false;
    if (is_down_errno(err)) {
      go_down();
    } else {
      ++counters_.other_errors;
    }
    return false;
  }
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const unsigned len = rx_->msgs[k].msg_len;
    const canfd_frame& raw = rx_->frames[k];
    msghdr& hdr = rx_->msgs[k].msg_hdr;
    std::int64_t stamp_ns = 0;
    for (cmsghdr* c = CMSG_FIRSTHDR(&hdr); c != nullptr; c = CMSG_NXTHDR(&hdr, c)) {
      if (c->cmsg_level != SOL_SOCKET) continue;
      if (c->cmsg_type == SO_TIMESTAMPNS) {
        timespec ts{};
        std::memcpy(&ts, CMSG_DATA(c), sizeof(ts));
        stamp_ns = static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
      } else if (c->cmsg_type == SO_RXQ_OVFL) {
        std::uint32_t dropped = 0;
        std::memcpy(&dropped, CMSG_DATA(c), sizeof(dropped));
        counters_.rx_overflows += static_cast<std::uint32_t>(dropped - last_overflow_);
        last_overflow_ = dropped;
      }
    }
    if (len != CAN_MTU && len != CANFD_MTU) {
      ++counters_.malformed;
      continue;
    }
    if ((raw.can_id & CAN_ERR_FLAG) != 0) {
      on_error_frame(raw);
      continue;
    }
    TransportFrame& out = batch_[got];
    out.extended = (raw.can_id & CAN_EFF_FLAG) != 0;
    out.id = raw.can_id & (out.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
    out.remote = (raw.can_id & CAN_RTR_FLAG) != 0;
    out.fd = len == CANFD_MTU;
    out.bit_rate_switch = out.fd && (raw.flags & CANFD_BRS) != 0;
    const std::uint8_t max_len = out.fd ? CANFD_MAX_DLEN : CAN_MAX_DLEN;
    out.len = raw.len > max_len ? max_len : raw.len;
    std::memcpy(out.data.data(), raw.data, out.len);
    out.rx_realtime_ns = stamp_ns;
    ++got;
    ++counters_.frames_received;
  }
  return n == static_cast<int>(kBatch);
}

SocketCanTransport::Raw SocketCanTransport::send_now(const TransportFrame& frame) noexcept {
  canfd_frame raw{};
  raw.can_id =
      frame.extended ? ((frame.id & CAN_EFF_MASK) | CAN_EFF_FLAG) : (frame.id & CAN_SFF_MASK);
  const std::uint8_t max_len = frame.fd ? CANFD_MAX_DLEN : CAN_MAX_DLEN;
  if (frame.len > max_len) return Raw::kInvalid;
  if (frame.remote && !frame.fd) raw.can_id |= CAN_RTR_FLAG;
  raw.len = frame.len;
  if (frame.fd && frame.bit_rate_switch) raw.flags = CANFD_BRS;
  std::memcpy(raw.data, frame.data.data(), frame.len);
  const std::size_t mtu = frame.fd ? CANFD_MTU : CAN_MTU;
  const ssize_t n = ::send(fd_, &raw, mtu, MSG_DONTWAIT);
  if (n == static_cast<ssize_t>(mtu)) {
    ++counters_.frames_sent;
    return Raw::kSent;
  }
  const int err = n < 0 ? errno : EIO;
  if (err == ENOBUFS || err == EAGAIN || err == EWOULDBLOCK) return Raw::kNoBuffer;
  if (is_down_errno(err)) {
    go_down();
    return Raw::kDown;
  }
  ++counters_.other_errors;
  return Raw::kInvalid;
}

SendStatus SocketCanTransport::send(const TransportFrame& frame) noexcept {
  if (state_ != BusState::kUp || fd_ < 0) {
    ++counters_.send_dropped;
    return SendStatus::kDropped;
  }
  switch (send_now(frame)) {
    case Raw::kSent:
      return SendStatus::kSent;
    case Raw::kNoBuffer:
      ++counters_.send_no_buffer;
      if (retry_.push(frame)) return SendStatus::kDeferred;
      ++counters_.send_dropped;
      return SendStatus::kDropped;
    case Raw::kDown:
    case Raw::kInvalid:
      break;
  }
  ++counters_.send_dropped;
  return SendStatus::kDropped;
}

}  // namespace rig::io::can::transport
