// GDTF optics beyond the gobo: the bundled BMFL Spot and Alpha Spot import with their prisms,
// frost and shutter (numbers read from their description.xml by hand), their DMX values decode
// into shutter modes and rates, and a synthetic fixture with framing blades and an oversized
// prism imports with the blades and a clamped prism.
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>

#include "fixtures/dmx_decode.h"
#include "fixtures/gdtf.h"
#include "unit/gdtf/zip_builder.h"
#include "test_data.h"

namespace haze {
namespace {


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
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  auto g = loadGdtf(test::dataFile("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"));
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

TEST(GdtfOptics, BmflHasTwoGoboWheelsAndGobo2DrivesTheSecond) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  auto g = loadGdtf(test::dataFile("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  // <Wheel Name="Gobo1"> and <Wheel Name="Gobo2">: Open and six gobos each.
  ASSERT_EQ(p.goboWheels.size(), 2u);
  EXPECT_EQ(p.goboWheels[0].slots.size(), 7u);
  EXPECT_EQ(p.goboWheels[1].slots.size(), 7u);
  EXPECT_EQ(p.goboWheels[1].slots[2].name, "G02 (Radial Dashes 18)");
  ASSERT_EQ(p.colorWheels.size(), 2u);
  const DmxMode& m = p.modes.at(0);
  // Mode 1: Gobo1 at offset 23, Gobo1Pos 24-25, Gobo2 at 26, Gobo2Pos 27-28, Color2 at 9-10.
  EXPECT_EQ(m.channels[22].attribute, DmxAttribute::Gobo);
  EXPECT_EQ(m.channels[22].wheel, 0);
  EXPECT_EQ(m.channels[25].attribute, DmxAttribute::Gobo);
  EXPECT_EQ(m.channels[25].wheel, 1);
  EXPECT_EQ(m.channels[26].attribute, DmxAttribute::GoboRotation);
  EXPECT_EQ(m.channels[26].wheel, 1);
  EXPECT_EQ(m.channels[26].bytes, 2);
  EXPECT_EQ(m.channels[8].attribute, DmxAttribute::ColorWheel);
  EXPECT_EQ(m.channels[8].wheel, 1);
  // Gobo2 "Gobo 2" from DMX 9 is WheelSlotIndex 3; Gobo2Pos -180..180 over 0..65535.
  std::vector<uint8_t> dmx(m.channels.size(), 0);
  dmx[25] = 10;
  dmx[26] = 255;
  dmx[27] = 255;
  const Attributes a = decodeDmx(p, m, dmx);
  EXPECT_EQ(a.gobo, "Open");
  EXPECT_EQ(a.gobo2, "G02 (Radial Dashes 18)");
  EXPECT_NEAR(a.gobo2RotationDeg, 180.0f, 1e-3f);
  EXPECT_NEAR(a.goboRotationDeg, -180.0f, 1e-3f);  // Gobo1Pos at 0
  // Color2 (16 bit) "Pink - Positioning" from 4626 (coarse 18) is WheelSlotIndex 2, the second
  // wheel's "C01 (Pink)"; CTO at offset 14 runs 0..1 of a full CTO, +159 mired.
  EXPECT_EQ(a.color2, "Open");
  EXPECT_EQ(a.ctoMired, 0.0f);
  EXPECT_EQ(m.channels[13].attribute, DmxAttribute::Cto);
  dmx[8] = 20;
  dmx[13] = 255;
  const Attributes c = decodeDmx(p, m, dmx);
  EXPECT_EQ(c.color2, "C01 (Pink)");
  EXPECT_NEAR(c.ctoMired, 159.0f, 1e-3f);
  EXPECT_EQ(c.color, a.color);  // the second wheel is its own attribute, not folded in
}

// The BMFL tells index from spin by its gobo and prism channels (ModeMaster on a SelectSpin
// range): Gobo1 32-59 is "Gobo n - Rotation", and then Gobo1Pos (16 bit) runs -30 -> 30 deg/s.
TEST(GdtfOptics, BmflSpinsWhenItsWheelChannelSelectsSpinning) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  auto g = loadGdtf(test::dataFile("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  const DmxMode& m = p.modes.at(0);
  ASSERT_TRUE(m.channels[23].spinWhenSelected.has_value());
  std::vector<uint8_t> dmx(m.channels.size(), 0);
  dmx[22] = 34;  // Gobo1 "Gobo 1 - Rotation"
  Attributes a = decodeDmx(p, m, dmx);
  EXPECT_EQ(a.gobo, p.goboWheels[0].slots[1].name);
  EXPECT_NEAR(a.goboSpinDegS, -30.0f, 1e-3f);  // Gobo1Pos at 0: forwards fast
  EXPECT_EQ(a.goboRotationDeg, 0.0f);
  dmx[23] = dmx[24] = 255;
  EXPECT_NEAR(decodeDmx(p, m, dmx).goboSpinDegS, 30.0f, 1e-3f);
  dmx[23] = 128;
  dmx[24] = 0;  // the middle: still, within one step of 60 / 65535 deg/s
  EXPECT_NEAR(decodeDmx(p, m, dmx).goboSpinDegS, 0.0f, 1e-3f);
  // Gobo1 at 10 indexes: the same Gobo1Pos is an angle, -180 -> 180 degrees.
  dmx[22] = 10;
  dmx[23] = dmx[24] = 255;
  a = decodeDmx(p, m, dmx);
  EXPECT_NEAR(a.goboRotationDeg, 180.0f, 1e-3f);
  EXPECT_EQ(a.goboSpinDegS, 0.0f);
  // Prism1 50-75 selects spinning: Prism1Pos (8 bit) at 255 is +30 deg/s.
  dmx[28] = 60;
  dmx[29] = 255;
  a = decodeDmx(p, m, dmx);
  EXPECT_NEAR(a.prismSpinDegS, 30.0f, 1e-3f);
  EXPECT_EQ(a.prismRotationDeg, 0.0f);
}

TEST(GdtfOptics, AlphaSpotNamesItsThreeFacetPrismAndPulses) {
  HAZE_NEED_DATA("gdtf/Clay Paky@Alpha Spot QWO 800@allWorking.gdtf");
  auto g = loadGdtf(test::dataFile("gdtf/Clay Paky@Alpha Spot QWO 800@allWorking.gdtf"));
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
  // One channel, two ranges: an angle over 0-127, a spin of -60 -> 60 deg/s over 128-255.
  channels += channel(offset++, "Prism1Pos", R"(<ChannelFunction Attribute="Prism1Pos" DMXFrom="0/1" PhysicalFrom="0" PhysicalTo="360"/>
              <ChannelFunction Attribute="Prism1PosRotate" DMXFrom="128/1" PhysicalFrom="-60" PhysicalTo="60"/>)");
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
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("haze_gdtf_optics." + std::to_string(::getpid()));
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
  // Prism1Pos: in the index range an angle (0 -> 360 over 0-127), in the rotate range a spin.
  ASSERT_EQ(m.channels[11].spinRanges.size(), 1u);
  EXPECT_EQ(m.channels[11].spinRanges[0].from, 128);
  EXPECT_EQ(m.channels[11].spinRanges[0].to, 255);
  dmx[11] = 64;
  Attributes turn = decodeDmx(p, m, dmx);
  EXPECT_NEAR(turn.prismRotationDeg, 64.0f / 127.0f * 360.0f, 1e-3f);
  EXPECT_EQ(turn.prismSpinDegS, 0.0f);
  for (const auto& [value, degS] : {std::pair{128, -60.0f}, std::pair{255, 60.0f}, std::pair{200, -60.0f + 120.0f * 72.0f / 127.0f}}) {
    dmx[11] = static_cast<uint8_t>(value);
    turn = decodeDmx(p, m, dmx);
    EXPECT_NEAR(turn.prismSpinDegS, degS, 1e-3f) << value;
    EXPECT_EQ(turn.prismRotationDeg, 0.0f) << value;
  }
  std::filesystem::remove_all(dir);
}

// Animation wheels (docs/physics.md, "Animation wheel"). The BMFL's wheel "Animation" carries its
// disc (wheels/11020171.png, 256 x 256); its AnimationWheel1 channel picks the disc from DMX 20
// (WheelSlotIndex 1, "Proportional indexing min") and AnimationWheel1PosRotate turns it at
// -30..30 deg/s. The Alpha Spot's AnimationWheel1 names no wheel: haze adds one slot with its
// default disc, in from DMX 255 (the ChannelSet "Animation"), and the rotate channel runs
// -720..720 deg/s.
TEST(GdtfAnimation, BmflImportsItsDiscAndItsChannels) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  auto g = loadGdtf(test::dataFile("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  ASSERT_EQ(p.animationWheels.size(), 1u);
  EXPECT_EQ(p.animationWheels[0].name, "Animation");
  ASSERT_EQ(p.animationWheels[0].slots.size(), 2u);
  EXPECT_EQ(p.animationWheels[0].slots[0].name, "Open");
  const WheelSlot& disc = p.animationWheels[0].slots[1];
  EXPECT_EQ(disc.name, "Animation");
  ASSERT_NE(disc.image, nullptr);
  EXPECT_EQ(disc.image->width, 256);
  const DmxMode& m = p.modes.at(0);
  const DmxChannel* slot = channelOf(m, DmxAttribute::Animation);
  ASSERT_NE(slot, nullptr);
  const DmxChannel* spin = channelOf(m, DmxAttribute::AnimationSpin);
  ASSERT_NE(spin, nullptr);
  EXPECT_FLOAT_EQ(spin->physicalFrom, -30.0f);
  EXPECT_FLOAT_EQ(spin->physicalTo, 30.0f);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Animation, 0).animation, "Open");
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Animation, 19).animation, "Open");
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Animation, 73).animation, "Animation");
  EXPECT_NEAR(decodeOne(p, m, DmxAttribute::AnimationSpin, 255).animationSpinDegS, 30.0f, 1e-4f);
  // In the beam the disc's own image is drawn, not the default.
  Attributes a;
  a.animation = "Animation";
  EXPECT_EQ(p.optics(a).animation, disc.image);
}

