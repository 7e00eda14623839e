// Universe synchronisation through DmxInput with an injected clock: sACN synchronization
// (E1.31 6.2.4, 6.3: hold until the sync packet, 2.5 s fallback, Force_Synchronization) and
// Art-Net ArtSync (hold until the next ArtSync, 4 s fallback). The tearing check: a poll never
// shows one universe's new frame beside the other's old one.
#include <gtest/gtest.h>

#include <cmath>

#include "unit/dmx/packets.h"
#include "unit/dmx/test_show.h"
#include "shows/dmx/dmx_input.h"

namespace haze {
namespace {

constexpr uint32_t kLocalhost = 0x7F000001;

std::vector<uint8_t> sacnLevel(uint16_t universe, uint8_t level, uint8_t sequence, uint16_t syncAddress,
                               uint8_t options = 0) {
  test::SacnFields f;
  f.universe = universe;
  f.sequence = sequence;
  f.syncAddress = syncAddress;
  f.options = options;
  f.slots[0] = level;  // 101's dimmer on universe 1, 201's red on universe 2
  return test::sacn(f);
}

// 101 (universe 1) intensity and 201 (universe 2, RGB par) red, as DMX bytes.
std::pair<int, int> look(DmxInput& input, double t) {
  const StageState& s = input.poll(t);
  return {static_cast<int>(std::lround(s.at(101).intensity * 255)),
          static_cast<int>(std::lround(s.at(201).intensity * s.at(201).color.r * 255))};
}

TEST(Sync, SacnUniversesChangeTogetherOnTheSyncPacket) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  // Before any sync packet, synchronised data is applied as it arrives (E1.31 11.2).
  input.receive(DmxProtocol::Sacn, sacnLevel(1, 10, 1, 7000), kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::Sacn, sacnLevel(2, 10, 1, 7000), kLocalhost, 1, 0.0);
  EXPECT_EQ(look(input, 0.0), std::make_pair(10, 10));
  input.receive(DmxProtocol::Sacn, test::sacnSync(7000, 1), kLocalhost, 1, 0.02);
  // A sweep of frames, each universe sent separately, polled after every datagram: the two
  // universes must always show the same frame.
  uint8_t seq = 2;
  for (int frame = 1; frame <= 50; ++frame, ++seq) {
    const double at = 0.02 + 0.04 * frame;
    const uint8_t level = static_cast<uint8_t>(10 + 4 * frame);
    input.receive(DmxProtocol::Sacn, sacnLevel(1, level, seq, 7000), kLocalhost, 1, at);
    const auto a = look(input, at);
    EXPECT_EQ(a.first, a.second) << "frame " << frame << " after universe 1";
    input.receive(DmxProtocol::Sacn, sacnLevel(2, level, seq, 7000), kLocalhost, 1, at + 0.001);
    const auto b = look(input, at + 0.001);
    EXPECT_EQ(b.first, b.second) << "frame " << frame << " after universe 2";
    EXPECT_EQ(b.first, level - 4) << "the previous frame until the sync packet";
    input.receive(DmxProtocol::Sacn, test::sacnSync(7000, seq), kLocalhost, 1, at + 0.002);
    EXPECT_EQ(look(input, at + 0.002), std::make_pair(int{level}, int{level}));
  }
  EXPECT_EQ(input.stats().syncPackets, 51u);
  EXPECT_EQ(input.stats().held, 100u);
  // A sync packet for another address releases nothing.
  input.receive(DmxProtocol::Sacn, sacnLevel(1, 250, seq, 7000), kLocalhost, 1, 2.1);
  input.receive(DmxProtocol::Sacn, test::sacnSync(7001), kLocalhost, 1, 2.1);
  EXPECT_EQ(look(input, 2.1).first, 210);
}

TEST(Sync, SacnFallsBackToImmediateAfterTheTimeoutUnlessForced) {
  for (bool force : {false, true}) {
    const test::TestShow t = test::makeTestShow();
    DmxInput input(t.show, t.profiles);
    const uint8_t opt = force ? kSacnOptionForceSync : 0;
    input.receive(DmxProtocol::Sacn, test::sacnSync(9), kLocalhost, 1, 0.0);
    input.receive(DmxProtocol::Sacn, sacnLevel(1, 100, 1, 9, opt), kLocalhost, 1, 1.0);
    EXPECT_EQ(look(input, 1.0).first, 0) << "held";
    // 2.5 s after the last sync packet the held frame is applied, and later ones at once; with
    // Force_Synchronization nothing changes until synchronisation resumes.
    EXPECT_EQ(look(input, 2.6).first, force ? 0 : 100);
    input.receive(DmxProtocol::Sacn, sacnLevel(1, 120, 2, 9, opt), kLocalhost, 1, 2.7);
    EXPECT_EQ(look(input, 2.7).first, force ? 0 : 120);
    input.receive(DmxProtocol::Sacn, test::sacnSync(9), kLocalhost, 1, 2.8);
    EXPECT_EQ(look(input, 2.8).first, 120);
    EXPECT_EQ(input.stats().superseded, force ? 1u : 0u);
  }
}

// Stream_Terminated is not held, and takes the source's held frames with it: a later sync
// packet must not bring the source back.
TEST(Sync, StreamTerminatedIsNotHeldAndDropsWhatWasHeld) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  input.receive(DmxProtocol::Sacn, sacnLevel(1, 100, 1, 0), kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::Sacn, test::sacnSync(9), kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::Sacn, sacnLevel(1, 50, 2, 9), kLocalhost, 1, 0.05);  // held
  input.receive(DmxProtocol::Sacn, sacnLevel(1, 0, 3, 9, kSacnOptionTerminated), kLocalhost, 1, 0.1);
  EXPECT_TRUE(input.sources().empty());
  EXPECT_EQ(input.stats().superseded, 1u);
  input.receive(DmxProtocol::Sacn, test::sacnSync(9), kLocalhost, 1, 0.2);
  EXPECT_TRUE(input.sources().empty());
  EXPECT_EQ(input.syncGate().heldCount(), 0u);
}

