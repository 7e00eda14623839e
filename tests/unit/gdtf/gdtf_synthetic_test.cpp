// GDTF import on hand-built archives: the frame conversion with a known answer, the choice of
// the main beam, DMX offsets and value syntax, and broken files refused with a place.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fixtures/gdtf.h"
#include "fixtures/gdtf_geometry.h"
#include "fixtures/gdtf_wheels.h"
#include "fixtures/gdtf_xml.h"
#include "unit/gdtf/zip_builder.h"

namespace haze {
namespace {

using test::TempDir;
using test::writeZip;

// A small moving head. Yoke 0.2 m below the base; the head's tilt axis 0.1 m lower and
// 0.1 m to +X, 0.05 m to +Y (into the screen); the lens 0.3 m further down the head.
std::string movingHead(const std::string& beamAttrs = R"(BeamAngle="20" FieldAngle="30" LuminousFlux="5000" BeamType="Wash")",
                       const std::string& extraBeams = "", const std::string& channels = "") {
  std::string defaultChannels = R"(
        <DMXChannel DMXBreak="1" Offset="3,1" Geometry="Yoke">
          <LogicalChannel Attribute="Pan">
            <ChannelFunction Attribute="Pan" DMXFrom="0/2" PhysicalFrom="-270" PhysicalTo="270"/>
          </LogicalChannel>
        </DMXChannel>
        <DMXChannel DMXBreak="1" Offset="5" Geometry="Beam">
          <LogicalChannel Attribute="Dimmer">
            <ChannelFunction Attribute="Dimmer" DMXFrom="0/1" PhysicalFrom="0" PhysicalTo="1"/>
          </LogicalChannel>
        </DMXChannel>
        <DMXChannel DMXBreak="1" Offset="6" Geometry="Beam">
          <LogicalChannel Attribute="Gobo1">
            <ChannelFunction Attribute="Gobo1" DMXFrom="0/1" Wheel="G1">
              <ChannelSet DMXFrom="0/1" Name="Open" WheelSlotIndex="1"/>
              <ChannelSet DMXFrom="10/1" Name="Dots" WheelSlotIndex="2"/>
            </ChannelFunction>
            <ChannelFunction Attribute="Gobo1WheelSpin" DMXFrom="128/1" PhysicalFrom="-100" PhysicalTo="100"/>
          </LogicalChannel>
        </DMXChannel>
        <DMXChannel DMXBreak="1" Offset="7" Geometry="Beam">
          <LogicalChannel Attribute="Focus1Adjust">
            <ChannelFunction Attribute="Focus1Adjust" DMXFrom="0/1"/>
          </LogicalChannel>
        </DMXChannel>
        <DMXChannel DMXBreak="1" Offset="8" Geometry="Beam">
          <LogicalChannel Attribute="Zoom">
            <ChannelFunction Attribute="Zoom" DMXFrom="0/1" PhysicalFrom="10" PhysicalTo="40"/>
          </LogicalChannel>
        </DMXChannel>)";
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<GDTF DataVersion="1.2">
  <FixtureType Name="Test Head" Manufacturer="Haze Tests">
    <Wheels>
      <Wheel Name="G1"><Slot Name="Open"/><Slot Name="Dots" MediaFileName="dots"/></Wheel>
    </Wheels>
    <Geometries>
      <Geometry Name="Base" Position="{1,0,0,0}{0,1,0,0}{0,0,1,0}{0,0,0,1}">
        <Axis Name="Yoke" Position="{1,0,0,0}{0,1,0,0}{0,0,1,-0.2}{0,0,0,1}">
          <Axis Name="Head" Position="{1,0,0,0.1}{0,1,0,0.05}{0,0,1,-0.1}{0,0,0,1}">
            <Beam Name="Beam" Position="{1,0,0,0}{0,1,0,0}{0,0,1,-0.3}{0,0,0,1}" )" +
         beamAttrs + R"(/>)" + extraBeams + R"(
          </Axis>
        </Axis>
      </Geometry>
    </Geometries>
    <DMXModes>
      <DMXMode Name="Basic" Geometry="Base">
        <DMXChannels>)" +
         (channels.empty() ? defaultChannels : channels) + R"(
        </DMXChannels>
      </DMXMode>
    </DMXModes>
  </FixtureType>
