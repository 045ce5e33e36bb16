// Host tests of the transport: the ENOBUFS rule and the load-time error without AF_CAN.
// The socket behaviour itself is tested on vcan in tests/io/can/vcan (inside the VM).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/can/transport/send_retry_queue.h"
#include "io/can/transport/socket_can_transport.h"
#include "io/can/transport/transport_error.h"

namespace rig::io::can {
namespace {

can::transport::TransportFrame frame_with_id(std::uint32_t id) {
  can::transport::TransportFrame f;
  f.id = id;
  f.len = 1;
  f.data[0] = static_cast<std::uint8_t>(id);
  return f;
}

TEST(SendRetryQueue, RetriesEachFrameOnceInOrderThenForgetsIt) {
  can::transport::SendRetryQueue q;
  ASSERT_TRUE(q.push(frame_with_id(1)));
  ASSERT_TRUE(q.push(frame_with_id(2)));
  ASSERT_TRUE(q.push(frame_with_id(3)));
  std::vector<std::uint32_t> offered;
  // The kernel accepts 1 and 3, refuses 2 again: 2 is dropped (refused count 1).
  const std::size_t refused = q.retry_all([&](const can::transport::TransportFrame& f) {
    offered.push_back(f.id);
    return f.id != 2;
  });
  EXPECT_EQ(refused, 1u);
  EXPECT_EQ(offered, (std::vector<std::uint32_t>{1, 2, 3}));
  EXPECT_EQ(q.size(), 0u);
  // Nothing is offered a second time.
  offered.clear();
  EXPECT_EQ(q.retry_all([&](const can::transport::TransportFrame& f) {
    offered.push_back(f.id);
    return true;
  }),
            0u);
  EXPECT_TRUE(offered.empty());
}

TEST(SendRetryQueue, RefusesBeyondCapacity) {
  can::transport::SendRetryQueue q;
  for (std::size_t i = 0; i < can::transport::SendRetryQueue::kCapacity; ++i) {
    ASSERT_TRUE(q.push(frame_with_id(static_cast<std::uint32_t>(i))));
  }
  EXPECT_FALSE(q.push(frame_with_id(999)));
  EXPECT_EQ(q.clear(), can::transport::SendRetryQueue::kCapacity);
  EXPECT_EQ(q.size(), 0u);
}

TEST(SocketCanTransport, ClearErrorWithoutSocketCan) {
  std::string why;
  if (can::transport::can_sockets_available(&why)) GTEST_SKIP() << "this kernel has AF_CAN";
  EXPECT_NE(why.find("socket(PF_CAN"), std::string::npos) << why;
  can::transport::TransportSettings settings;
  settings.interface = "vcan0";
  try {
    can::transport::SocketCanTransport transport(settings);
    FAIL() << "expected can::transport::TransportError";
  } catch (const can::transport::TransportError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no SocketCAN"), std::string::npos) << what;
    EXPECT_NE(what.find("--can none"), std::string::npos) << what;
    EXPECT_NE(what.find("vcan0"), std::string::npos) << what;
  }
}

TEST(SocketCanTransport, RejectsBadInterfaceNameOrFilter) {
  if (!can::transport::can_sockets_available()) GTEST_SKIP() << "needs AF_CAN";
  can::transport::TransportSettings settings;
  settings.interface = "a-name-far-too-long-for-ifreq";
  EXPECT_THROW(can::transport::SocketCanTransport{settings}, can::transport::TransportError);
  settings.interface = "vcan0";
  settings.use_filter = true;
  settings.filter_ids = {0x800};
  EXPECT_THROW(can::transport::SocketCanTransport{settings}, can::transport::TransportError);
}

}  // namespace
}  // namespace rig::io::can
