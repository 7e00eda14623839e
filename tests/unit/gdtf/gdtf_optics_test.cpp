// GDTF optics beyond the gobo: the bundled BMFL Spot and Alpha Spot import with their prisms,
// frost and shutter (numbers read from their description.xml by hand), their DMX values decode
// into shutter modes and rates, and a synthetic fixture with framing blades and an oversized
// prism imports with the blades and a clamped prism.
#include <gtest/gtest.h>

#include <algorithm>

#include "fixtures/dmx_decode.h"
#include "fixtures/gdtf.h"
#include "unit/gdtf/zip_builder.h"

namespace haze {
namespace {

const std::filesystem::path kGdtfDir = std::filesystem::path(HAZE_SHARED_DATA) / "gdtf";

const DmxChannel* channelOf(const DmxMode& m, DmxAttribute a) {
  for (const DmxChannel& c : m.channels)
    if (c.attribute == a && c.byte == 0) return &c;
  return nullptr;
}

Attributes decodeOne(const Profile& p, const DmxMode& m, DmxAttribute a, uint8_t value) {
  std::vector<uint8_t> dmx(m.channels.size(), 0);
  for (size_t i = 0; i < m.channels.size(); ++i)
    if (m.channels[i].attribute == a && m.channels[i].byte == 0) dmx[i] = value;
  return decodeDmx(p, m, dmx);
}

TEST(GdtfOptics, BmflHasTwoSixFacetPrismsFrostAndAFullShutter) {
  auto g = loadGdtf(kGdtfDir / "Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  // Wheel Prism1: Open, "P01 (6F Linear)" with six facets on the x axis, "P02 (8F Circular)" with
  // six facets at 60-degree steps (the file lists six whatever the name says).
  ASSERT_EQ(p.prisms.size(), 2u);
  EXPECT_EQ(p.prisms[0].name, "P01 (6F Linear)");
  EXPECT_EQ(p.prisms[0].facets, 6);
  EXPECT_TRUE(p.prisms[0].linear);
  EXPECT_EQ(p.prisms[1].name, "P02 (8F Circular)");
  EXPECT_EQ(p.prisms[1].facets, 6);
  EXPECT_FALSE(p.prisms[1].linear);
  EXPECT_FLOAT_EQ(p.prisms[1].deflectionDeg, kDefaultPrismDeflectionDeg);
  EXPECT_TRUE(p.hasFrost);
  EXPECT_FALSE(p.hasBlades);
  const DmxMode& m = p.modes.at(0);
  // Prism1 at offset 29: 0-19 the open hole, 20-49 slot 2 (linear, indexing), 76-105 slot 3.
  const DmxChannel* prism = channelOf(m, DmxAttribute::Prism);
  ASSERT_TRUE(prism);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Prism, 10).prism, "Open");
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Prism, 30).prism, "P01 (6F Linear)");
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Prism, 80).prism, "P02 (8F Circular)");
  // Prism1Pos: -180..180 degrees over 0..255.
  EXPECT_NEAR(decodeOne(p, m, DmxAttribute::PrismRotation, 255).prismRotationDeg, 180.0f, 1e-3f);
  // Shutter1 at offset 39: 0-31 closed, 32-63 open, 64-95 strobe 0.1 -> 10 Hz, 128-143 pulse
  // opening, 144-159 pulse closing 10 -> 0.1 Hz, 192-223 random 0.1 -> 10 Hz, 224-255 open.
  const DmxChannel* shutter = channelOf(m, DmxAttribute::Shutter);
  ASSERT_TRUE(shutter);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 0).shutter.mode, ShutterMode::Closed);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 40).shutter.mode, ShutterMode::Open);
  const Shutter fast = decodeOne(p, m, DmxAttribute::Shutter, 95).shutter;
  EXPECT_EQ(fast.mode, ShutterMode::Strobe);
  EXPECT_NEAR(fast.rateHz, 10.0f, 1e-4f);
  EXPECT_NEAR(decodeOne(p, m, DmxAttribute::Shutter, 64).shutter.rateHz, 0.1f, 1e-4f);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 130).shutter.mode, ShutterMode::PulseOpen);
  const Shutter close = decodeOne(p, m, DmxAttribute::Shutter, 144).shutter;
  EXPECT_EQ(close.mode, ShutterMode::PulseClose);
  EXPECT_NEAR(close.rateHz, 10.0f, 1e-4f);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 200).shutter.mode, ShutterMode::Random);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 240).shutter.mode, ShutterMode::Open);
  // Frost1 from DMX 1: full light frost at 83 and beyond.
  EXPECT_FLOAT_EQ(decodeOne(p, m, DmxAttribute::Frost, 0).frost, 0.0f);
  EXPECT_GT(decodeOne(p, m, DmxAttribute::Frost, 40).frost, 0.3f);
}