</GDTF>
)";
}

// A 2x2 grey+alpha PNG: white opaque, black opaque, white with alpha 0, mid grey opaque.
std::string tinyPng() {
  static const unsigned char png[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
      0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x04, 0x00, 0x00, 0x00, 0xd8, 0xbf, 0xc5, 0xaf, 0x00, 0x00, 0x00,
      0x10, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xff, 0x9f, 0x01, 0x04, 0x1b, 0xfe, 0x03, 0x00, 0x1c,
      0xee, 0x05, 0x7c, 0x99, 0xde, 0x6c, 0x65, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60,
      0x82};
  return std::string(reinterpret_cast<const char*>(png), sizeof png);
}

Result<GdtfImport> importXml(const TempDir& dir, const std::string& xml, bool withMedia = true) {
  std::vector<test::ZipItem> items = {{"description.xml", xml}};
  if (withMedia) items.push_back({"wheels/dots.png", tinyPng()});
  EXPECT_TRUE(writeZip(dir / "t.gdtf", items));
  return loadGdtf(dir / "t.gdtf");
}

bool near3(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
  return std::fabs(a.x - b.x) < eps && std::fabs(a.y - b.y) < eps && std::fabs(a.z - b.z) < eps;
}

TEST(GdtfSynthetic, ConvertsTheGeometryFrameToHazeHeadFrame) {
  TempDir dir("frame");
  auto g = importXml(dir, movingHead());
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  EXPECT_EQ(p.name, "Test Head");
  EXPECT_EQ(p.manufacturer, "Haze Tests");
  // GDTF (x, y, z) -> haze (x, z, -y). Lens relative to the Head axis: GDTF (0, 0, -0.3)
  // -> haze (0, -0.3, 0). The Head axis in the fixture: GDTF (0.1, 0.05, -0.3) -> (0.1, -0.3, -0.05).
  EXPECT_TRUE(near3(p.lensOffset, {0.0f, -0.3f, 0.0f})) << p.lensOffset.x << " " << p.lensOffset.y << " " << p.lensOffset.z;
  EXPECT_TRUE(near3(g->pivotOffsetM, {0.1f, -0.3f, -0.05f}));
  EXPECT_EQ(g->beamGeometry, "Beam");
  EXPECT_EQ(g->beamCount, 1);
  EXPECT_FLOAT_EQ(p.fieldAngleDeg, 30.0f);
  EXPECT_FLOAT_EQ(p.zoomDeg.min, 10.0f);
  EXPECT_FLOAT_EQ(p.zoomDeg.max, 40.0f);
  EXPECT_FLOAT_EQ(p.panDeg.min, -270.0f);
  EXPECT_FLOAT_EQ(p.panDeg.max, 270.0f);
  EXPECT_TRUE(near3(gdtfToHaze({0.0f, 0.0f, -1.0f}), {0.0f, -1.0f, 0.0f}));  // beam -Z -> -Y
  EXPECT_TRUE(near3(gdtfToHaze({1.0f, 0.0f, 0.0f}), {1.0f, 0.0f, 0.0f}));    // reference axis X -> X
}

