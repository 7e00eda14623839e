// GDTF names that are not valid UTF-8 (Latin-1 bytes from older tools) are cleaned on import as
// the IES and EULUMDAT names are (textToUtf8), so the profile can be saved as JSON.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fixtures/gdtf.h"
#include "fixtures/profile.h"
#include "unit/gdtf/zip_builder.h"

namespace haze {
namespace {

// \xfc = u-umlaut, \xe9 = e-acute, \x01 a control byte: all as Latin-1 bytes.
std::string latin1Head() {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<GDTF DataVersion=\"1.2\">\n"
         "  <FixtureType Name=\"B\xfchne\x01 Spot\" Manufacturer=\"M\xfcller\">\n"
         "    <Wheels><Wheel Name=\"R\xe9gie\"><Slot Name=\"Open\"/><Slot Name=\"Kreis\xe9\"/></Wheel></Wheels>\n"
         "    <Geometries>\n"
         "      <Geometry Name=\"Base\" Position=\"{1,0,0,0}{0,1,0,0}{0,0,1,0}{0,0,0,1}\">\n"
         "        <Beam Name=\"Strahl\xe9\" BeamAngle=\"20\" FieldAngle=\"30\" LuminousFlux=\"5000\"/>\n"
         "      </Geometry>\n"
         "    </Geometries>\n"
         "    <DMXModes>\n"
         "      <DMXMode Name=\"Standard \xfc\" Geometry=\"Base\"><DMXChannels>\n"
         "        <DMXChannel DMXBreak=\"1\" Offset=\"1\" Geometry=\"Strahl\xe9\"><LogicalChannel Attribute=\"Dimmer\">\n"
         "          <ChannelFunction Attribute=\"Dimmer\" DMXFrom=\"0/1\" PhysicalFrom=\"0\" PhysicalTo=\"1\"/></LogicalChannel></DMXChannel>\n"
         "        <DMXChannel DMXBreak=\"1\" Offset=\"2\" Geometry=\"Strahl\xe9\"><LogicalChannel Attribute=\"Gobo1\">\n"
         "          <ChannelFunction Attribute=\"Gobo1\" DMXFrom=\"0/1\" Wheel=\"R\xe9gie\">\n"
         "            <ChannelSet DMXFrom=\"0/1\" Name=\"Open\" WheelSlotIndex=\"1\"/>\n"
         "            <ChannelSet DMXFrom=\"128/1\" Name=\"Kreis\" WheelSlotIndex=\"2\"/>\n"
         "          </ChannelFunction></LogicalChannel></DMXChannel>\n"
         "      </DMXChannels></DMXMode>\n"
         "    </DMXModes>\n"
         "  </FixtureType>\n"
         "</GDTF>\n";
}

TEST(GdtfUtf8, Latin1NamesAreCleanedAndTheProfileSavesAsJson) {
  test::TempDir dir("utf8");
  ASSERT_TRUE(test::writeZip(dir / "latin1.gdtf", {{"description.xml", latin1Head()}}));
  auto g = loadGdtf(dir / "latin1.gdtf");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  EXPECT_EQ(p.name, "B\xc3\xbchne Spot");  // Latin-1 read as such, the control byte dropped
  EXPECT_EQ(p.manufacturer, "M\xc3\xbcller");
  EXPECT_EQ(g->beamGeometry, "Strahl\xc3\xa9");
  ASSERT_EQ(p.modes.size(), 1u);
  EXPECT_EQ(p.modes[0].name, "Standard \xc3\xbc");
  EXPECT_NE(p.findMode("Standard \xc3\xbc"), nullptr);
  ASSERT_EQ(p.goboWheels.size(), 1u);
  EXPECT_EQ(p.goboWheels[0].name, "R\xc3\xa9gie");
  ASSERT_EQ(p.goboWheels[0].slots.size(), 2u);
  EXPECT_EQ(p.goboWheels[0].slots[1].name, "Kreis\xc3\xa9");
  // nlohmann::json throws type_error 316 on invalid UTF-8: this is what failed before.
  std::string text;
  EXPECT_NO_THROW(text = profileToJson(p).dump());
  EXPECT_NE(text.find("B\xc3\xbchne Spot"), std::string::npos);
}

TEST(GdtfUtf8, ValidUtf8NamesAreKeptAsTheyAre) {
  std::string xml = latin1Head();
  // The same file written correctly: UTF-8 bytes for the same letters.
  for (auto [from, to] : {std::pair<std::string, std::string>{"\xfc", "\xc3\xbc"}, {"\xe9", "\xc3\xa9"}, {"\x01", ""}}) {
    for (size_t at = xml.find(from); at != std::string::npos; at = xml.find(from, at + to.size()))
      xml.replace(at, from.size(), to);
  }
  test::TempDir dir("utf8ok");
  ASSERT_TRUE(test::writeZip(dir / "utf8.gdtf", {{"description.xml", xml}}));
  auto g = loadGdtf(dir / "utf8.gdtf");
  ASSERT_TRUE(g.ok()) << g.error().str();
  EXPECT_EQ(g->profile->name, "B\xc3\xbchne Spot");
  EXPECT_EQ(g->profile->goboWheels.at(0).name, "R\xc3\xa9gie");
}

TEST(GdtfUtf8, ErrorPlacesNameTheElementInUtf8) {
  std::string xml = latin1Head();
  xml.replace(xml.find("BeamAngle=\"20\""), 14, "BeamAngle=\"abc\"");
  test::TempDir dir("utf8err");
  ASSERT_TRUE(test::writeZip(dir / "bad.gdtf", {{"description.xml", xml}}));
  auto g = loadGdtf(dir / "bad.gdtf");
  ASSERT_FALSE(g.ok());
  EXPECT_NE(g.error().place.find("Name=\"Strahl\xc3\xa9\""), std::string::npos) << g.error().place;
}

}  // namespace
}  // namespace haze
