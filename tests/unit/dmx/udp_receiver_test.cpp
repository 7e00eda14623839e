// UdpReceiver on loopback: a port already held by another receiver (olad, a second visualiser on
// the same laptop) can still be opened, and the ports a receiver reports are the ones it bound.
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
