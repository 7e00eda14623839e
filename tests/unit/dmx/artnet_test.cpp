// ArtDmx parsing against hand-written bytes (Art-Net 4: ID, OpCode 0x5000 low byte first,
// ProtVer >= 14, 15-bit Port-Address, even Length 2..512) and each way a packet can be wrong.
#include <gtest/gtest.h>

#include "unit/dmx/packets.h"
#include "shows/dmx/artnet.h"

namespace haze {
namespace {

TEST(ArtNet, ParsesHandWrittenPacket) {
  // Net 1, Sub-Net 2, Universe 3 -> Port-Address 0x0123; 4 data slots.
  const std::vector<uint8_t> bytes = {'A', 'r', 't', '-', 'N', 'e', 't', 0, 0x00, 0x50, 0, 14,
                                      7, 2, 0x23, 0x01, 0, 4, 10, 20, 30, 255};
  const ArtDmxParse p = parseArtDmx(bytes);
  ASSERT_TRUE(p.ok()) << artNetStatusName(p.status);
  EXPECT_EQ(p.packet.sequence, 7);
  EXPECT_EQ(p.packet.physical, 2);
  EXPECT_EQ(p.packet.portAddress, 0x0123);
  EXPECT_EQ(p.packet.hazeUniverse(), 0x0124);
  EXPECT_EQ(p.packet.length, 4);
  EXPECT_EQ(p.packet.slots[0], 10);
  EXPECT_EQ(p.packet.slots[3], 255);
  EXPECT_EQ(p.packet.slots[4], 0);
}

TEST(ArtNet, PortAddressZeroIsHazeUniverseOne) {
  const ArtDmxParse p = parseArtDmx(test::artDmx({}));
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.packet.portAddress, 0);
  EXPECT_EQ(p.packet.hazeUniverse(), 1);
  EXPECT_EQ(p.packet.length, 512);
}

TEST(ArtNet, HighestPortAddressUsesSevenNetBits) {
  test::ArtDmxFields f;
  f.subUni = 0xFF;
  f.net = 0x7F;
  const ArtDmxParse p = parseArtDmx(test::artDmx(f));
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.packet.portAddress, 32767);
}

TEST(ArtNet, NewerProtocolVersionIsAccepted) {
  test::ArtDmxFields f;
  f.protVer = 0x0100;
  EXPECT_TRUE(parseArtDmx(test::artDmx(f)).ok());
}

TEST(ArtNet, RejectsEachMalformedField) {
  auto good = test::artDmx({});
  {
    auto b = good;
    b[3] = 'X';
    EXPECT_EQ(parseArtDmx(b).status, ArtNetStatus::BadId);
  }
  {
    test::ArtDmxFields f;
    f.protVer = 13;
    const auto p = parseArtDmx(test::artDmx(f));
    EXPECT_EQ(p.status, ArtNetStatus::OldProtocol);
    EXPECT_EQ(p.byte, 10);
  }
  for (size_t length : {0u, 1u, 3u, 511u, 514u}) {
    test::ArtDmxFields f;
    f.data.assign(length, 9);
    EXPECT_EQ(parseArtDmx(test::artDmx(f)).status, ArtNetStatus::BadLength) << length;
  }
  {
    auto b = good;
    b.resize(18 + 100);  // Length still says 512
    EXPECT_EQ(parseArtDmx(b).status, ArtNetStatus::Truncated);
  }
  for (size_t n : {0u, 5u, 9u, 12u, 17u}) {
    std::vector<uint8_t> b(good.begin(), good.begin() + static_cast<long>(n));
    EXPECT_EQ(parseArtDmx(b).status, ArtNetStatus::TooShort) << n;
  }
}

TEST(ArtNet, OtherOpCodesAreIgnoredNotMalformed) {
  // ArtPoll (0x2000) and ArtSync (0x5200) are valid Art-Net without levels.
  for (uint16_t op : {0x2000, 0x5200, 0x2100}) {
    auto b = test::artDmx({});
    b[8] = static_cast<uint8_t>(op & 0xFF);
    b[9] = static_cast<uint8_t>(op >> 8);
    EXPECT_EQ(parseArtDmx(b).status, ArtNetStatus::Ignored) << op;
  }
  // OpCode written big-endian by mistake is not ArtDmx either.
  auto b = test::artDmx({});
  b[8] = 0x50;
  b[9] = 0x00;
  EXPECT_EQ(parseArtDmx(b).status, ArtNetStatus::Ignored);
}

TEST(ArtNet, ExtraTrailingBytesAreNotData) {
  test::ArtDmxFields f;
  f.data = {1, 2};
  auto b = test::artDmx(f);
  b.push_back(99);
  const ArtDmxParse p = parseArtDmx(b);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.packet.length, 2);
  EXPECT_EQ(p.packet.slots[2], 0);
}

}  // namespace
}  // namespace haze
