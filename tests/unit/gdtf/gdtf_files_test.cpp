// Every real GDTF of the test data (gdtf/) imports, checked against numbers read independently
// from its description.xml (libzip + pugixml here, not the importer's code) and against the
// gobo images copied out of the archives into the test data's gobos/gdtf-wheels.
#include <gtest/gtest.h>

#include <zip.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <pugixml.hpp>
#include <string>

#include "fixtures/gdtf.h"
#include "fixtures/gdtf_wheels.h"
#include "fixtures/gobo_image.h"
#include "unit/gdtf/zip_builder.h"
#include "test_data.h"

namespace haze {
namespace {

std::filesystem::path gdtfFile(const std::string& name) { return test::dataFile("gdtf/" + name); }

// The bytes of one archive member, read with libzip directly.
std::string unzipMember(const std::filesystem::path& file, const char* member) {
  int err = 0;
  zip_t* z = zip_open(file.string().c_str(), ZIP_RDONLY, &err);
  if (!z) return {};
  std::string out;
  zip_stat_t st;
  if (zip_stat(z, member, 0, &st) == 0) {
    if (zip_file_t* f = zip_fopen(z, member, 0)) {
      out.resize(st.size);
      if (zip_fread(f, out.data(), st.size) != static_cast<zip_int64_t>(st.size)) out.clear();
      zip_fclose(f);
    }
  }
  zip_discard(z);
  return out;
}

struct ModeFacts {
  std::string name;
  int footprint = 0;   // the largest Offset of the mode's DMX break 1
};

std::vector<ModeFacts> modesFromXml(const pugi::xml_document& doc) {
  std::vector<ModeFacts> out;
  for (pugi::xml_node m : doc.child("GDTF").child("FixtureType").child("DMXModes").children("DMXMode")) {
    ModeFacts f{m.attribute("Name").value(), 0};
    for (pugi::xml_node ch : m.child("DMXChannels").children("DMXChannel")) {
      std::string offsets = ch.attribute("Offset").value();
      std::size_t start = 0;
      while (start < offsets.size()) {
        std::size_t comma = offsets.find(',', start);
        if (comma == std::string::npos) comma = offsets.size();
        f.footprint = std::max(f.footprint, std::stoi(offsets.substr(start, comma - start)));
        start = comma + 1;
      }
    }
    out.push_back(f);
  }
  return out;
}

// Flux by Simpson's rule over theta (the distributions are axially symmetric).
double fluxLm(const Distribution& d) {
  const int n = 20000;
  const double h = std::min<double>(d.maxThetaRad(), M_PI) / n;
  double s = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = i * h;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    s += w * d.intensityCd(static_cast<float>(t), 0.0f) * std::sin(t);
  }
  return 2.0 * M_PI * s * h / 3.0;
}

class GdtfFile : public ::testing::TestWithParam<std::string> {};

TEST_P(GdtfFile, ImportsWithTheNumbersOfItsXml) {
  HAZE_NEED_DATA("gdtf/" + GetParam());
  const auto file = gdtfFile(GetParam());
  const std::string xml = unzipMember(file, "description.xml");
  ASSERT_FALSE(xml.empty());
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_buffer(xml.data(), xml.size()));
  pugi::xml_node ft = doc.child("GDTF").child("FixtureType");

