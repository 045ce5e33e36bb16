// The SocketCAN transport on real (virtual) CAN interfaces, against can-utils as the peer.
// Runs inside the VM (label vcan-inside); judged on function and counts, never on timing.
#include <gtest/gtest.h>

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "io/can/transport/socket_can_transport.h"
#include "tests/io/can/vcan/vcan_support.h"
#include "tests/support/alloc_counter.h"

namespace rig::io::can {
namespace {

/// Frames the kernel dropped before any socket saw them (the per-CPU backlog of netif_rx is
/// full; counted per device as rx_dropped). SO_RXQ_OVFL counts only socket-queue drops.
std::uint64_t device_rx_dropped(const std::string& iface) {
  std::ifstream in("/sys/class/net/" + iface + "/statistics/rx_dropped");
  std::uint64_t n = 0;
  in >> n;
  return n;
}

using test::Child;
using test::monotonic_ns;
using test::sh;
using test::sleep_ms;

/// Drains and services `transport` until `done()` or `timeout_ms`; collects frames.
template <class Done>
bool cycle_until(can::transport::SocketCanTransport& transport,
                 std::vector<can::transport::TransportFrame>& got, Done done,
                 int timeout_ms = 5000) {
  const std::int64_t end = monotonic_ns() + std::int64_t{timeout_ms} * 1'000'000;
  while (!done()) {
    if (monotonic_ns() > end) return false;
    transport.service(monotonic_ns());
    transport.drain([&](const can::transport::TransportFrame& f) { got.push_back(f); });
    sleep_ms(1);
  }
  return true;
}

can::transport::TransportSettings settings_for(const char* ifname) {
  can::transport::TransportSettings s;
  s.interface = ifname;
  return s;
}

/// A raw socket of the test's own, for what cansend cannot send (error frames).
int raw_socket(const char* ifname) {
  const int fd = socket(PF_CAN, SOCK_RAW, CAN_RAW);
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(if_nametoindex(ifname));
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

TEST(TransportVcan, ReceivesCansendFramesClassicExtendedAndFdWithKernelTimestamps) {
  RIG_REQUIRE_VCAN();
  can::transport::SocketCanTransport transport(settings_for("vcan0"));
  ASSERT_EQ(transport.state(), BusState::kUp);
  const std::int64_t before = test::realtime_ns();
  ASSERT_EQ(sh("cansend vcan0 123#DEADBEEF && cansend vcan0 1ABCDEF0#0102 && "
               "cansend vcan0 456##1.0102030405060708090A0B0C"),
            0);
  std::vector<can::transport::TransportFrame> got;
  ASSERT_TRUE(cycle_until(transport, got, [&] { return got.size() >= 3; }));
  const std::int64_t after = test::realtime_ns();
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].id, 0x123u);
  EXPECT_FALSE(got[0].extended);
  EXPECT_FALSE(got[0].fd);
  ASSERT_EQ(got[0].len, 4);
  EXPECT_EQ(got[0].data[0], 0xDE);
  EXPECT_EQ(got[0].data[3], 0xEF);
  EXPECT_EQ(got[1].id, 0x1ABCDEF0u);
  EXPECT_TRUE(got[1].extended);
  EXPECT_EQ(got[1].len, 2);
  EXPECT_EQ(got[2].id, 0x456u);
  EXPECT_TRUE(got[2].fd);
  EXPECT_TRUE(got[2].bit_rate_switch);
  ASSERT_EQ(got[2].len, 12);
  EXPECT_EQ(got[2].data[11], 0x0C);
  for (const auto& f : got) {
    EXPECT_GE(f.rx_realtime_ns, before);
    EXPECT_LE(f.rx_realtime_ns, after);
  }
  EXPECT_EQ(transport.counters().frames_received, 3u);
}

TEST(TransportVcan, SentFramesAppearInCandump) {
  RIG_REQUIRE_VCAN();
  can::transport::SocketCanTransport transport(settings_for("vcan0"));
  Child candump("candump -L vcan0");
  // Synchronise: repeat a marker frame until candump shows it (it is listening from then on).
  can::transport::TransportFrame marker;
  marker.id = 0x7FF;
  marker.len = 0;
  bool synced = false;
  for (int i = 0; i < 200 && !synced; ++i) {
    transport.send(marker);
    synced = candump.wait_for_line(
        [](const std::string& l) { return l.find("7FF#") != std::string::npos; }, 50);
  }
  ASSERT_TRUE(synced) << "candump never showed the marker";
  can::transport::TransportFrame classic;
  classic.id = 0x321;
  classic.len = 3;
  classic.data = {0x01, 0x02, 0x03};
  can::transport::TransportFrame ext;
  ext.id = 0x18FEF100;
  ext.extended = true;
  ext.len = 8;
  for (std::uint8_t i = 0; i < 8; ++i) ext.data[i] = static_cast<std::uint8_t>(0xA0 + i);
  can::transport::TransportFrame fd;
  fd.id = 0x222;
  fd.fd = true;
  fd.len = 16;
  for (std::uint8_t i = 0; i < 16; ++i) fd.data[i] = i;
  EXPECT_EQ(transport.send(classic), can::transport::SendStatus::kSent);
  EXPECT_EQ(transport.send(ext), can::transport::SendStatus::kSent);
  EXPECT_EQ(transport.send(fd), can::transport::SendStatus::kSent);
  auto has = [](const char* text) {
    return [text](const std::string& l) { return l.find(text) != std::string::npos; };
  };
  EXPECT_TRUE(candump.wait_for_line(has("vcan0 321#010203"), 5000));
  EXPECT_TRUE(candump.wait_for_line(has("vcan0 18FEF100#A0A1A2A3A4A5A6A7"), 5000));
  EXPECT_TRUE(candump.wait_for_line(
      [](const std::string& l) {
        // candump -L: "222##<flags nibble><data>"; 6.1 sets CANFD_FDF in the flags.
        return l.find("vcan0 222##") != std::string::npos &&
               l.ends_with("000102030405060708090A0B0C0D0E0F");
      },
      5000));
  candump.terminate();
  EXPECT_EQ(transport.counters().send_dropped, 0u);
}

TEST(TransportVcan, ErrorFramesAreCountedNotDelivered) {
  RIG_REQUIRE_VCAN();
  can::transport::SocketCanTransport transport(settings_for("vcan0"));
  const int fd = raw_socket("vcan0");
  ASSERT_GE(fd, 0);
  can_frame err{};
  err.can_id = CAN_ERR_FLAG | CAN_ERR_CRTL;
  err.len = CAN_ERR_DLC;
  err.data[1] = CAN_ERR_CRTL_RX_WARNING;
  for (int i = 0; i < 5; ++i) ASSERT_EQ(write(fd, &err, sizeof(err)), CAN_MTU);
  can_frame data{};
  data.can_id = 0x100;
  data.len = 1;
  ASSERT_EQ(write(fd, &data, sizeof(data)), CAN_MTU);
  close(fd);
  std::vector<can::transport::TransportFrame> got;
  ASSERT_TRUE(cycle_until(
      transport, got, [&] { return got.size() >= 1 && transport.counters().error_frames >= 5; }));
  EXPECT_EQ(transport.counters().error_frames, 5u);
  EXPECT_EQ(transport.state(), BusState::kErrorPassive);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].id, 0x100u);
}