TEST(GdtfOptics, AlphaSpotNamesItsThreeFacetPrismAndPulses) {
  auto g = loadGdtf(kGdtfDir / "Clay Paky@Alpha Spot QWO 800@allWorking.gdtf");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  // Prism1 without a wheel: ChannelSets "Open" (0) and "3 facet prism" (128).
  ASSERT_EQ(p.prisms.size(), 1u);
  EXPECT_EQ(p.prisms[0].name, "3 facet prism");
  EXPECT_EQ(p.prisms[0].facets, 3);
  EXPECT_TRUE(p.hasFrost);
  const DmxMode& m = p.modes.at(0);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Prism, 0).prism, "Open");
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Prism, 200).prism, "3 facet prism");
  // Shutter1: 0-3 closed, 4-103 strobe 1 -> 12 Hz, 104-107 open, 108-207 pulse 0.1 -> 10 Hz,
  // 208-212 open, 213-251 random, 252-255 open.
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 2).shutter.mode, ShutterMode::Closed);
  const Shutter s = decodeOne(p, m, DmxAttribute::Shutter, 103).shutter;
  EXPECT_EQ(s.mode, ShutterMode::Strobe);
  EXPECT_NEAR(s.rateHz, 12.0f, 1e-4f);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 105).shutter.mode, ShutterMode::Open);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 150).shutter.mode, ShutterMode::Pulse);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 220).shutter.mode, ShutterMode::Random);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Shutter, 255).shutter.mode, ShutterMode::Open);
}

std::string bladeFixture() {
  auto channel = [](int offset, const std::string& attr, const std::string& functions) {
    return R"(<DMXChannel DMXBreak="1" Offset=")" + std::to_string(offset) + R"(" Default="0/1" Geometry="Beam">
            <LogicalChannel Attribute=")" + attr + R"(">)" + functions + R"(</LogicalChannel></DMXChannel>)";
  };
  auto plain = [&](int offset, const std::string& attr, const char* from, const char* to) {
    return channel(offset, attr, R"(<ChannelFunction Attribute=")" + attr + R"(" DMXFrom="0/1" PhysicalFrom=")" + from +
                                     R"(" PhysicalTo=")" + to + R"("/>)");
  };
  std::string channels = plain(1, "Dimmer", "0", "1");
  int offset = 2;
  for (int k = 1; k <= 4; ++k)
    for (const char* end : {"A", "B"})  // Blade4B in percent, which haze clamps to 0..1 and says so
      channels += plain(offset++, "Blade" + std::to_string(k) + end, "0", k == 4 && end[0] == 'B' ? "100" : "1");
  channels += plain(offset++, "ShaperRot", "-45", "45");
  channels += channel(offset++, "Prism1", R"(<ChannelFunction Attribute="Prism1" DMXFrom="0/1" Wheel="P">
              <ChannelSet DMXFrom="0/1" Name="Open" WheelSlotIndex="1"/>
              <ChannelSet DMXFrom="128/1" Name="Many" WheelSlotIndex="2"/></ChannelFunction>)");
  std::string facets;
  for (int i = 0; i < 40; ++i) facets += R"(<Facet Rotation="{1,0,0}{0,1,0}{)" + std::to_string(std::cos(i * 0.157)) + "," +
                                         std::to_string(std::sin(i * 0.157)) + R"(,1}"/>)";
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<GDTF DataVersion="1.1">
  <FixtureType Name="Shaper" Manufacturer="Test">
    <Wheels><Wheel Name="P"><Slot Name="Open"/><Slot Name="Many">)" + facets + R"(</Slot></Wheel></Wheels>
    <PhysicalDescriptions/>
    <Geometries>
      <Geometry Name="Base" Position="{1,0,0,0}{0,1,0,0}{0,0,1,0}{0,0,0,1}">
        <Beam Name="Beam" Position="{1,0,0,0}{0,1,0,0}{0,0,1,-0.2}{0,0,0,1}" LuminousFlux="10000" BeamAngle="20" FieldAngle="30"/>
      </Geometry>
    </Geometries>
    <DMXModes><DMXMode Name="Std" Geometry="Base"><DMXChannels>)" + channels + R"(</DMXChannels></DMXMode></DMXModes>
  </FixtureType>
</GDTF>
)";
}

TEST(GdtfOptics, ReadsFramingBladesAndClampsAPrismOfFortyFacets) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "haze_gdtf_optics";
  std::filesystem::create_directories(dir);
  ASSERT_TRUE(test::writeZip(dir / "shaper.gdtf", {{"description.xml", bladeFixture()}}));
  auto g = loadGdtf(dir / "shaper.gdtf");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  EXPECT_TRUE(p.hasBlades);
  ASSERT_EQ(p.prisms.size(), 1u);
  EXPECT_EQ(p.prisms[0].facets, kMaxPrismFacets);
  ASSERT_FALSE(p.warnings.empty());
  EXPECT_NE(p.warnings[0].find("40 facets; clamped to 24"), std::string::npos) << p.warnings[0];
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_NE(p.warnings[1].find("Blade4B runs from 0.000000 to 100.000000; haze clamps it to 0..1"), std::string::npos)
      << p.warnings[1];
  const DmxMode& m = p.modes.at(0);
  std::vector<uint8_t> dmx(m.channels.size(), 0);
  dmx[0] = 255;
  dmx[1] = 255;  // Blade1A all the way in
  dmx[4] = 51;   // Blade2B at 0.2
  dmx[9] = 255;  // ShaperRot +45
  dmx[10] = 200; // the prism
  const Attributes a = decodeDmx(p, m, dmx);
  EXPECT_FLOAT_EQ(a.blades[0].x, 1.0f);
  EXPECT_FLOAT_EQ(a.blades[0].y, 0.0f);
  EXPECT_FLOAT_EQ(a.blades[1].y, 0.2f);
  EXPECT_FLOAT_EQ(a.bladeRotationDeg, 45.0f);
  EXPECT_EQ(a.prism, "Many");
  dmx[8] = 128;  // Blade4B at 50 "percent": all the way in once clamped
  EXPECT_FLOAT_EQ(decodeDmx(p, m, dmx).blades[3].y, 1.0f);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace haze