TEST(GdtfSynthetic, MapsDmxOffsetsBytesAndWheelSlots) {
  TempDir dir("dmx");
  auto g = importXml(dir, movingHead());
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  ASSERT_EQ(p.modes.size(), 1u);
  const DmxMode& m = p.modes[0];
  EXPECT_EQ(m.name, "Basic");
  ASSERT_EQ(m.footprint(), 8);
  // Offset "3,1": coarse byte at slot 3, fine byte at slot 1; slot 2 and 4 are unused.
  EXPECT_EQ(m.channels[2].attribute, DmxAttribute::Pan);
  EXPECT_EQ(m.channels[2].byte, 0);
  EXPECT_EQ(m.channels[2].bytes, 2);
  EXPECT_EQ(m.channels[0].attribute, DmxAttribute::Pan);
  EXPECT_EQ(m.channels[0].byte, 1);
  EXPECT_EQ(m.channels[0].name, "Pan fine");
  EXPECT_EQ(m.channels[1].attribute, DmxAttribute::None);
  EXPECT_EQ(m.channels[1].name, "(unused)");
  EXPECT_EQ(m.channels[3].name, "(unused)");
  EXPECT_FLOAT_EQ(m.channels[2].physicalFrom, -270.0f);
  EXPECT_FLOAT_EQ(m.channels[2].physicalTo, 270.0f);
  EXPECT_EQ(m.channels[4].attribute, DmxAttribute::Intensity);
  const DmxChannel& gobo = m.channels[5];
  EXPECT_EQ(gobo.attribute, DmxAttribute::Gobo);
  EXPECT_EQ(gobo.wheel, 0);
  ASSERT_EQ(gobo.slotRanges.size(), 2u);
  EXPECT_EQ(gobo.slotRanges[0].from, 0);
  EXPECT_EQ(gobo.slotRanges[0].to, 9);
  EXPECT_EQ(gobo.slotRanges[0].slot, 0);
  EXPECT_EQ(gobo.slotRanges[1].from, 10);
  EXPECT_EQ(gobo.slotRanges[1].to, 127);  // the wheel spin function starts at 128
  EXPECT_EQ(gobo.slotRanges[1].slot, 1);
  EXPECT_EQ(m.channels[6].attribute, DmxAttribute::None);  // Focus1Adjust
  EXPECT_EQ(m.channels[7].attribute, DmxAttribute::Zoom);
  bool focusWarned = false;
  for (const auto& w : g->warnings) focusWarned |= w.find("'Focus1Adjust' is not used by haze") != std::string::npos &&
                                                    w.find("description.xml line") != std::string::npos;
  EXPECT_TRUE(focusWarned);
  // The gobo image: Annex E, white opaque passes, black blocks, alpha 0 (holder) blocks.
  ASSERT_EQ(p.goboWheels.size(), 1u);
  ASSERT_EQ(p.goboWheels[0].slots.size(), 2u);
  EXPECT_EQ(p.goboWheels[0].slots[1].name, "Dots");
  const auto& img = p.goboWheels[0].slots[1].image;
  ASSERT_TRUE(img);
  ASSERT_EQ(img->width, 2);
  ASSERT_EQ(img->transmittance.size(), 4u);
  EXPECT_NEAR(img->transmittance[0], 1.0f, 1e-6);
  EXPECT_NEAR(img->transmittance[1], 0.0f, 1e-6);
  EXPECT_NEAR(img->transmittance[2], 0.0f, 1e-6);
  EXPECT_NEAR(img->transmittance[3], 0.2158605f, 1e-4);  // sRGB 128 decoded to linear
}

// Several Beams are cells (docs/cells.md); the brightest is the profile's own beam.
TEST(GdtfSynthetic, PicksTheBrightestOfSeveralBeamsAndWarns) {
  TempDir dir("multi");
  const std::string extra = R"(
            <Beam Name="Cell2" Position="{1,0,0,0.2}{0,1,0,0}{0,0,1,-0.3}{0,0,0,1}" LuminousFlux="9000" BeamType="Spot" BeamAngle="10" FieldAngle="10"/>
            <Beam Name="Glow" LuminousFlux="99999" BeamType="Glow"/>)";
  auto g = importXml(dir, movingHead(R"(LuminousFlux="5000")", extra));
  ASSERT_TRUE(g.ok()) << g.error().str();
  EXPECT_EQ(g->beamGeometry, "Cell2");
  EXPECT_EQ(g->beamCount, 3);
  EXPECT_TRUE(near3(g->profile->lensOffset, {0.2f, -0.3f, 0.0f}));
  EXPECT_FLOAT_EQ(g->profile->fieldAngleDeg, 10.0f);
  bool warned = false;  // the Glow beam lights nothing: two cells
  for (const auto& w : g->warnings) warned |= w.find("2 Beam geometries: imported as 2 cells") != std::string::npos;
  EXPECT_TRUE(warned);
  ASSERT_EQ(g->profile->cells.size(), 2u);
  EXPECT_EQ(g->profile->cells[1].name, "Cell2");
}