TEST(TransportVcan, BusOffUntilRestartErrorPassiveUntilErrorActive) {
  RIG_REQUIRE_VCAN();
  can::transport::SocketCanTransport transport(settings_for("vcan0"));
  const int fd = raw_socket("vcan0");
  ASSERT_GE(fd, 0);
  std::vector<can::transport::TransportFrame> got;
  auto inject = [&](canid_t classes, std::uint8_t controller) {
    can_frame err{};
    err.can_id = CAN_ERR_FLAG | classes;
    err.len = CAN_ERR_DLC;
    err.data[1] = controller;
    const std::uint64_t before = transport.counters().error_frames;
    ASSERT_EQ(write(fd, &err, sizeof(err)), CAN_MTU);
    ASSERT_TRUE(
        cycle_until(transport, got, [&] { return transport.counters().error_frames > before; }));
  };
  EXPECT_EQ(transport.state(), BusState::kUp);
  inject(CAN_ERR_BUSOFF, 0);
  EXPECT_EQ(transport.state(), BusState::kBusOff);
  EXPECT_EQ(transport.last_error_class(), static_cast<std::uint32_t>(CAN_ERR_BUSOFF));
  inject(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE);  // only a restart ends bus-off
  EXPECT_EQ(transport.state(), BusState::kBusOff);
  inject(CAN_ERR_RESTARTED, 0);
  EXPECT_EQ(transport.state(), BusState::kUp);
  inject(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE);
  EXPECT_EQ(transport.state(), BusState::kErrorPassive);
  inject(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE);
  EXPECT_EQ(transport.state(), BusState::kUp);
  close(fd);
  EXPECT_EQ(transport.counters().error_frames, 5u);
  EXPECT_TRUE(got.empty());
}

