// sACN E1.31 data packets: a full 638-byte packet with the length words the standard gives
// (0x726E, 0x7258, 0x720B), every field check, options bits, ignored packet kinds.
#include <gtest/gtest.h>

#include "unit/dmx/packets.h"
#include "shows/dmx/sacn.h"

namespace haze {
namespace {

TEST(Sacn, FullPacketHasTheStandardLengthWords) {
  const auto b = test::sacn({});
  ASSERT_EQ(b.size(), 638u);
  EXPECT_EQ((b[16] << 8) | b[17], 0x726E);
  EXPECT_EQ((b[38] << 8) | b[39], 0x7258);
  EXPECT_EQ((b[115] << 8) | b[116], 0x720B);
  EXPECT_EQ((b[123] << 8) | b[124], 513);
}

TEST(Sacn, ParsesEveryField) {
  test::SacnFields f;
  f.cidFill = 0xAB;
  f.sourceName = "Eos";
  f.priority = 150;
  f.syncAddress = 7;
  f.sequence = 42;
  f.options = kSacnOptionPreview;
  f.universe = 0x0102;
  f.slots[0] = 255;
  f.slots[511] = 17;
  const SacnParse p = parseSacn(test::sacn(f));
  ASSERT_TRUE(p.ok()) << sacnStatusName(p.status);
  EXPECT_EQ(p.packet.cid[0], 0xAB);
  EXPECT_EQ(p.packet.cid[15], 0xAB);
  EXPECT_EQ(p.packet.sourceName, "Eos");
  EXPECT_EQ(p.packet.priority, 150);
  EXPECT_EQ(p.packet.syncAddress, 7);
  EXPECT_EQ(p.packet.sequence, 42);
  EXPECT_TRUE(p.packet.preview());
  EXPECT_FALSE(p.packet.terminated());
  EXPECT_EQ(p.packet.universe, 258);
  EXPECT_EQ(p.packet.slotCount, 512);
  EXPECT_EQ(p.packet.slots[0], 255);
  EXPECT_EQ(p.packet.slots[511], 17);
}

TEST(Sacn, ShortPacketsCarryFewerSlots) {
  test::SacnFields f;
  f.slots = {1, 2, 3};
  const SacnParse p = parseSacn(test::sacn(f));
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.packet.slotCount, 3);
  EXPECT_EQ(p.packet.slots[2], 3);
  EXPECT_EQ(p.packet.slots[3], 0);
  // A packet with only the START code is valid: no slots.
  f.slots.clear();
  EXPECT_TRUE(parseSacn(test::sacn(f)).ok());
}

TEST(Sacn, StreamTerminatedBitIsBit6) {
  test::SacnFields f;
  f.options = 0x40;
  const SacnParse p = parseSacn(test::sacn(f));
  ASSERT_TRUE(p.ok());
  EXPECT_TRUE(p.packet.terminated());
  EXPECT_FALSE(p.packet.preview());
}

struct Corruption {
  const char* what;
  size_t at;
  uint8_t value;
  SacnStatus expected;
};

TEST(Sacn, RejectsEachMalformedField) {
  const Corruption cases[] = {
      {"preamble", 1, 0x11, SacnStatus::BadPreamble},
      {"postamble", 3, 0x01, SacnStatus::BadPostamble},
      {"acn id", 8, 'X', SacnStatus::BadAcnId},
      {"acn id padding", 15, 1, SacnStatus::BadAcnId},
      {"root flags", 16, 0x62, SacnStatus::BadRootLength},
      {"root length", 17, 0x6F, SacnStatus::BadRootLength},
      {"root vector", 21, 0x05, SacnStatus::BadRootVector},
      {"framing flags", 38, 0x32, SacnStatus::BadFramingLength},
      {"framing length", 39, 0x57, SacnStatus::BadFramingLength},
      {"framing vector", 43, 0x01, SacnStatus::BadFramingVector},
      {"priority", 108, 201, SacnStatus::BadPriority},
      {"universe 0", 114, 0, SacnStatus::BadUniverse},
      {"dmp flags", 115, 0x02, SacnStatus::BadDmpLength},
      {"dmp length", 116, 0x0A, SacnStatus::BadDmpLength},
      {"dmp vector", 117, 0x01, SacnStatus::BadDmpVector},
      {"address type", 118, 0xA2, SacnStatus::BadAddressType},
      {"first address", 120, 1, SacnStatus::BadFirstAddress},
      {"increment", 122, 2, SacnStatus::BadIncrement},
      {"property count", 124, 0x00, SacnStatus::BadPropertyCount},
  };
  for (const Corruption& c : cases) {
    auto b = test::sacn({});
    b[c.at] = c.value;
    const SacnParse p = parseSacn(b);
    EXPECT_EQ(p.status, c.expected) << c.what << ": got " << sacnStatusName(p.status);
  }
}

TEST(Sacn, UniverseRangeIsOneTo63999) {
  test::SacnFields f;
  f.universe = 63999;
  EXPECT_TRUE(parseSacn(test::sacn(f)).ok());
  f.universe = 64000;
  EXPECT_EQ(parseSacn(test::sacn(f)).status, SacnStatus::BadUniverse);
  f.universe = 64214;  // the discovery universe carries no data packets
  EXPECT_EQ(parseSacn(test::sacn(f)).status, SacnStatus::BadUniverse);
}

TEST(Sacn, TruncatedOrPaddedDatagramsFailTheLengthCheck) {
  auto b = test::sacn({});
  auto shorter = b;
  shorter.pop_back();
  EXPECT_EQ(parseSacn(shorter).status, SacnStatus::BadRootLength);
  auto longer = b;
  longer.push_back(0);
  EXPECT_EQ(parseSacn(longer).status, SacnStatus::BadRootLength);
  for (size_t n : {0u, 10u, 37u, 60u, 114u, 125u}) {
    std::vector<uint8_t> cut(b.begin(), b.begin() + static_cast<long>(n));
    EXPECT_NE(parseSacn(cut).status, SacnStatus::Ok) << n;
  }
  EXPECT_EQ(parseSacn(std::vector<uint8_t>(b.begin(), b.begin() + 20)).status, SacnStatus::TooShort);
}

TEST(Sacn, PropertyCountAbove513IsRejected) {
  // 514 property values: the lengths nest, but DMX has at most 512 slots.
  test::SacnFields f;
  f.slots.assign(513, 1);
  EXPECT_EQ(parseSacn(test::sacn(f)).status, SacnStatus::BadPropertyCount);
}

TEST(Sacn, ExtendedPacketsAndAlternateStartCodesAreIgnored) {
  EXPECT_EQ(parseSacn(test::sacnSync(7)).status, SacnStatus::Ignored);
  test::SacnFields f;
  f.startCode = 0x17;  // ASCII text
  EXPECT_EQ(parseSacn(test::sacn(f)).status, SacnStatus::Ignored);
  // A data packet is not an extended one.
  EXPECT_EQ(parseSacnExtended(test::sacn({})).status, SacnStatus::NotExtended);
}

TEST(Sacn, PerSlotPriorityPacketsAreReadAndChecked) {
  test::SacnFields f;
  f.startCode = 0xDD;
  f.slots.assign(4, 0);
  f.slots = {200, 0, 50, 100};
  const SacnParse p = parseSacn(test::sacn(f));
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.packet.startCode, kSacnStartPerSlotPriority);
  EXPECT_EQ(p.packet.slotCount, 4);
  EXPECT_EQ(p.packet.slots[2], 50);
  f.slots[3] = 201;  // per-slot priorities stop at 200 too
  const SacnParse bad = parseSacn(test::sacn(f));
  EXPECT_EQ(bad.status, SacnStatus::BadPriority);
  EXPECT_EQ(bad.byte, 126 + 3);
}

