// Hostile input: tens of thousands of random and mutated datagrams through both parsers and the
// whole DmxInput (merge + decode). Run under ASan/UBSan this is the "never crash, never read
// past the datagram" test; the asserts check that the counters account for every datagram and
// that a mutated packet is only accepted when its checked fields survived the mutation.
#include <gtest/gtest.h>

#include <random>

#include "unit/dmx/packets.h"
#include "unit/dmx/test_show.h"
#include "shows/dmx/artnet.h"
#include "shows/dmx/dmx_input.h"
#include "shows/dmx/sacn.h"

namespace haze {
namespace {

std::vector<uint8_t> randomBytes(std::mt19937& rng, size_t maxSize) {
  std::uniform_int_distribution<size_t> size(0, maxSize);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<uint8_t> b(size(rng));
  for (auto& x : b) x = static_cast<uint8_t>(byte(rng));
  return b;
}

// Flips, overwrites, truncates or extends a valid packet.
std::vector<uint8_t> mutate(std::vector<uint8_t> b, std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 3), byte(0, 255), count(1, 4);
  const int n = count(rng);
  for (int i = 0; i < n && !b.empty(); ++i) {
    std::uniform_int_distribution<size_t> at(0, b.size() - 1);
    switch (kind(rng)) {
      case 0: b[at(rng)] ^= static_cast<uint8_t>(1u << (byte(rng) % 8)); break;
      case 1: b[at(rng)] = static_cast<uint8_t>(byte(rng)); break;
      case 2: b.resize(at(rng)); break;
      case 3: b.resize(b.size() + static_cast<size_t>(byte(rng)), static_cast<uint8_t>(byte(rng))); break;
    }
  }
  return b;
}

TEST(Fuzz, RandomDatagramsNeverParse) {
  std::mt19937 rng(1234);
  for (int i = 0; i < 20000; ++i) {
    const auto b = randomBytes(rng, 700);
    // Random bytes essentially never hold "Art-Net\0" or the ACN id; the point is no crash.
    EXPECT_FALSE(parseArtDmx(b).ok());
    EXPECT_FALSE(parseSacn(b).ok());
  }
}

TEST(Fuzz, MutatedSacnPacketsAreAcceptedOnlyWhenStillConsistent) {
  std::mt19937 rng(99);
  int accepted = 0, rejected = 0;
  test::SacnFields f;
  for (size_t i = 0; i < f.slots.size(); ++i) f.slots[i] = static_cast<uint8_t>(i);
  const auto good = test::sacn(f);
  for (int i = 0; i < 30000; ++i) {
    const auto b = mutate(good, rng);
    const SacnParse p = parseSacn(b);
    if (p.ok()) {
      ++accepted;
      // Whatever survived must satisfy the invariants the parser promises.
      EXPECT_LE(p.packet.slotCount, 512);
      EXPECT_EQ(static_cast<size_t>(p.packet.slotCount) + 126, b.size());
      EXPECT_LE(p.packet.priority, 200);
      EXPECT_GE(p.packet.universe, 1);
      EXPECT_LE(p.packet.universe, 63999);
      EXPECT_TRUE(p.packet.startCode == 0 || p.packet.startCode == 0xDD);
      if (p.packet.startCode == 0xDD) {
        for (int k = 0; k < p.packet.slotCount; ++k) {
          EXPECT_LE(p.packet.slots[static_cast<size_t>(k)], 200);
        }
      }
    } else {
      ++rejected;
      EXPECT_GE(p.byte, 0);
      EXPECT_LE(static_cast<size_t>(p.byte), b.size());
    }
  }
  // Mutations of slot bytes leave a valid packet, header mutations do not: both must occur.
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(rejected, 1000);
}

TEST(Fuzz, MutatedArtDmxPacketsAreAcceptedOnlyWhenStillConsistent) {
  std::mt19937 rng(7);
  int accepted = 0, rejected = 0;
  const auto good = test::artDmx({});
  for (int i = 0; i < 30000; ++i) {
    const auto b = mutate(good, rng);
    const ArtDmxParse p = parseArtDmx(b);
    if (p.ok()) {
      ++accepted;
      EXPECT_GE(p.packet.length, 2);
      EXPECT_LE(p.packet.length, 512);
      EXPECT_EQ(p.packet.length % 2, 0);
      EXPECT_LE(static_cast<size_t>(p.packet.length) + 18, b.size());
      EXPECT_LE(p.packet.portAddress, 32767);
    } else {
      ++rejected;
    }
  }
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(rejected, 1000);
}

TEST(Fuzz, DmxInputCountsEveryDatagramAndStaysBounded) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> pick(0, 6);
  std::uniform_int_distribution<uint32_t> ip(0, 0xFFFFFFFF);
  test::SacnFields f;
  const auto sacnGood = test::sacn(f);
  const auto artGood = test::artDmx({});
  f.syncAddress = 9;
  const auto sacnSynced = test::sacn(f);
  const auto sync = test::sacnSync(9);
  const auto discovery = test::sacnDiscovery({1, 2, 3});
  double now = 0.0;
  const int total = 40000;
  for (int i = 0; i < total; ++i) {
    now += 0.001;
    std::vector<uint8_t> b;
    DmxProtocol protocol = DmxProtocol::Sacn;
    switch (pick(rng)) {
      case 0: b = randomBytes(rng, 700); break;
      case 1: b = mutate(sacnGood, rng); break;
      case 2: b = mutate(artGood, rng); protocol = DmxProtocol::ArtNet; break;
      case 3: b = randomBytes(rng, 700); protocol = DmxProtocol::ArtNet; break;
      case 4: b = mutate(sacnSynced, rng); break;
      case 5: b = mutate(i % 2 ? sync : discovery, rng); break;
      case 6: b = i % 3 ? test::artSync() : mutate(artGood, rng); protocol = DmxProtocol::ArtNet; break;
    }
    // Random senders: Art-Net sources are keyed by address, so this also floods the merger.
    input.receive(protocol, b, ip(rng), 6454, now);
    if (i % 100 == 0) input.poll(now);
  }
  const DmxInputStats& s = input.stats();
  EXPECT_EQ(s.received, static_cast<uint64_t>(total));
  // Every datagram ends in exactly one count (or is still held for its sync packet).
  EXPECT_EQ(s.good + s.ignored + s.late + s.terminated + s.unwatched + s.exceeded + s.malformedTotal() +
                s.syncPackets + s.discoveryPackets + s.superseded + input.syncGate().heldCount(),
            s.received);
  EXPECT_GT(s.syncPackets, 1000u);
  EXPECT_GT(s.held, 100u);
  EXPECT_LE(input.discovered().size(), kMaxDiscoveredSources);
  EXPECT_GT(s.malformedTotal(), 10000u);
  // The merger never holds more sources than its per-universe limit allows.
  EXPECT_LE(input.sources().size(), static_cast<size_t>(8 * 2));
  const StageState& state = input.poll(now);
  EXPECT_EQ(state.size(), t.show.fixtures.size());
  for (const auto& [id, a] : state) {
    EXPECT_GE(a.intensity, 0.0f);
    EXPECT_LE(a.intensity, 1.0f);
    EXPECT_GE(a.color.r, 0.0f);
    EXPECT_LE(a.color.r, 1.0f);
  }
}

}  // namespace
}  // namespace haze