  auto g = loadGdtf(file);
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  EXPECT_EQ(p.name, ft.attribute("Name").value());
  EXPECT_EQ(p.manufacturer, ft.attribute("Manufacturer").value());
  const auto modes = modesFromXml(doc);
  ASSERT_EQ(p.modes.size(), modes.size());
  for (std::size_t i = 0; i < modes.size(); ++i) {
    EXPECT_EQ(p.modes[i].name, modes[i].name);
    EXPECT_EQ(p.modes[i].footprint(), modes[i].footprint) << modes[i].name;
  }
  // Photometry: the distribution carries the Beam's LuminousFlux (within 1 %).
  pugi::xml_node beam = doc.select_node("//Beam").node();
  ASSERT_TRUE(beam);
  const double lumens = beam.attribute("LuminousFlux").as_double();
  ASSERT_TRUE(p.distribution);
  EXPECT_NEAR(fluxLm(*p.distribution), lumens, 0.01 * lumens);
  EXPECT_FLOAT_EQ(p.fieldAngleDeg, beam.attribute("FieldAngle").as_float());
  // The field angle is where the intensity falls to 10 % of the peak.
  EXPECT_NEAR(p.distribution->intensityCd(static_cast<float>(p.fieldAngleDeg * M_PI / 360.0), 0.0f),
              0.1 * p.distribution->peakCd(), 0.002 * p.distribution->peakCd());
  for (const std::string& w : g->warnings) EXPECT_EQ(w.find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(SharedData, GdtfFile,
                         ::testing::Values("BlenderDMX@LED_PAR_64_RGBW@v0.3.gdtf", "BlenderDMX@BeskydBeam@version10.gdtf",
                                           "Clay Paky@Alpha Spot QWO 800@allWorking.gdtf",
                                           "Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"),
                         [](const auto& info) {
                           std::string n = info.param.substr(0, info.param.find('@', info.param.find('@') + 1));
                           for (char& c : n) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return n;
                         });

TEST(GdtfFiles, EveryFileInTheFolderIsCovered) {
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(test::dataDir("gdtf"))) count += e.path().extension() == ".gdtf";
  // Four in ../shared/data, one of them in the repository (tests/data/shared/SOURCES.md).
  EXPECT_EQ(count, test::haveFullData() ? 4 : 1) << "a new .gdtf in the test data: add it to the SharedData list";
}

TEST(GdtfFiles, LedParIsAnRgbwWashHangingBelowItsBody) {
  auto g = loadGdtf(gdtfFile("BlenderDMX@LED_PAR_64_RGBW@v0.3.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  // <Beam Position ... {0,0,1,-0.134}> under Body, no Axis: lens 0.134 m below the origin.
  EXPECT_NEAR(p.lensOffset.x, 0.0f, 1e-6);
  EXPECT_NEAR(p.lensOffset.y, -0.134f, 1e-6);
  EXPECT_NEAR(p.lensOffset.z, 0.0f, 1e-6);
  EXPECT_EQ(p.colorMixing, ColorMixing::Rgb);
  const auto& ch = p.modes.at(0).channels;
  ASSERT_EQ(ch.size(), 5u);
  const DmxAttribute want[] = {DmxAttribute::Intensity, DmxAttribute::Red, DmxAttribute::Green, DmxAttribute::Blue,
                               DmxAttribute::White};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(ch[static_cast<std::size_t>(i)].attribute, want[i]) << i;
  // Wash with BeamAngle 60 < FieldAngle 90: the file's angles are kept (50 % at 30 degrees).
  EXPECT_NEAR(p.distribution->intensityCd(static_cast<float>(30.0 * M_PI / 180.0), 0.0f),
              0.5 * p.distribution->peakCd(), 0.002 * p.distribution->peakCd());
}

TEST(GdtfFiles, BmflSpotModesWheelsAndRanges) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  auto g = loadGdtf(gdtfFile("Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  // Yoke at z -0.105, Head at -0.389 below it, Beam -0.319 below the head.
  EXPECT_NEAR(p.lensOffset.y, -0.319f, 1e-5);
  EXPECT_NEAR(g->pivotOffsetM.y, -0.494f, 1e-5);
  EXPECT_FLOAT_EQ(p.panDeg.min, -270.0f);
  EXPECT_FLOAT_EQ(p.panDeg.max, 270.0f);
  EXPECT_FLOAT_EQ(p.zoomDeg.min, 5.0f);   // Zoom PhysicalFrom 55 .. PhysicalTo 5
  EXPECT_FLOAT_EQ(p.zoomDeg.max, 55.0f);
  EXPECT_EQ(p.colorMixing, ColorMixing::Cmy);
  const DmxMode& m1 = p.modes.at(0);
  EXPECT_EQ(m1.channels[0].attribute, DmxAttribute::Pan);  // Offset "1,2"
  EXPECT_EQ(m1.channels[1].attribute, DmxAttribute::Pan);
  EXPECT_EQ(m1.channels[1].byte, 1);
  EXPECT_EQ(m1.channels[39].attribute, DmxAttribute::Intensity);  // Dimmer "40,41"
  EXPECT_EQ(m1.channels[39].bytes, 2);
  // Gobo1 at slot 23: "Gobo 1" from DMX 5 picks WheelSlotIndex 2, the wheel's second slot.
  const DmxChannel& gobo = m1.channels[22];
  ASSERT_EQ(gobo.attribute, DmxAttribute::Gobo);
  ASSERT_GE(p.goboWheels.size(), 2u);
  EXPECT_EQ(p.goboWheels[0].name, "Gobo1");
  EXPECT_EQ(p.goboWheels[1].name, "Gobo2");
  ASSERT_FALSE(gobo.slotRanges.empty());
  EXPECT_EQ(gobo.slotRanges[0].from, 0);
  EXPECT_EQ(gobo.slotRanges[0].to, 4);
  EXPECT_EQ(gobo.slotRanges[0].slot, 0);
  EXPECT_EQ(gobo.slotRanges[1].from, 5);
  EXPECT_EQ(p.goboWheels[0].slots[static_cast<std::size_t>(gobo.slotRanges[1].slot)].name, "G01 (New Raylines)");
  // The mode 2 channel uses the attribute Gobo1WheelIndex on the same wheel.
  const DmxChannel& gobo2 = p.modes.at(1).channels[20];
  EXPECT_EQ(gobo2.attribute, DmxAttribute::Gobo);
  EXPECT_EQ(gobo2.slotRanges.at(1).slot, 1);
  // Colour wheel Color1: "C01 (Deep Red)" at CIE (0.5985, 0.3377) is a red filter.
  ASSERT_GE(p.colorWheels.size(), 1u);
  EXPECT_EQ(p.colorWheels[0].name, "Color1");
  const WheelSlot& red = p.colorWheels[0].slots.at(1);
  EXPECT_EQ(red.name, "C01 (Deep Red)");
  ASSERT_TRUE(red.color);
  EXPECT_FLOAT_EQ(red.color->r, 1.0f);
  EXPECT_LT(red.color->g, 0.2f);
  EXPECT_LT(red.color->b, 0.2f);
  EXPECT_EQ(m1.channels[6].attribute, DmxAttribute::ColorWheel);
  // Focus1 is read (gdtf_optics_test.cpp, GdtfFocus), so it is not among the attributes listed
  // as read past; the shutter is read too.
  int focusWarnings = 0;
  for (const auto& w : g->warnings) focusWarnings += w.find("'Focus1' is not used") != std::string::npos;
  EXPECT_EQ(focusWarnings, 0);
  EXPECT_TRUE(p.hasGateFocus);
  EXPECT_EQ(m1.channels[38].attribute, DmxAttribute::Shutter);  // Shutter1 at offset 39
}

TEST(GdtfFiles, ClayPakyCountsWheelSlotsFromZeroAndFindsFolderedMedia) {
  HAZE_NEED_DATA("gdtf/Clay Paky@Alpha Spot QWO 800@allWorking.gdtf");
  auto g = loadGdtf(gdtfFile("Clay Paky@Alpha Spot QWO 800@allWorking.gdtf"));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  const DmxChannel& gobo = p.modes.at(0).channels[10];  // Offset 11
  ASSERT_EQ(gobo.attribute, DmxAttribute::Gobo);
  // <ChannelSet DMXFrom="8/1" Name="Gobo 1" WheelSlotIndex="1"/>; the wheel is Open, Gobo1, ...
  auto it = std::find_if(gobo.slotRanges.begin(), gobo.slotRanges.end(), [](const DmxSlotRange& r) { return r.from == 8; });
  ASSERT_NE(it, gobo.slotRanges.end());
  EXPECT_EQ(it->to, 15);
  const WheelSlot& slot = p.goboWheels.at(0).slots.at(static_cast<std::size_t>(it->slot));
  EXPECT_EQ(slot.name, "Gobo1");
  // MediaFileName "Clay Paky/00591401" is stored as wheels/00591401.png.
  EXPECT_EQ(slot.imagePath, "wheels/00591401.png");
  ASSERT_TRUE(slot.image);
  EXPECT_EQ(slot.image->width, 128);
}

// The gobo in the profile is the archive's PNG: byte-identical to the copy in shared data, and
// its transmittance follows Annex E pixel by pixel (checked on the copy, decoded here).
void expectGoboMatches(const std::string& gdtf, std::size_t wheel, std::size_t slot, const char* member,
                       const char* copy) {
  auto g = loadGdtf(gdtfFile(gdtf));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const WheelSlot& s = g->profile->goboWheels.at(wheel).slots.at(slot);
  EXPECT_EQ(s.imagePath, member);
  ASSERT_TRUE(s.image);
  const std::string archived = unzipMember(gdtfFile(gdtf), member);
  const std::string shared = test::readFile(test::dataFile(std::string("gobos/gdtf-wheels/") + copy));
  ASSERT_FALSE(shared.empty());
  EXPECT_EQ(archived, shared);
  auto fromCopy = goboFromImageBytes({reinterpret_cast<const std::uint8_t*>(shared.data()), shared.size()}, copy, copy);
  ASSERT_TRUE(fromCopy.ok()) << fromCopy.error().str();
  EXPECT_EQ((*fromCopy)->width, s.image->width);
  EXPECT_EQ((*fromCopy)->height, s.image->height);
  EXPECT_EQ((*fromCopy)->transmittance, s.image->transmittance);
  // Both opaque and clear parts exist in a real gobo.
  auto [lo, hi] = std::minmax_element(s.image->transmittance.begin(), s.image->transmittance.end());
  EXPECT_LT(*lo, 0.01f);
  EXPECT_GT(*hi, 0.9f);
}

TEST(GdtfFiles, BmflGoboMatchesTheSharedCopy) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  HAZE_NEED_DATA("gobos/gdtf-wheels/BMFL_15020296_DotBreakup.png");
  expectGoboMatches("Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf", 1, 1,
                    "wheels/15020296.png", "BMFL_15020296_DotBreakup.png");
  expectGoboMatches("Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf", 0, 6,
                    "wheels/15020295.png", "BMFL_15020295_LeafBreakup.png");
}

TEST(GdtfFiles, BeskydGoboMatchesTheSharedCopy) {
  HAZE_NEED_DATA("gdtf/BlenderDMX@BeskydBeam@version10.gdtf");
  HAZE_NEED_DATA("gobos/gdtf-wheels/BeskydBeam_image_0001.png");
  expectGoboMatches("BlenderDMX@BeskydBeam@version10.gdtf", 0, 1, "wheels/image_0001.png", "BeskydBeam_image_0001.png");
  expectGoboMatches("BlenderDMX@BeskydBeam@version10.gdtf", 0, 5, "wheels/image_0005.png", "BeskydBeam_image_0005.png");
}

}  // namespace
}  // namespace haze