TEST(TransportVcan, ReadsWhetherTheInterfaceCarriesCanFd) {
  RIG_REQUIRE_VCAN();
  ASSERT_EQ(sh("ip link add dev rigclassic0 type vcan && ip link set rigclassic0 mtu 16 && "
               "ip link set up dev rigclassic0"),
            0);
  {
    can::transport::SocketCanTransport classic(settings_for("rigclassic0"));
    EXPECT_FALSE(classic.fd_capable());
    can::transport::SocketCanTransport fd(settings_for("vcan0"));
    EXPECT_TRUE(fd.fd_capable());
  }
  sh("ip link del dev rigclassic0");
}

TEST(TransportVcan, KernelFilterPassesOnlyConfiguredIds) {
  RIG_REQUIRE_VCAN();
  can::transport::TransportSettings s = settings_for("vcan0");
  s.use_filter = true;
  s.filter_ids = {0x123};
  s.extended_filter_ids = {0x1ABCDEF0};
  can::transport::SocketCanTransport transport(s);
  ASSERT_EQ(sh("cansend vcan0 124#01 && cansend vcan0 123#02 && cansend vcan0 00000123#03 && "
               "cansend vcan0 1ABCDEF0#04 && cansend vcan0 7FF#05"),
            0);
  std::vector<can::transport::TransportFrame> got;
  cycle_until(transport, got, [&] { return got.size() >= 2; });
  // A little longer: anything else that leaked through would show up now.
  cycle_until(
      transport, got, [] { return false; }, 200);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].id, 0x123u);
  EXPECT_FALSE(got[0].extended);
  EXPECT_EQ(got[1].id, 0x1ABCDEF0u);
}

TEST(TransportVcan, CangenFloodEveryFrameReceivedOrCountedAsKernelDrop) {
  RIG_REQUIRE_VCAN();
  can::transport::TransportSettings s = settings_for("vcan0");
  can::transport::SocketCanTransport transport(s);
  constexpr int kFrames = 20000;
  const std::uint64_t backlog_drops_before = device_rx_dropped("vcan0");
  // Maximal rate (-g 0), random ids, lengths, data; classic and FD (-f), extended mixed in (-e).
  Child gen1("cangen vcan0 -g 0 -I r -L r -D r -n 10000");
  Child gen2("cangen vcan0 -g 0 -e -f -I r -L r -D r -n 10000");
  std::uint64_t handed = 0;
  std::uint64_t sentinels = 0;
  const auto count = [&](const can::transport::TransportFrame& f) {
    ++handed;
    // Random flood frames can carry id 0x555 too: the sentinel is told by its payload.
    constexpr std::array<std::uint8_t, 8> kSentinel{0xDE, 0xAD, 0xBE, 0xEF, 0xCA, 0xFE, 0xF0, 0x0D};
    if (f.id == 0x555 && !f.extended && !f.fd && f.len == 8 &&
        std::equal(kSentinel.begin(), kSentinel.end(), f.data.begin())) {
      ++sentinels;
    }
  };
  // Drain like the loop does (every 1 ms) until both generators have finished.
  const std::int64_t end = monotonic_ns() + 60'000'000'000;
  while (monotonic_ns() < end && !(gen1.exited() && gen2.exited())) {
    transport.service(monotonic_ns());
    transport.drain(count);
    sleep_ms(1);
  }
  EXPECT_EQ(gen1.wait(10000), 0);
  EXPECT_EQ(gen2.wait(10000), 0);
  // SO_RXQ_OVFL reports the socket's drop count with the next frame it delivers: a sentinel
  // behind the flood makes drops at its very end visible too.
  ASSERT_EQ(sh("cansend vcan0 555#DEADBEEFCAFEF00D"), 0);
  for (int i = 0; i < 5000 && sentinels == 0; ++i) {
    transport.service(monotonic_ns());
    transport.drain(count);
    sleep_ms(1);
  }
  ASSERT_GE(sentinels, 1u) << "sentinel frame never arrived";
  const auto& c = transport.counters();
  const std::uint64_t backlog_drops = device_rx_dropped("vcan0") - backlog_drops_before;
  // Every frame is accounted for: received, dropped at our socket (SO_RXQ_OVFL), or dropped by
  // the kernel's input backlog before reaching any socket (rx_dropped of the device); minus one
  // for the sentinel.
  EXPECT_EQ(c.frames_received - 1 + c.rx_overflows + backlog_drops,
            static_cast<std::uint64_t>(kFrames))
      << "received " << c.frames_received << ", socket drops " << c.rx_overflows
      << ", backlog drops " << backlog_drops;
  EXPECT_EQ(handed, c.frames_received);  // every received frame was handed over
  EXPECT_EQ(c.malformed, 0u);
  EXPECT_EQ(transport.state(), BusState::kUp);
  std::printf(
      "[ flood    ] %d frames: %llu received, %llu dropped at the socket (SO_RXQ_OVFL), %llu in "
      "the backlog\n",
      kFrames, static_cast<unsigned long long>(c.frames_received - 1),
      static_cast<unsigned long long>(c.rx_overflows),
      static_cast<unsigned long long>(backlog_drops));
}