TEST(GdtfSynthetic, RefusesAFixtureWithoutLight) {
  TempDir dir("nolight");
  auto g = importXml(dir, movingHead(R"(BeamType="None")"));
  ASSERT_FALSE(g.ok());
  EXPECT_NE(g.error().message.find("BeamType None or Glow"), std::string::npos) << g.error().str();
  EXPECT_NE(g.error().place.find("description.xml line 11"), std::string::npos) << g.error().str();
}

TEST(GdtfSynthetic, RefusesBadFilesWithTheXmlPlace) {
  TempDir dir("bad");
  struct Case {
    std::string xml;
    std::string place;    // expected in Error::place
    std::string message;  // expected in Error::message
  };
  const std::vector<Case> cases = {
      {movingHead(R"(BeamAngle="nan")"), "line 11", "BeamAngle is 'nan'; expected a finite number"},
      {movingHead(R"(BeamAngle="1e30")"), "line 11", "expected a value between 0 and 179"},
      {movingHead(R"(LuminousFlux="-5")"), "<Beam Name=\"Beam\">", "LuminousFlux is -5"},
      {movingHead("", "", R"(<DMXChannel Offset="600"><LogicalChannel Attribute="Dimmer"><ChannelFunction/></LogicalChannel></DMXChannel>)"),
       "<DMXChannel>", "outside the DMX universe"},
      {movingHead("", "", R"(<DMXChannel Offset="1"><LogicalChannel Attribute="Dimmer"><ChannelFunction DMXFrom="x/9"/></LogicalChannel></DMXChannel>)"),
       "<ChannelFunction>", "DMXFrom is 'x/9'"},
      {movingHead("", "", R"(<DMXChannel Offset="1"/><DMXChannel Offset="1"/>)"), "line", "DMX slot 1 is used twice"},
      {"<GDTF><FixtureType Name=\"x\"><Geometries><Geometry Name=\"a\" Position=\"{1,0,0}\"/></Geometries></FixtureType></GDTF>",
       "line 1", "expected a 4x4 matrix"},
      {"<GDTF><FixtureType><Geometries/></FixtureType></GDTF>", "line 1", "has no Name"},
      {"<NotGdtf/>", "description.xml", "root element is not <GDTF>"},
      // A GeometryReference that instances its own parent: the walk must stop.
      {"<GDTF><FixtureType Name=\"x\"><Geometries><Geometry Name=\"a\"><GeometryReference Name=\"r\" Geometry=\"a\"/>"
       "</Geometry></Geometries></FixtureType></GDTF>",
       "<GeometryReference Name=\"r\">", "deeper than 32 levels"},
      {"<GDTF><FixtureType Name=\"x\"><Geometries><Geometry Name=\"a\"><GeometryReference Name=\"r\" Geometry=\"nope\"/>"
       "</Geometry></Geometries></FixtureType></GDTF>",
       "<GeometryReference Name=\"r\">", "references the geometry 'nope'"},
      // Scales of 1e5 composed three times put the lens at 1e10 m.
      {"<GDTF><FixtureType Name=\"x\"><Geometries><Geometry Name=\"a\" Position=\"{1e5,0,0,0}{0,1e5,0,0}{0,0,1e5,0}{0,0,0,1}\">"
       "<Axis Name=\"b\" Position=\"{1e5,0,0,0}{0,1e5,0,0}{0,0,1e5,0}{0,0,0,1}\">"
       "<Beam Name=\"c\" Position=\"{1,0,0,0}{0,1,0,0}{0,0,1,-1}{0,0,0,1}\"/></Axis></Geometry></Geometries></FixtureType></GDTF>",
       "<Beam Name=\"c\">", "more than 1 km"},
      {"<GDTF>\n<FixtureType Name=\"x\">\n<Geometries>\n</GDTF>", "line 4", "not well-formed XML"},
  };
  for (const Case& c : cases) {
    auto g = importXml(dir, c.xml);
    ASSERT_FALSE(g.ok()) << c.message;
    EXPECT_EQ(g.error().file, (dir / "t.gdtf").string());
    EXPECT_NE(g.error().place.find(c.place), std::string::npos) << g.error().str();
    EXPECT_NE(g.error().message.find(c.message), std::string::npos) << g.error().str();
    EXPECT_EQ(g.error().str().find('\n'), std::string::npos) << "one line: " << g.error().str();
  }
}