TEST(GdtfAnimation, AlphaSpotGetsTheDefaultDiscForAWheellessChannel) {
  HAZE_NEED_DATA("gdtf/Clay Paky@Alpha Spot QWO 800@allWorking.gdtf");
  auto g = loadGdtf(test::dataFile("gdtf/Clay Paky@Alpha Spot QWO 800@allWorking.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  ASSERT_EQ(p.animationWheels.size(), 1u);
  ASSERT_EQ(p.animationWheels[0].slots.size(), 2u);
  EXPECT_EQ(p.animationWheels[0].slots[1].name, "Animation");
  EXPECT_EQ(p.animationWheels[0].slots[1].image, nullptr);
  bool warned = false;
  for (const std::string& w : p.warnings) warned = warned || w.find("default disc") != std::string::npos;
  EXPECT_TRUE(warned);
  const DmxMode& m = p.modes.at(0);
  ASSERT_NE(channelOf(m, DmxAttribute::Animation), nullptr);
  EXPECT_EQ(decodeOne(p, m, DmxAttribute::Animation, 254).animation, "Open");
  const Attributes in = decodeOne(p, m, DmxAttribute::Animation, 255);
  EXPECT_EQ(in.animation, "Animation");
  EXPECT_NE(p.optics(in).animation, nullptr);  // the default disc
  const DmxChannel* spin = channelOf(m, DmxAttribute::AnimationSpin);
  ASSERT_NE(spin, nullptr);
  EXPECT_NEAR(spin->physicalTo, 719.98f, 0.01f);
}


// The BMFL's Focus1 (description.xml: mode 1 at offsets 36,37, 16 bits, "Focus far" at 0 to
// "Focus near" at 65535; mode 2 at offset 30, 8 bits) gives the profile a focus with haze's
// defaults, and its DMX value runs 0..1 over the lens's travel (docs/gdtf.md, "Focus").
TEST(GdtfFocus, BmflFocus1DecodesOverTheLensesTravel) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  auto g = loadGdtf(test::dataFile("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  EXPECT_TRUE(p.hasGateFocus);
  EXPECT_FLOAT_EQ(p.focusSharp, kDefaultFocusSharp);
  EXPECT_FLOAT_EQ(p.focusBlur, kDefaultFocusBlur);
  for (const DmxMode& m : p.modes) {
    int coarse = -1, fine = -1;
    for (size_t i = 0; i < m.channels.size(); ++i)
      if (m.channels[i].attribute == DmxAttribute::GateFocus) (m.channels[i].byte == 0 ? coarse : fine) = static_cast<int>(i);
    ASSERT_GE(coarse, 0) << m.name;
    std::vector<uint8_t> dmx(m.channels.size(), 0);
    EXPECT_FLOAT_EQ(decodeDmx(p, m, dmx).gateFocus, 0.0f) << m.name;
    dmx[static_cast<size_t>(coarse)] = 255;
    if (fine >= 0) dmx[static_cast<size_t>(fine)] = 255;
    EXPECT_FLOAT_EQ(decodeDmx(p, m, dmx).gateFocus, 1.0f) << m.name;
    dmx[static_cast<size_t>(coarse)] = 64;
    if (fine >= 0) dmx[static_cast<size_t>(fine)] = 0;
    const float quarter = fine >= 0 ? 64.0f * 256.0f / 65535.0f : 64.0f / 255.0f;
    const Attributes a = decodeDmx(p, m, dmx);
    EXPECT_NEAR(a.gateFocus, quarter, 1e-6f) << m.name;
    // In the beam: the gate blurred by |focus - 0.5| * 0.3 gate radii.
    EXPECT_NEAR(p.optics(a).focusBlur, (0.5f - quarter) * 0.3f, 1e-6f) << m.name;
  }
  EXPECT_EQ(p.modes.size(), 2u);
}

}  // namespace
}  // namespace haze
