// DmxInput end to end without sockets: datagrams -> counters, merge and each fixture's decoded
// attributes at its patch address; Art-Net Port-Address 0 is haze universe 1.
#include <gtest/gtest.h>

#include "unit/dmx/packets.h"
#include "unit/dmx/test_show.h"
#include "shows/dmx/dmx_input.h"

namespace haze {
namespace {

constexpr uint32_t kLocalhost = 0x7F000001;

TEST(DmxInput, SacnLevelsReachFixturesAtTheirAddresses) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  test::SacnFields f;
  f.universe = 1;
  f.slots[0] = 255;                      // 101 dimmer
  f.slots[1] = 0xFF; f.slots[2] = 0xFF;  // 101 pan +270
  f.slots[11] = 102;                     // 102 dimmer at address 12: 0.4
  f.slots[11 + 8] = 15;                  // 102 gobo: Dots
  input.receive(DmxProtocol::Sacn, test::sacn(f), kLocalhost, 50000, 0.0);
  const StageState& s = input.poll(0.0);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_FLOAT_EQ(s.at(101).intensity, 1.0f);
  EXPECT_FLOAT_EQ(s.at(101).panDeg, 270.0f);
  EXPECT_FLOAT_EQ(s.at(102).intensity, 0.4f);
  EXPECT_EQ(s.at(102).gobo, "Dots");
  EXPECT_FLOAT_EQ(s.at(102).panDeg, -270.0f);
  // No data on universe 2 yet, and 301 has no patch: defaults.
  EXPECT_EQ(s.at(201), Attributes{});
  EXPECT_EQ(s.at(301), Attributes{});
  EXPECT_EQ(input.stats().good, 1u);
  ASSERT_EQ(input.sources().size(), 1u);
  EXPECT_EQ(input.sources()[0].name, "test console");
}

// On loss, hold keeps the look; blackout puts the light out and keeps the heads where they were
// (what a moving light set to blackout on DMX loss does), never the positions zeros decode to.
TEST(DmxInput, LossHoldsOrBlacksOutWithoutMovingHeads) {
  for (LossPolicy policy : {LossPolicy::HoldLastLook, LossPolicy::Blackout}) {
    const test::TestShow t = test::makeTestShow();
    DmxInputOptions o;
    o.merge.onLoss = policy;
    DmxInput input(t.show, t.profiles, o);
    test::SacnFields f;
    f.universe = 1;
    f.slots[0] = 255;                      // 101 dimmer
    f.slots[1] = 0xC0; f.slots[2] = 0x00;  // 101 pan, well off both ends
    input.receive(DmxProtocol::Sacn, test::sacn(f), kLocalhost, 50000, 0.0);
    const Attributes live = input.poll(0.0).at(101);
    ASSERT_FLOAT_EQ(live.intensity, 1.0f);
    const Attributes after = input.poll(10.0).at(101);  // sACN sources expire after 2.5 s
    EXPECT_FLOAT_EQ(after.panDeg, live.panDeg) << "the head holds its position either way";
    EXPECT_FLOAT_EQ(after.tiltDeg, live.tiltDeg);
    EXPECT_FLOAT_EQ(after.intensity, policy == LossPolicy::HoldLastLook ? 1.0f : 0.0f);
  }
}

TEST(DmxInput, ArtNetPortAddressZeroIsUniverseOne) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  test::ArtDmxFields a;
  a.data.assign(512, 0);
  a.data[0] = 204;  // 101 dimmer 0.8
  input.receive(DmxProtocol::ArtNet, test::artDmx(a), kLocalhost, 6454, 0.0);
  // Port-Address 1 (Sub-Net 0, Universe 1) is haze universe 2: the RGB par 201 at address 1.
  test::ArtDmxFields b;
  b.subUni = 1;
  b.data.assign(512, 0);
  b.data[0] = 255;
  b.data[1] = 0;
  b.data[2] = 255;
  b.data[509] = 255;  // 202 dimmer at 510
  b.data[510] = 255;  // 202 red; green at 512 stays 0, blue and white fall off the universe
  input.receive(DmxProtocol::ArtNet, test::artDmx(b), kLocalhost, 6454, 0.0);
  const StageState& s = input.poll(0.0);
  EXPECT_FLOAT_EQ(s.at(101).intensity, 0.8f);
  EXPECT_FLOAT_EQ(s.at(201).intensity, 1.0f);
  EXPECT_EQ(s.at(201).color, glm::vec3(1.0f, 0.0f, 1.0f));
  EXPECT_FLOAT_EQ(s.at(202).intensity, 1.0f);
  EXPECT_EQ(s.at(202).color, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(input.stats().good, 2u);
}

TEST(DmxInput, ArtNetAndSacnMergeOnOneUniverse) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  test::ArtDmxFields a;
  a.data.assign(2, 0);
  a.data[0] = 100;
  input.receive(DmxProtocol::ArtNet, test::artDmx(a), kLocalhost, 6454, 0.0);
  test::SacnFields f;  // priority 100: equal, so HTP
  f.slots[0] = 50;
  f.slots[1] = 0x80;
  input.receive(DmxProtocol::Sacn, test::sacn(f), kLocalhost, 5568, 0.0);
  const StageState& s = input.poll(0.0);
  EXPECT_FLOAT_EQ(s.at(101).intensity, 100.0f / 255.0f);
  EXPECT_EQ(input.sources().size(), 2u);
  // The sACN source goes quiet: after 2.5 s only Art-Net (10 s timeout) remains.
  input.poll(3.0);
  ASSERT_EQ(input.sources().size(), 1u);
  EXPECT_EQ(input.sources()[0].id.protocol, DmxProtocol::ArtNet);
}

