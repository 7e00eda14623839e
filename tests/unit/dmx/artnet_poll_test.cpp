// ArtPollReply field by field against the Art-Net 4 table (offsets written out here, not taken
// from the builder), BindIndex pages of four ports, and a real ArtPoll over loopback answered.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>
#include <string>
#include <vector>

#include "shows/dmx/artnet_poll.h"
#include "shows/dmx/dmx_input.h"
#include "shows/dmx/udp_receiver.h"
#include "unit/dmx/test_show.h"

namespace haze {
namespace {

std::vector<uint8_t> artPoll() {
  std::vector<uint8_t> p = {'A', 'r', 't', '-', 'N', 'e', 't', 0, 0x00, 0x20, 0, 14, 0x02, 0x00};
  return p;
}

TEST(ArtPoll, RecognisesOnlyArtPoll) {
  EXPECT_TRUE(isArtPoll(artPoll()));
  std::vector<uint8_t> dmx = artPoll();
  dmx[9] = 0x50;  // OpDmx
  EXPECT_FALSE(isArtPoll(dmx));
  std::vector<uint8_t> old = artPoll();
  old[11] = 13;  // ProtVer below 14
  EXPECT_FALSE(isArtPoll(old));
  const std::vector<uint8_t> full = artPoll();
  EXPECT_FALSE(isArtPoll(std::vector<uint8_t>(full.begin(), full.begin() + 12)));
}

TEST(ArtPoll, ReplyFieldsFollowTheArtNet4Table) {
  ArtNodeInfo node;
  node.ipv4 = 0x7F4D010A;  // 127.77.1.10
  node.hazeUniverses = {1, 2, 18};  // Port-Addresses 0, 1 (0:0:0, 0:0:1) and 17 (0:1:1)
  const auto replies = artPollReplies(node);
  ASSERT_EQ(replies.size(), 2u) << "Sub-Net 0 and Sub-Net 1 are two pages";
  const std::vector<uint8_t>& r = replies[0];
  ASSERT_EQ(r.size(), 239u);
  EXPECT_EQ(std::memcmp(r.data(), "Art-Net", 8), 0);
  EXPECT_EQ(r[8], 0x00);  // OpPollReply 0x2100, low byte first
  EXPECT_EQ(r[9], 0x21);
  EXPECT_EQ(r[10], 127);  // IP address, most significant byte first
  EXPECT_EQ(r[11], 77);
  EXPECT_EQ(r[12], 1);
  EXPECT_EQ(r[13], 10);
  EXPECT_EQ(r[14] | (r[15] << 8), 6454);
  EXPECT_EQ(r[18], 0);  // NetSwitch
  EXPECT_EQ(r[19], 0);  // SubSwitch
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&r[26])), "haze");
  EXPECT_EQ(r[173], 2);  // NumPorts
  EXPECT_EQ(r[174], 0x80);  // output, DMX512
  EXPECT_EQ(r[175], 0x80);
  EXPECT_EQ(r[176], 0x00);
  EXPECT_EQ(r[190], 0);  // SwOut
  EXPECT_EQ(r[191], 1);
  EXPECT_EQ(r[200], 0x06);  // StVisual
  EXPECT_EQ(r[211], 1);     // BindIndex
  EXPECT_EQ(r[212] & 0x08, 0x08);  // 15-bit Port-Address support
  const std::vector<uint8_t>& r2 = replies[1];
  EXPECT_EQ(r2[19], 1);
  EXPECT_EQ(r2[173], 1);
  EXPECT_EQ(r2[190], 1);
  EXPECT_EQ(r2[211], 2);
}

TEST(ArtPoll, FourPortsPerReplyAndOneReplyWhenNothingIsPatched) {
  ArtNodeInfo node;
  for (int u = 1; u <= 6; ++u) node.hazeUniverses.insert(u);
  const auto replies = artPollReplies(node);
  ASSERT_EQ(replies.size(), 2u);
  EXPECT_EQ(replies[0][173], 4);
  EXPECT_EQ(replies[1][173], 2);
  EXPECT_EQ(replies[1][190], 4);
  EXPECT_EQ(artPollReplies(ArtNodeInfo{}).size(), 1u);
  EXPECT_EQ(artPollReplies(ArtNodeInfo{})[0][173], 0);
}

TEST(ArtPoll, ALiveReceiverAnswersAPollOnLoopback) {
  const test::TestShow t = test::makeTestShow();
  UdpReceiverOptions o;
  o.artNetPort = 0;
  o.sacn = false;
  o.artNetUniverses = patchedUniverses(t.show);
  auto r = UdpReceiver::open(o);
  ASSERT_TRUE(r.ok()) << r.error().str();
  const int console = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(console, 0);
  sockaddr_in self{};
  self.sin_family = AF_INET;
  self.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(console, reinterpret_cast<sockaddr*>(&self), sizeof self), 0);
  sockaddr_in to = self;
  to.sin_port = htons(static_cast<uint16_t>((*r)->artNetPort()));
  const std::vector<uint8_t> poll = artPoll();
  ASSERT_EQ(::sendto(console, poll.data(), poll.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to),
            static_cast<ssize_t>(poll.size()));
  DmxInput input(t.show, t.profiles);
  int pumped = 0;
  for (int i = 0; i < 50 && pumped == 0; ++i) pumped = (*r)->pump(input, 0.0, 20);
  ASSERT_EQ(pumped, 1);
  EXPECT_EQ((*r)->artPollsAnswered(), 1);
  pollfd pfd{console, POLLIN, 0};
  ASSERT_EQ(::poll(&pfd, 1, 2000), 1) << "no ArtPollReply within 2 s";
  uint8_t reply[600];
  const ssize_t n = ::recv(console, reply, sizeof reply, 0);
  ::close(console);
  ASSERT_EQ(n, 239);
  EXPECT_EQ(reply[9], 0x21);
  EXPECT_EQ(reply[10], 127);  // the address the console reached
  EXPECT_GE(reply[173], 1) << "the test show's patched universes are listed as output ports";
}

}  // namespace
}  // namespace haze
