// Stub GDTFs, as Capture embeds them in an MVR: every slot of the mode a channel named Dimmer1..n
// and nothing else. Each is a dimmer of the fixture and the highest sets its intensity
// (docs/live.md, "What the console drives"), so the stub answers a console's dimmers.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fixtures/dmx_decode.h"
#include "fixtures/gdtf.h"
#include "unit/gdtf/zip_builder.h"

namespace haze {
namespace {

std::string stub(int slots) {
  std::string channels;
  for (int k = 1; k <= slots; ++k) {
    const std::string n = std::to_string(k);
    channels += R"(<DMXChannel DMXBreak="1" Geometry="Base" Offset=")" + n + R"("><LogicalChannel Attribute="Dimmer)" + n +
                R"("><ChannelFunction Attribute="Dimmer)" + n + R"(" DMXFrom="0/1" Name=""/></LogicalChannel></DMXChannel>)";
  }
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<GDTF DataVersion="1.1">
  <FixtureType Name="Stub Spot" Manufacturer="Haze Tests">
    <Geometries>
      <Geometry Name="Base" Position="{1,0,0,0}{0,1,0,0}{0,0,1,0}{0,0,0,1}">
        <Beam Name="Beam" Position="{1,0,0,0}{0,1,0,0}{0,0,1,-0.1}{0,0,0,1}" BeamAngle="20" FieldAngle="30" LuminousFlux="5000"/>
      </Geometry>
    </Geometries>
    <DMXModes>
      <DMXMode Name="Standard" Geometry="Base"><DMXChannels>)" +
         channels + R"(</DMXChannels></DMXMode>
    </DMXModes>
  </FixtureType>
</GDTF>
)";
}

TEST(GdtfStubDimmers, EveryNumberedDimmerIsADimmerAndTheHighestDrives) {
  test::TempDir dir("stub");
  ASSERT_TRUE(test::writeZip(dir / "stub.gdtf", {{"description.xml", stub(3)}}));
  auto g = loadGdtf(dir / "stub.gdtf");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  ASSERT_EQ(p.modes.size(), 1u);
  const DmxMode& m = p.modes[0];
  ASSERT_EQ(m.channels.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(m.channels[static_cast<size_t>(k)].attribute, DmxAttribute::Intensity) << k;
    EXPECT_EQ(m.channels[static_cast<size_t>(k)].wheel, k) << k;
  }
  for (const std::string& w : g->warnings) EXPECT_EQ(w.find("Dimmer"), std::string::npos) << w;
  const auto level = [&](std::vector<uint8_t> dmx) { return decodeDmx(p, m, dmx).intensity; };
  EXPECT_FLOAT_EQ(level({0, 0, 0}), 0.0f);
  EXPECT_FLOAT_EQ(level({255, 255, 255}), 1.0f);
  EXPECT_FLOAT_EQ(level({0, 255, 0}), 1.0f);
  EXPECT_FLOAT_EQ(level({51, 0, 102}), 102.0f / 255.0f);
}

// A plain "Dimmer" is still the one dimmer, and a mode without any dimmer is at full.
TEST(GdtfStubDimmers, NoDimmerChannelIsFull) {
  test::TempDir dir("none");
  std::string xml = stub(1);
  for (const char* from : {"Attribute=\"Dimmer1\"", "Attribute=\"Dimmer1\""})
    xml.replace(xml.find(from), std::string(from).size(), "Attribute=\"Zoom\"");
  ASSERT_TRUE(test::writeZip(dir / "zoom.gdtf", {{"description.xml", xml}}));
  auto g = loadGdtf(dir / "zoom.gdtf");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const DmxMode& m = g->profile->modes[0];
  EXPECT_EQ(m.channels[0].attribute, DmxAttribute::Zoom);
  EXPECT_FLOAT_EQ(decodeDmx(*g->profile, m, std::vector<uint8_t>{0}).intensity, 1.0f);
}

}  // namespace
}  // namespace haze