TEST(GdtfSynthetic, RefusesAnArchiveWithoutDescription) {
  TempDir dir("nodesc");
  ASSERT_TRUE(writeZip(dir / "t.gdtf", {{"thumbnail.png", tinyPng()}, {"wheels/dots.png", tinyPng()}}));
  auto g = loadGdtf(dir / "t.gdtf");
  ASSERT_FALSE(g.ok());
  EXPECT_NE(g.error().message.find("no description.xml"), std::string::npos) << g.error().str();
}

TEST(GdtfSynthetic, WarnsAboutMissingGoboMedia) {
  TempDir dir("media");
  auto g = importXml(dir, movingHead(), /*withMedia=*/false);
  ASSERT_TRUE(g.ok()) << g.error().str();
  const WheelSlot& slot = g->profile->goboWheels[0].slots[1];
  EXPECT_EQ(slot.imagePath, "wheels/dots.png");
  EXPECT_FALSE(slot.image);
  bool warned = false;
  for (const auto& w : g->warnings) warned |= w.find("'wheels/dots.png' is missing") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(GdtfSynthetic, RefusesABrokenGoboImage) {
  TempDir dir("badpng");
  ASSERT_TRUE(writeZip(dir / "t.gdtf", {{"description.xml", movingHead()}, {"wheels/dots.png", "\x89PNG garbage"}}));
  auto g = loadGdtf(dir / "t.gdtf");
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.error().place, "wheels/dots.png");
}

TEST(GdtfValues, DmxValueSyntax) {
  EXPECT_EQ(parseDmxValue("255/1", 1), 255u);
  EXPECT_EQ(parseDmxValue("255/1", 2), 65535u);   // byte mirroring
  EXPECT_EQ(parseDmxValue("255/1s", 2), 65280u);  // byte shifting
  EXPECT_EQ(parseDmxValue("128/1", 2), 32896u);   // 0x8080
  EXPECT_EQ(parseDmxValue("32768/2", 1), 128u);
  EXPECT_EQ(parseDmxValue("1/1", 3), 65793u);     // 0x010101
  EXPECT_EQ(parseDmxValue("7", 1), 7u);
  EXPECT_FALSE(parseDmxValue("256/1", 1));
  EXPECT_FALSE(parseDmxValue("-1/1", 1));
  EXPECT_FALSE(parseDmxValue("1/5", 1));
  EXPECT_FALSE(parseDmxValue("", 1));
  EXPECT_FALSE(parseDmxValue("12/", 1));
}

TEST(GdtfValues, CieXyYToLinearSrgbFilter) {
  const glm::vec3 white = cieXyYToFilterRgb(0.3127f, 0.3290f, 100.0f);  // D65
  EXPECT_NEAR(white.r, 1.0f, 2e-3);
  EXPECT_NEAR(white.g, 1.0f, 2e-3);
  EXPECT_NEAR(white.b, 1.0f, 2e-3);
  // The sRGB primaries map to the pure channels, whatever their Y.
  const glm::vec3 red = cieXyYToFilterRgb(0.64f, 0.33f, 21.26f);
  EXPECT_NEAR(red.r, 1.0f, 1e-3);
  EXPECT_NEAR(red.g, 0.0f, 2e-3);
  EXPECT_NEAR(red.b, 0.0f, 2e-3);
  const glm::vec3 green = cieXyYToFilterRgb(0.30f, 0.60f, 0.5f);
  EXPECT_NEAR(green.g, 1.0f, 1e-3);
  EXPECT_NEAR(green.r, 0.0f, 2e-3);
  const glm::vec3 blue = cieXyYToFilterRgb(0.15f, 0.06f, 7.22f);
  EXPECT_NEAR(blue.b, 1.0f, 1e-3);
  EXPECT_NEAR(blue.r, 0.0f, 2e-3);
}

}  // namespace
}  // namespace haze
