// UdpReceiver on loopback: a port already held by another receiver (olad, a second visualiser on
// the same laptop) can still be opened, with a warning that unicast is then split, and the
// ports a receiver reports are the ones it bound.
#include <gtest/gtest.h>

#include "shows/dmx/udp_receiver.h"

namespace haze {
namespace {

TEST(UdpReceiver, SharesItsPortsWithAnotherReceiver) {
  UdpReceiverOptions o;
  o.artNetPort = 0;  // a free port, then the same one again
  o.sacnPort = 0;
  auto first = UdpReceiver::open(o);
  ASSERT_TRUE(first.ok()) << first.error().str();
  ASSERT_GT((*first)->artNetPort(), 0);
  ASSERT_GT((*first)->sacnPort(), 0);
  o.artNetPort = (*first)->artNetPort();
  o.sacnPort = (*first)->sacnPort();
  auto second = UdpReceiver::open(o);
  ASSERT_TRUE(second.ok()) << "a second program on the same ports: " << second.error().str();
  EXPECT_EQ((*second)->artNetPort(), o.artNetPort);
  EXPECT_EQ((*second)->sacnPort(), o.sacnPort);
  // The first had the ports to itself (port 0 is never shared); the second says, once a port,
  // that unicast now reaches only one of the two.
  EXPECT_TRUE((*first)->notes().empty());
  const auto& notes = (*second)->notes();
  ASSERT_EQ(notes.size(), 2u);
  const std::string art = "127.0.0.1:" + std::to_string(o.artNetPort) + ": Art-Net sent unicast to this address reaches only one";
  const std::string sacn = "127.0.0.1:" + std::to_string(o.sacnPort) + ": sACN sent unicast to this address reaches only one";
  EXPECT_NE(notes[0].find(art), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find(sacn), std::string::npos) << notes[1];
  // Another loopback address on the same port shares nothing: no warning.
  o.bindAddress = "127.0.0.2";
  auto beside = UdpReceiver::open(o);
  ASSERT_TRUE(beside.ok()) << beside.error().str();
  EXPECT_TRUE((*beside)->notes().empty()) << (*beside)->notes().front();
}

TEST(UdpReceiver, AnAddressOfAnotherMachineIsAClearError) {
  UdpReceiverOptions o;
  o.bindAddress = "192.0.2.1";  // TEST-NET-1: never an address of this machine
  o.artNetPort = 0;
  o.sacn = false;
  auto r = UdpReceiver::open(o);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().str().find("192.0.2.1"), std::string::npos) << r.error().str();
}

}  // namespace
}  // namespace haze