TEST(TransportVcan, InterfaceDownThenUpIsSurvivedAndResumes) {
  RIG_REQUIRE_VCAN();
  can::transport::SocketCanTransport transport(settings_for("vcan0"));
  std::vector<can::transport::TransportFrame> got;
  ASSERT_EQ(sh("ip link set vcan0 down"), 0);
  EXPECT_TRUE(cycle_until(transport, got, [&] {
    can::transport::TransportFrame probe;
    probe.id = 0x10;
    transport.send(probe);
    return transport.state() == BusState::kDown;
  })) << "bus never flagged down";
  EXPECT_EQ(transport.counters().bus_down_events, 1u);
  const auto dropped = transport.counters().send_dropped;
  can::transport::TransportFrame f;
  f.id = 0x11;
  EXPECT_EQ(transport.send(f), can::transport::SendStatus::kDropped);
  EXPECT_EQ(transport.counters().send_dropped, dropped + 1);
  // Still down for a while: stays down, no reopen.
  cycle_until(
      transport, got, [] { return false; }, 300);
  EXPECT_EQ(transport.state(), BusState::kDown);
  EXPECT_EQ(transport.counters().reopens, 0u);
  ASSERT_EQ(sh("ip link set vcan0 up"), 0);
  EXPECT_TRUE(cycle_until(transport, got, [&] { return transport.state() == BusState::kUp; }));
  EXPECT_EQ(transport.counters().reopens, 1u);
  ASSERT_EQ(sh("cansend vcan0 124#AB"), 0);
  EXPECT_TRUE(cycle_until(transport, got, [&] { return !got.empty(); }));
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.back().id, 0x124u);
}

TEST(TransportVcan, InterfaceDeletedAndRecreatedIsReopenedWithoutAllocation) {
  RIG_REQUIRE_VCAN();
  can::transport::SocketCanTransport transport(settings_for("vcan1"));
  std::vector<can::transport::TransportFrame> got;
  got.reserve(64);
  ASSERT_EQ(sh("ip link del dev vcan1"), 0);
  std::uint64_t allocations = 0;
  {
    test::AllocationCounter count;
    const std::int64_t end = monotonic_ns() + 5'000'000'000;
    while (transport.state() == BusState::kUp && monotonic_ns() < end) {
      transport.service(monotonic_ns());
      transport.drain([&](const can::transport::TransportFrame& f) { got.push_back(f); });
      can::transport::TransportFrame probe;
      probe.id = 0x10;
      transport.send(probe);
      sleep_ms(1);
    }
    allocations += count.count();
  }
  ASSERT_EQ(transport.state(), BusState::kDown);
  ASSERT_EQ(sh("ip link add dev vcan1 type vcan && ip link set up dev vcan1"), 0);
  {
    test::AllocationCounter count;
    const std::int64_t end = monotonic_ns() + 5'000'000'000;
    while (transport.state() != BusState::kUp && monotonic_ns() < end) {
      transport.service(monotonic_ns());
      transport.drain([&](const can::transport::TransportFrame& f) { got.push_back(f); });
      sleep_ms(1);
    }
    allocations += count.count();
  }
  EXPECT_EQ(allocations, 0u) << "the RT path (drain/send/service incl. reopen) allocated";
  ASSERT_EQ(transport.state(), BusState::kUp);
  EXPECT_EQ(transport.counters().reopens, 1u);
  ASSERT_EQ(sh("cansend vcan1 042#4242"), 0);
  EXPECT_TRUE(cycle_until(transport, got, [&] { return !got.empty(); }));
}

TEST(TransportVcan, DownInterfaceAtStartIsFlaggedDownThenOpened) {
  RIG_REQUIRE_VCAN();
  ASSERT_EQ(sh("ip link set vcan1 down"), 0);
  can::transport::SocketCanTransport transport(settings_for("vcan1"));
  EXPECT_EQ(transport.state(), BusState::kDown);
  ASSERT_EQ(sh("ip link set vcan1 up"), 0);
  std::vector<can::transport::TransportFrame> got;
  EXPECT_TRUE(cycle_until(transport, got, [&] { return transport.state() == BusState::kUp; }));
}

TEST(TransportVcan, MissingInterfaceIsAClearLoadTimeError) {
  RIG_REQUIRE_VCAN();
  try {
    can::transport::SocketCanTransport transport(settings_for("vcan9"));
    FAIL() << "expected can::transport::TransportError";
  } catch (const can::transport::TransportError& e) {
    EXPECT_NE(std::string(e.what()).find("vcan9' does not exist"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rig::io::can