TEST(Sacn, SynchronizationPacketFields) {
  const SacnExtendedParse p = parseSacnExtended(test::sacnSync(7001, 42, 0x5A));
  ASSERT_TRUE(p.ok()) << sacnError(p.status, p.byte).str();
  EXPECT_TRUE(p.isSync);
  EXPECT_EQ(p.sync.syncAddress, 7001);
  EXPECT_EQ(p.sync.sequence, 42);
  EXPECT_EQ(p.sync.cid[15], 0x5A);
  EXPECT_EQ(parseSacnExtended(test::sacnSync(0)).status, SacnStatus::BadSyncAddress);
  EXPECT_EQ(parseSacnExtended(test::sacnSync(64000)).status, SacnStatus::BadSyncAddress);
  auto longer = test::sacnSync(1);
  longer.push_back(0);  // root length follows the datagram, framing does not
  EXPECT_EQ(parseSacnExtended(longer).status, SacnStatus::BadRootLength);
  test::put16(longer, 16, 0x7000 | 34);
  test::put16(longer, 38, 0x7000 | 12);  // nested, but a sync packet is 11 bytes of framing
  EXPECT_EQ(parseSacnExtended(longer).status, SacnStatus::BadExtendedLength);
  auto vector = test::sacnSync(1);
  vector[43] = 0x03;
  EXPECT_EQ(parseSacnExtended(vector).status, SacnStatus::BadExtendedVector);
  auto cut = test::sacnSync(1);
  cut.resize(45);
  EXPECT_EQ(parseSacnExtended(cut).status, SacnStatus::BadRootLength);
}