TEST(DmxInput, CountsEveryKindOfDrop) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  auto bad = test::sacn({});
  bad[108] = 250;  // priority
  input.receive(DmxProtocol::Sacn, bad, kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::Sacn, bad, kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::ArtNet, std::vector<uint8_t>{1, 2, 3}, kLocalhost, 1, 0.0);
  test::SacnFields other;
  other.universe = 3;  // nobody is patched there
  input.receive(DmxProtocol::Sacn, test::sacn(other), kLocalhost, 1, 0.0);
  test::SacnFields alt;
  alt.startCode = 0x17;  // text: valid, not for haze
  input.receive(DmxProtocol::Sacn, test::sacn(alt), kLocalhost, 1, 0.0);
  test::SacnFields seq;
  seq.sequence = 10;
  input.receive(DmxProtocol::Sacn, test::sacn(seq), kLocalhost, 1, 0.0);
  input.receive(DmxProtocol::Sacn, test::sacn(seq), kLocalhost, 1, 0.0);  // duplicate
  seq.options = kSacnOptionTerminated;
  seq.sequence = 11;
  input.receive(DmxProtocol::Sacn, test::sacn(seq), kLocalhost, 1, 0.0);
  const DmxInputStats& s = input.stats();
  EXPECT_EQ(s.received, 8u);
  EXPECT_EQ(s.malformed.at("sacn.bad_priority"), 2u);
  EXPECT_EQ(s.malformed.at("artnet.too_short"), 1u);
  EXPECT_EQ(s.malformedTotal(), 3u);
  EXPECT_EQ(s.unwatched, 1u);
  EXPECT_EQ(s.ignored, 1u);
  EXPECT_EQ(s.good, 1u);
  EXPECT_EQ(s.late, 1u);
  EXPECT_EQ(s.terminated, 1u);
  EXPECT_TRUE(input.sources().empty());
  // The first malformed packets are kept in full: sender, byte and what was expected.
  ASSERT_EQ(s.firstMalformed.size(), 3u);
  EXPECT_EQ(s.firstMalformed[0].str(), "sACN from 127.0.0.1:1:byte 108: priority is above 200; expected 0..200");
  EXPECT_EQ(s.firstMalformed[2].place, "byte 3");
}

TEST(DmxInput, PreviewDataCanBeRefused) {
  const test::TestShow t = test::makeTestShow();
  test::SacnFields f;
  f.options = kSacnOptionPreview;
  f.slots[0] = 255;
  {
    DmxInput input(t.show, t.profiles);
    input.receive(DmxProtocol::Sacn, test::sacn(f), kLocalhost, 1, 0.0);
    EXPECT_FLOAT_EQ(input.poll(0.0).at(101).intensity, 1.0f);
  }
  {
    DmxInputOptions o;
    o.acceptPreview = false;
    DmxInput input(t.show, t.profiles, o);
    input.receive(DmxProtocol::Sacn, test::sacn(f), kLocalhost, 1, 0.0);
    EXPECT_FLOAT_EQ(input.poll(0.0).at(101).intensity, 0.0f);
    EXPECT_EQ(input.stats().ignored, 1u);
  }
}

TEST(DmxInput, PacketRateOverTheLastSecond) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  test::SacnFields f;
  // 40 packets over 2 s (every 50 ms): 20 per second.
  for (int i = 0; i < 40; ++i) {
    f.sequence = static_cast<uint8_t>(i);
    input.receive(DmxProtocol::Sacn, test::sacn(f), kLocalhost, 1, 100.0 + 0.05 * i);
  }
  EXPECT_NEAR(input.packetRate(100.0 + 0.05 * 39), 20.0, 1.0);
  EXPECT_EQ(input.packetRate(103.5), 0.0);
}

}  // namespace
}  // namespace haze