TEST(Sync, ArtSyncHoldsArtDmxUntilTheNextAndLapsesAfter4s) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  auto dmx = [](uint8_t subUni, uint8_t level) {
    test::ArtDmxFields f;
    f.subUni = subUni;  // Port-Address 0 = universe 1, 1 = universe 2
    f.data[0] = level;
    return test::artDmx(f);
  };
  input.receive(DmxProtocol::ArtNet, dmx(0, 10), kLocalhost, 6454, 0.0);
  EXPECT_EQ(look(input, 0.0).first, 10) << "no ArtSync yet: immediate";
  input.receive(DmxProtocol::ArtNet, test::artSync(), kLocalhost, 6454, 0.1);
  input.receive(DmxProtocol::ArtNet, dmx(0, 50), kLocalhost, 6454, 0.2);
  input.receive(DmxProtocol::ArtNet, dmx(1, 50), kLocalhost, 6454, 0.2);
  EXPECT_EQ(look(input, 0.2), std::make_pair(10, 0));
  input.receive(DmxProtocol::ArtNet, test::artSync(), kLocalhost, 6454, 0.3);
  EXPECT_EQ(look(input, 0.3), std::make_pair(50, 50));
  input.receive(DmxProtocol::ArtNet, dmx(0, 70), kLocalhost, 6454, 1.0);
  EXPECT_EQ(look(input, 4.29).first, 50);
  EXPECT_EQ(look(input, 4.31).first, 70) << "4 s without ArtSync: the held frame goes out";
  input.receive(DmxProtocol::ArtNet, dmx(0, 90), kLocalhost, 6454, 4.4);
  EXPECT_EQ(look(input, 4.4).first, 90);
  EXPECT_EQ(input.stats().syncPackets, 2u);
}