TEST(Sacn, UniverseDiscoveryPacketFields) {
  const SacnExtendedParse p = parseSacnExtended(test::sacnDiscovery({1, 2, 300}, 1, 2, "desk"));
  ASSERT_TRUE(p.ok()) << sacnError(p.status, p.byte).str();
  EXPECT_FALSE(p.isSync);
  EXPECT_EQ(p.discovery.sourceName, "desk");
  EXPECT_EQ(p.discovery.page, 1);
  EXPECT_EQ(p.discovery.lastPage, 2);
  EXPECT_EQ(p.discovery.universes, (std::vector<uint16_t>{1, 2, 300}));
  EXPECT_TRUE(parseSacnExtended(test::sacnDiscovery({})).ok());  // a source with no universes
  EXPECT_EQ(parseSacnExtended(test::sacnDiscovery({1}, 3, 2)).status, SacnStatus::BadDiscoveryPage);
  EXPECT_EQ(parseSacnExtended(test::sacnDiscovery({1, 0})).status, SacnStatus::BadDiscoveryUniverse);
  EXPECT_EQ(parseSacnExtended(test::sacnDiscovery(std::vector<uint16_t>(513, 5))).status,
            SacnStatus::BadDiscoveryUniverse);
  auto odd = test::sacnDiscovery({1, 2});
  odd.push_back(0);  // half a universe: every layer length nested, but not a whole list
  test::put16(odd, 16, 0x7000 | static_cast<unsigned>(odd.size() - 16));
  test::put16(odd, 38, 0x7000 | static_cast<unsigned>(odd.size() - 38));
  test::put16(odd, 112, 0x7000 | static_cast<unsigned>(odd.size() - 112));
  EXPECT_EQ(parseSacnExtended(odd).status, SacnStatus::BadDiscoveryLength);
  auto vector = test::sacnDiscovery({1});
  vector[117] = 0x02;
  EXPECT_EQ(parseSacnExtended(vector).status, SacnStatus::BadDiscoveryVector);
}

TEST(Sacn, SourceNameWithoutTerminatorIsCut) {
  auto b = test::sacn({});
  for (size_t i = 44; i < 108; ++i) b[i] = 'A';
  const SacnParse p = parseSacn(b);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.packet.sourceName.size(), 64u);
}

TEST(Sacn, MulticastGroupIs239_255_HiLo) {
  EXPECT_EQ(sacnMulticastGroup(1), 0xEFFF0001u);
  EXPECT_EQ(sacnMulticastGroup(258), 0xEFFF0102u);  // 239.255.1.2
  EXPECT_EQ(sacnMulticastGroup(63999), 0xEFFFF9FFu);
}

}  // namespace
}  // namespace haze