// Art-Net 4: ArtSync belongs to the controller that sends the ArtDmx. An ArtSync from another
// IP address neither starts holding nor releases the held frames; each controller's ArtSync
// releases only its own.
TEST(Sync, ArtSyncFromAnotherAddressIsIgnored) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  constexpr uint32_t kConsole = 0x0A000001, kOther = 0x0A000002;
  auto dmx = [](uint8_t subUni, uint8_t level) {
    test::ArtDmxFields f;
    f.subUni = subUni;
    f.data[0] = level;
    return test::artDmx(f);
  };
  input.receive(DmxProtocol::ArtNet, dmx(0, 10), kConsole, 6454, 0.0);
  input.receive(DmxProtocol::ArtNet, test::artSync(), kOther, 6454, 0.05);
  input.receive(DmxProtocol::ArtNet, dmx(0, 20), kConsole, 6454, 0.1);
  EXPECT_EQ(look(input, 0.1).first, 20) << "another address's ArtSync must not make the console's ArtDmx wait";
  EXPECT_EQ(input.stats().foreignArtSyncs, 1u);

  input.receive(DmxProtocol::ArtNet, test::artSync(), kConsole, 6454, 0.2);
  input.receive(DmxProtocol::ArtNet, dmx(0, 50), kConsole, 6454, 0.3);
  input.receive(DmxProtocol::ArtNet, dmx(1, 50), kConsole, 6454, 0.3);
  EXPECT_EQ(look(input, 0.3), std::make_pair(20, 0)) << "held for the console's next ArtSync";
  input.receive(DmxProtocol::ArtNet, test::artSync(), kOther, 6454, 0.35);
  EXPECT_EQ(look(input, 0.35), std::make_pair(20, 0)) << "another address's ArtSync released the console's frames";
  input.receive(DmxProtocol::ArtNet, test::artSync(), kConsole, 6454, 0.4);
  EXPECT_EQ(look(input, 0.4), std::make_pair(50, 50));

  // A second controller on universe 2 with a sync of its own: each ArtSync releases its sender's.
  input.receive(DmxProtocol::ArtNet, dmx(1, 60), kOther, 6454, 0.5);  // not synced yet: at once
  EXPECT_EQ(look(input, 0.5).second, 60);
  input.receive(DmxProtocol::ArtNet, test::artSync(), kOther, 6454, 0.55);
  input.receive(DmxProtocol::ArtNet, dmx(0, 80), kConsole, 6454, 0.6);
  input.receive(DmxProtocol::ArtNet, dmx(1, 90), kOther, 6454, 0.6);
  EXPECT_EQ(look(input, 0.6), std::make_pair(50, 60));
  input.receive(DmxProtocol::ArtNet, test::artSync(), kOther, 6454, 0.65);
  EXPECT_EQ(look(input, 0.65), std::make_pair(50, 90)) << "the other controller's ArtSync releases its frame only";
  input.receive(DmxProtocol::ArtNet, test::artSync(), kConsole, 6454, 0.7);
  EXPECT_EQ(look(input, 0.7), std::make_pair(80, 90));
  EXPECT_EQ(input.stats().foreignArtSyncs, 2u);
  EXPECT_EQ(input.stats().syncPackets, 7u);
}

// Sync holding is bounded: frames beyond the holder's limit are counted, not kept.
TEST(Sync, HolderIsBounded) {
  const test::TestShow t = test::makeTestShow();
  DmxInputOptions o;
  o.sync.maxHeld = 3;
  DmxInput input(t.show, t.profiles, o);
  input.receive(DmxProtocol::Sacn, test::sacnSync(9), kLocalhost, 1, 0.0);
  for (uint8_t c = 1; c <= 10; ++c) {
    test::SacnFields f;
    f.cidFill = c;
    f.syncAddress = 9;
    input.receive(DmxProtocol::Sacn, test::sacn(f), kLocalhost, 1, 0.1);
  }
  EXPECT_EQ(input.stats().held, 3u);
  EXPECT_EQ(input.stats().exceeded, 7u);
  EXPECT_EQ(input.syncGate().heldCount(), 3u);
}

TEST(Discovery, SourcesAndTheirUniversesAreListed) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  input.receive(DmxProtocol::Sacn, test::sacnDiscovery({1, 2, 3}, 0, 1, "desk", 0x21), kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::Sacn, test::sacnDiscovery({600}, 1, 1, "desk", 0x21), kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::Sacn, test::sacnDiscovery({5}, 0, 0, "backup", 0x22), kLocalhost, 1, 0.0);
  auto bad = test::sacnDiscovery({5}, 2, 0);
  input.receive(DmxProtocol::Sacn, bad, kLocalhost, 1, 0.0);
  std::vector<DiscoveredSource> d = input.discovered();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].name, "desk");
  EXPECT_EQ(d[0].universes, (std::set<int>{1, 2, 3, 600}));
  EXPECT_EQ(d[0].pages, 2);
  EXPECT_EQ(d[0].lastPage, 1);
  EXPECT_EQ(d[1].name, "backup");
  EXPECT_EQ(input.stats().discoveryPackets, 3u);
  EXPECT_EQ(input.stats().malformed.at("sacn.bad_discovery_page"), 1u);
  EXPECT_EQ(input.stats().good, 0u) << "discovery carries no levels";
  input.poll(31.0);
  EXPECT_TRUE(input.discovered().empty()) << "forgotten 30 s after the last page";
}

}  // namespace
}  // namespace haze
