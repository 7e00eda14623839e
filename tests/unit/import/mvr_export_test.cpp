// MVR export: a show built here and the shared MVR scenes go out and come back in through the
// import; the XML is checked against mvr.xsd's rules by reading it here (root attributes,
// required children, the matrix pattern, the ChildList order), and the placement against a
// worked example computed by hand (docs/mvr.md).
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtx/euler_angles.hpp>
#include <pugixml.hpp>

#include "fixtures/core/zip_archive.h"
#include "fixtures/facts.h"
#include "fixtures/gdtf.h"
#include "fixtures/pose.h"
#include "shows/scene/venue.h"
#include "shows/import/mvr_export.h"
#include "shows/import/mvr_import.h"
#include "shows/show.h"
#include "shows/show_save.h"
#include "unit/gdtf/zip_builder.h"

namespace haze {
namespace {

const std::filesystem::path kMvrDir = std::filesystem::path(HAZE_SHARED_DATA) / "gdtf" / "mvr";

std::string fileText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

glm::mat3 rotationOf(const glm::vec3& deg) {
  return glm::mat3(glm::eulerAngleZYX(glm::radians(deg.z), glm::radians(deg.y), glm::radians(deg.x)));
}

float maxDiff(const glm::mat3& a, const glm::mat3& b) {
  float d = 0.0f;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d;
}

std::string sceneXml(const std::filesystem::path& mvr) {
  auto zip = ZipArchive::open(mvr);
  EXPECT_TRUE(zip.ok()) << (zip.ok() ? "" : zip.error().str());
  if (!zip.ok()) return "";
  auto bytes = zip->read("GeneralSceneDescription.xml");
  EXPECT_TRUE(bytes.ok());
  return bytes.ok() ? std::string(bytes->begin(), bytes->end()) : "";
}

// mvr.xsd's rules for what haze writes, checked on the parsed XML.
// strict: everything haze wrote itself; over a source MVR (an older version, other writers'
// elements) only what haze adds or changes is checked.
void checkStructure(const std::string& xml, std::size_t expectedFixtures, bool strict = true) {
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str())) << "not well-formed";
  const pugi::xml_node root = doc.document_element();
  EXPECT_STREQ(root.name(), "GeneralSceneDescription");
  EXPECT_STREQ(root.attribute("verMajor").value(), "1");
  if (strict) {
    EXPECT_STREQ(root.attribute("verMinor").value(), "6");
  }
  EXPECT_STREQ(root.attribute("provider").value(), "haze");
  EXPECT_FALSE(root.attribute("providerVersion").empty());
  ASSERT_TRUE(root.child("Scene").child("Layers"));
  const std::regex matrixPattern(R"((\{-?[0-9]+\.?[0-9]*(,-?[0-9]+\.?[0-9]*){2}\}){4})");
  const std::regex guid(R"([0-9a-fA-F]{8}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{12})");
  std::set<std::string> uuids;
  std::size_t fixtures = 0;
  const std::map<std::string, int> rank = {{"SceneObject", 0}, {"GroupObject", 1}, {"FocusPoint", 2}, {"Fixture", 3},
                                           {"Support", 4},     {"Truss", 5},       {"VideoScreen", 6}, {"Projector", 7}};
  // (The writers of the shared files do not keep this order themselves, nor does a Symdef's ChildList.)
  for (pugi::xpath_node n : doc.select_nodes(strict ? "//ChildList" : "/nothing")) {
    int last = -1;
    for (pugi::xml_node c : n.node().children()) {
      if (c.type() != pugi::node_element) continue;
      ASSERT_TRUE(rank.count(c.name())) << c.name();
      EXPECT_GE(rank.at(c.name()), last) << "<" << c.name() << "> after a later kind: mvr.xsd's ChildList is a sequence";
      last = rank.at(c.name());
    }
  }
  for (pugi::xpath_node n : doc.select_nodes("//Layer | //GroupObject | //FocusPoint | //Fixture")) {
    const pugi::xml_node e = n.node();
    EXPECT_TRUE(std::regex_match(e.attribute("uuid").value(), guid)) << e.name() << " " << e.attribute("uuid").value();
    EXPECT_TRUE(uuids.insert(e.attribute("uuid").value()).second) << "uuid used twice: " << e.attribute("uuid").value();
    // Capture writes exponents ("8.53590478e-08"), which the export keeps where it keeps the Matrix.
    if (pugi::xml_node m = e.child("Matrix"); m && strict) {
      EXPECT_TRUE(std::regex_match(m.text().as_string(), matrixPattern)) << m.text().as_string();
    }
    if (std::string(e.name()) == "Fixture") {
      ++fixtures;
      if (!strict) continue;
      for (const char* required : {"FixtureID", "FixtureIDNumeric", "UnitNumber", "ChildList"})
        EXPECT_TRUE(e.child(required)) << "Fixture lacks <" << required << ">";
      for (pugi::xml_node a : e.child("Addresses").children("Address"))
        EXPECT_TRUE(std::regex_match(a.text().as_string(), std::regex("[0-9]+"))) << a.text().as_string();
    }
    if (std::string(e.name()) == "Layer" || std::string(e.name()) == "GroupObject") {
      EXPECT_TRUE(e.child("ChildList"));
    }
    if (std::string(e.name()) == "FocusPoint") {
      EXPECT_TRUE(e.child("Geometries"));
    }
  }
  EXPECT_EQ(fixtures, expectedFixtures);
}

// Fixtures of `a` and `b` in the same order, the same in everything MVR carries.
void expectSameRig(const Show& a, const Show& b) {
  ASSERT_EQ(a.fixtures.size(), b.fixtures.size());
  for (std::size_t i = 0; i < a.fixtures.size(); ++i) {
    const FixtureDef& x = a.fixtures[i];
    const FixtureDef& y = b.fixtures[i];
    SCOPED_TRACE("fixture " + std::to_string(x.id) + " \"" + x.name + "\"");
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.mvrUuid, y.mvrUuid);
    EXPECT_EQ(x.mode, y.mode);
    ASSERT_EQ(x.patch.has_value(), y.patch.has_value());
    if (x.patch) {
      EXPECT_EQ(x.patch->universe, y.patch->universe);
      EXPECT_EQ(x.patch->address, y.patch->address);
    }
    EXPECT_LT(glm::length(x.position - y.position), 1e-4f + 2e-6f)
        << x.position.x << " " << x.position.y << " " << x.position.z << " came back as " << y.position.x << " " << y.position.y << " "
        << y.position.z;
    EXPECT_LT(maxDiff(rotationOf(x.rotationDeg), rotationOf(y.rotationDeg)), 1e-4f);
  }
}

// The beam direction of each fixture the cue list "MVR focus" aims, by fixture id.
std::map<int, glm::vec3> focusBeams(const Show& show) {
  std::map<int, glm::vec3> out;
  const CueList* list = show.findCueList("MVR focus");
  if (list == nullptr || list->cues.empty()) return out;
  for (const auto& [id, v] : list->cues[0].values) {
    if (!v.panDeg || !v.tiltDeg) continue;
    const FixtureDef* f = show.findFixture(id);
    if (f) out[id] = headRotation(f->rotationDeg, *v.panDeg, *v.tiltDeg) * glm::vec3(0, -1, 0);
  }
  return out;
}

void expectSameFocus(const Show& a, const Show& b, std::size_t expected) {
  const auto fa = focusBeams(a), fb = focusBeams(b);
  EXPECT_EQ(fa.size(), expected);
  ASSERT_EQ(fa.size(), fb.size());
  for (const auto& [id, beam] : fa) {
    ASSERT_TRUE(fb.count(id)) << id;
    // Pan and tilt are stored to 0.01 degree (1.7e-4 rad).
    EXPECT_LT(glm::length(beam - fb.at(id)), 1e-3f) << "fixture " << id;
  }
}

// --- the placement --------------------------------------------------------------------------

// docs/mvr.md's worked example backwards: the first pendant of scene_objects.mvr.
TEST(MvrExportMatrix, WorkedExampleByHand) {
  const glm::dmat4 m = hazeToMvrMatrix({-14.1986f, 7.8169f, -7.1891f}, {0.0f, -90.0f, 0.0f}, {0.0f, -0.2095f, 0.0f});
  const double expected[4][3] = {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}, {-14198.6, 7189.1, 8026.4}};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(m[c][r], expected[c][r], c == 3 ? 0.01 : 1e-6) << c << "," << r;
  // Fixed notation: the axes to 1e-9, the origin to 1e-4 mm; no "-0".
  const std::string text = formatMvrMatrix(m);
  EXPECT_EQ(text.rfind("{0.000000000,-1.000000000,0.000000000}{1.000000000,0.000000000,0.000000000}"
                       "{0.000000000,0.000000000,1.000000000}{-14198.",
                       0),
            0u)
      << text;
  EXPECT_TRUE(std::regex_match(text, std::regex(R"((\{[^}]*\}){3}\{-14198\.[0-9]{4},7189\.[0-9]{4},8026\.[0-9]{4}\})"))) << text;
}

// Every orientation, gimbal lock and upside down included, reads back through the import's
// conversion as the same rotation and position.
TEST(MvrExportMatrix, ImportReadsBackWhatExportWrites) {
  const glm::vec3 pivot(0.01f, -0.4f, 0.03f);
  for (const glm::vec3 rot : {glm::vec3(0.0f), glm::vec3(0, -90, 0), glm::vec3(0, 90, 0), glm::vec3(180, 0, 0),
                              glm::vec3(12.5f, -33.0f, 171.25f), glm::vec3(-90, 0, 45), glm::vec3(0, 0, -179.9f)}) {
    const glm::vec3 pos(3.25f, 7.5f, -12.125f);
    auto parsed = parseMvrMatrix(formatMvrMatrix(hazeToMvrMatrix(pos, rot, pivot)));
    ASSERT_TRUE(parsed.ok());
    const glm::dmat3 r(*parsed);
    const glm::vec3 back = mvrRotationToHazeDeg(r);
    EXPECT_LT(maxDiff(rotationOf(rot), rotationOf(back)), 1e-5f) << rot.x << " " << rot.y << " " << rot.z;
    const glm::vec3 p = mvrPointToHazeM(glm::dvec3((*parsed)[3])) + rotationOf(back) * pivot;
    EXPECT_LT(glm::length(p - pos), 1e-5f);
  }
}

TEST(MvrExportUuid, AssignedOnceAndCopiesGetTheirOwn) {
  Show show;
  show.fixtures.resize(3);
  show.fixtures[0].mvrUuid = "2E149740-6A41-BC43-BD59-8968781B11B9";
  show.fixtures[2].mvrUuid = "2e149740-6a41-bc43-bd59-8968781b11b9";  // a copy of the first (case aside)
  EXPECT_EQ(assignMvrUuids(show), 2);
  EXPECT_EQ(show.fixtures[0].mvrUuid, "2E149740-6A41-BC43-BD59-8968781B11B9");
  EXPECT_TRUE(isMvrUuid(show.fixtures[1].mvrUuid));
  EXPECT_NE(show.fixtures[2].mvrUuid, show.fixtures[0].mvrUuid);
  EXPECT_NE(show.fixtures[2].mvrUuid, show.fixtures[1].mvrUuid);
  const std::vector<FixtureDef> before = show.fixtures;
  EXPECT_EQ(assignMvrUuids(show), 0);
  for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(show.fixtures[i].mvrUuid, before[i].mvrUuid);
}

// --- a show built here ------------------------------------------------------------------------

struct SmallShow {
  test::TempDir dir{"mvr-export"};
  Show show;
  std::string gdtfBytes;
  SmallShow() {
    const std::string xml = fileText(std::filesystem::path(HAZE_SOURCE_DIR) / "tests/data/gdtf/hex1_wash.xml");
    EXPECT_FALSE(xml.empty());
    EXPECT_TRUE(test::writeZip(dir / "hex1.gdtf", {{"description.xml", xml}}));
    gdtfBytes = fileText(dir / "hex1.gdtf");
    show.profiles["hex"] = ProfileRef{"hex1.gdtf", std::nullopt, false};
    auto add = [&](int id, const std::string& name, glm::vec3 pos, glm::vec3 rot, std::optional<Patch> patch) {
      FixtureDef f;
      f.id = id;
      f.name = name;
      f.profile = "hex";
      f.mode = "Single";
      f.position = pos;
      f.rotationDeg = rot;
      f.patch = patch;
      show.fixtures.push_back(f);
    };
    add(1, "SL <1> & \"front\"", {-4.0f, 8.0f, -2.5f}, {0, 0, 0}, Patch{1, 1});
    add(2, "SR 1", {4.0f, 8.0f, -2.5f}, {0, -90, 0}, Patch{3, 500});
    add(7, "Boom", {-6.0f, 1.2f, 1.0f}, {12.5f, -33.0f, 171.25f}, std::nullopt);
    add(9, "Floor", {0.5f, 0.3f, 3.0f}, {180, 0, 0}, Patch{64, 512});
    show.groups = {GroupDef{"Left", {1, 7}}, GroupDef{"Right", {2}}, GroupDef{"Both", {1, 2}}};
    Cue focus;
    focus.number = "1";
    focus.values[1].panDeg = 30.0f;
    focus.values[1].tiltDeg = 40.0f;
    focus.values[2].panDeg = -20.0f;
    focus.values[2].tiltDeg = 10.0f;
    show.cueLists.push_back(CueList{"MVR focus", {focus}});
    SaveOptions save;
    save.force = true;
    EXPECT_TRUE(saveShow(show, dir / "small.haze.json", save).ok());
  }
};

TEST(MvrExport, SmallShowRoundTrip) {
  SmallShow s;
  auto out = exportMvr(s.show, s.dir / "rig.mvr");
  ASSERT_TRUE(out.ok()) << out.error().str();
  EXPECT_EQ(out->fixtureCount, 4);
  EXPECT_EQ(out->uuidsMade, 4);
  EXPECT_EQ(out->gdtfFiles, 1);
  EXPECT_EQ(out->focusPoints, 2);
  EXPECT_EQ(out->groupObjects, 2);  // "Both" holds only fixtures already in "Left" and "Right"
  bool twoGroupsWarned = false;
  for (const auto& w : out->warnings) twoGroupsWarned |= w.find("more than one group") != std::string::npos;
  EXPECT_TRUE(twoGroupsWarned);

  const std::string xml = sceneXml(s.dir / "rig.mvr");
  checkStructure(xml, 4);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str()));
  // Fixture 2 patched at universe 3 address 500: absolute (3 - 1) * 512 + 500.
  pugi::xml_node sr = doc.select_node("//Fixture[FixtureID='2']").node();
  ASSERT_TRUE(sr);
  EXPECT_STREQ(sr.child("Addresses").child("Address").text().as_string(), "1524");
  EXPECT_STREQ(sr.child("GDTFSpec").text().as_string(), "hex1.gdtf");
  EXPECT_STREQ(sr.child("GDTFMode").text().as_string(), "Single");
  EXPECT_STREQ(sr.attribute("uuid").value(), s.show.fixtures[1].mvrUuid.c_str());
  EXPECT_TRUE(doc.select_node("//GroupObject[@name='Right']/ChildList/Fixture[FixtureID='2']"));
  EXPECT_FALSE(doc.select_node("//Fixture[FixtureID='7']/Addresses"));  // unpatched
  // The focus names a FocusPoint of the file.
  const std::string focusUuid = doc.select_node("//Fixture[FixtureID='1']/Focus").node().text().as_string();
  EXPECT_TRUE(doc.select_node(("//FocusPoint[@uuid='" + focusUuid + "']").c_str())) << focusUuid;
  // The GDTF is embedded as it is.
  auto zip = ZipArchive::open(s.dir / "rig.mvr");
  ASSERT_TRUE(zip.ok());
  auto gdtf = zip->read("hex1.gdtf");
  ASSERT_TRUE(gdtf.ok());
  EXPECT_EQ(std::string(gdtf->begin(), gdtf->end()), s.gdtfBytes);

  auto back = importMvr(s.dir / "rig.mvr", s.dir / "back.haze.json");
  ASSERT_TRUE(back.ok()) << back.error().str();
  // The import lists grouped fixtures where their group is; compare by id.
  Show sorted = back->show;
  std::sort(sorted.fixtures.begin(), sorted.fixtures.end(), [](const FixtureDef& a, const FixtureDef& b) { return a.id < b.id; });
  expectSameRig(s.show, sorted);
  expectSameFocus(s.show, back->show, 2);
  // The GroupObjects read back as the groups: "Left" and "Right" as the show has them; "Both",
  // written nowhere (its fixtures sit in earlier groups), is not there.
  ASSERT_EQ(back->show.groups.size(), 2u);
  EXPECT_EQ(back->show.groups[0], (GroupDef{"Left", {1, 7}}));
  EXPECT_EQ(back->show.groups[1], (GroupDef{"Right", {2}}));
  // And a second export, from the show alone, writes the same GroupObjects again.
  MvrExportOptions alone;
  alone.overSource = false;
  auto again = exportMvr(back->show, s.dir / "again.mvr", alone);
  ASSERT_TRUE(again.ok()) << again.error().str();
  EXPECT_EQ(again->groupObjects, 2);
}

TEST(MvrExport, ExportingTwiceGivesTheSameFile) {
  SmallShow s;
  ASSERT_TRUE(exportMvr(s.show, s.dir / "a.mvr").ok());
  const std::vector<FixtureDef> first = s.show.fixtures;
  auto again = exportMvr(s.show, s.dir / "b.mvr");
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->uuidsMade, 0);
  for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(s.show.fixtures[i].mvrUuid, first[i].mvrUuid);
  EXPECT_EQ(fileText(s.dir / "a.mvr"), fileText(s.dir / "b.mvr"));
  // The uuids survive the show file.
  SaveOptions save;
  save.force = true;
  ASSERT_TRUE(saveShow(s.show, s.dir / "small.haze.json", save).ok());
  auto loaded = loadShow(s.dir / "small.haze.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().str();
  EXPECT_EQ(assignMvrUuids(*loaded), 0);
  for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(loaded->fixtures[i].mvrUuid, first[i].mvrUuid);
}

TEST(MvrExport, ErrorsNameTheFile) {
  SmallShow s;
  ASSERT_TRUE(exportMvr(s.show, s.dir / "rig.mvr").ok());
  auto exists = exportMvr(s.show, s.dir / "rig.mvr");
  ASSERT_FALSE(exists.ok());
  EXPECT_NE(exists.error().str().find("rig.mvr"), std::string::npos) << exists.error().str();
  MvrExportOptions force;
  force.force = true;
  EXPECT_TRUE(exportMvr(s.show, s.dir / "rig.mvr", force).ok());
  auto noDir = exportMvr(s.show, s.dir / "missing" / "rig.mvr");
  ASSERT_FALSE(noDir.ok());
  EXPECT_NE(noDir.error().str().find("missing/rig.mvr"), std::string::npos) << noDir.error().str();
  EXPECT_EQ(noDir.error().str().find('\n'), std::string::npos);
  std::filesystem::remove(s.dir / "hex1.gdtf");
  auto noGdtf = exportMvr(s.show, s.dir / "other.mvr");
  ASSERT_FALSE(noGdtf.ok());
  EXPECT_NE(noGdtf.error().str().find("hex1.gdtf"), std::string::npos) << noGdtf.error().str();
  EXPECT_FALSE(std::filesystem::exists(s.dir / "other.mvr"));
}

TEST(MvrShowFormat, UuidIsReadWrittenAndChecked) {
  test::TempDir dir("mvr-uuid");
  const std::string good = R"({"format": "haze-show", "version": 2, "profiles": {"p": "p.json"},
    "fixtures": [{"id": 1, "profile": "p", "uuid": "2e149740-6a41-bc43-bd59-8968781b11b9"}]})";
  std::ofstream(dir / "good.haze.json") << good;
  auto show = loadShow(dir / "good.haze.json");
  ASSERT_TRUE(show.ok()) << show.error().str();
  EXPECT_EQ(show->fixtures[0].mvrUuid, "2e149740-6a41-bc43-bd59-8968781b11b9");
  std::ofstream(dir / "bad.haze.json") << R"({"format": "haze-show", "version": 2, "profiles": {"p": "p.json"},
    "fixtures": [{"id": 1, "profile": "p", "uuid": "not-a-uuid"}]})";
  auto bad = loadShow(dir / "bad.haze.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().str().find("/fixtures/0/uuid"), std::string::npos) << bad.error().str();
}

// --- profiles that are not GDTF files -----------------------------------------------------------

// The demo's native profiles go out as GDTFs written by haze, and the rig comes back: the same
// fixtures, patch and modes, placed where they were (their GDTF origin is the pivot).
// A QLC+ definition written for this test whose 16-bit mode lists Pan, Tilt, Pan fine, Tilt fine
// (the fine bytes do not follow their coarse ones, as in many real definitions).
constexpr const char* kSplitFineQxf = R"(<?xml version="1.0" encoding="UTF-8"?>
<FixtureDefinition xmlns="http://www.qlcplus.org/FixtureDefinition">
 <Creator><Name>haze tests</Name><Version>1</Version><Author>haze</Author></Creator>
 <Manufacturer>Test</Manufacturer>
 <Model>Split Fine Spot</Model>
 <Type>Moving Head</Type>
 <Channel Name="Pan" Preset="PositionPan"/>
 <Channel Name="Pan fine" Preset="PositionPanFine"/>
 <Channel Name="Tilt" Preset="PositionTilt"/>
 <Channel Name="Tilt fine" Preset="PositionTiltFine"/>
 <Channel Name="Dimmer" Preset="IntensityDimmer"/>
 <Channel Name="Colour">
  <Group Byte="0">Colour</Group>
  <Capability Min="0" Max="127" Preset="ColorMacro" Res1="#ffffff">White</Capability>
  <Capability Min="128" Max="255" Preset="ColorMacro" Res1="#ff0000">Red</Capability>
 </Channel>
 <Mode Name="16 bit">
  <Channel Number="0">Pan</Channel>
  <Channel Number="1">Tilt</Channel>
  <Channel Number="2">Pan fine</Channel>
  <Channel Number="3">Tilt fine</Channel>
  <Channel Number="4">Dimmer</Channel>
  <Channel Number="5">Colour</Channel>
 </Mode>
 <Physical>
  <Bulb Type="LED" Lumens="8000" ColourTemperature="6500"/>
  <Dimensions Weight="18" Width="300" Height="450" Depth="250"/>
  <Lens Name="PC" DegreesMin="15" DegreesMax="15"/>
  <Focus Type="Head" PanMax="540" TiltMax="270"/>
  <Technical PowerConsumption="300" DmxConnector="5-pin"/>
 </Physical>
</FixtureDefinition>
)";

// A show with a QLC+ profile and an IES file as a profile goes out as MVR (both written as GDTF)
// and comes back with the same fixtures, modes and patch; each GDTF reads back with the
// profile's channels in their slots (a 16-bit value's bytes where the mode puts them). The IES
// file is a bare lamp's (field angle over 200 degrees), so its Beam is the widest cone.
TEST(MvrExport, QlcAndIesProfilesRoundTrip) {
  auto demo = loadShow(std::filesystem::path(HAZE_SOURCE_DIR) / "examples/demo/demo.haze.json");
  ASSERT_TRUE(demo.ok()) << demo.error().str();
  test::TempDir dir("mvr-qlc-ies");
  std::ofstream(dir / "split-fine.qxf") << kSplitFineQxf;
  const std::filesystem::path ies =
      std::filesystem::path(HAZE_SOURCE_DIR) / "tests/data/shared/photometry/ies/hydraapi/ies_4.ies";
  Show show = *demo;
  show.profiles["split-fine"] = ProfileRef{.path = (dir / "split-fine.qxf").string()};
  show.profiles["ies-4"] = ProfileRef{.path = ies.string()};
  ASSERT_GE(show.fixtures.size(), 3u);
  show.fixtures[0].profile = "split-fine";
  show.fixtures[0].mode = "16 bit";
  show.fixtures[0].patch = Patch{9, 1};
  show.fixtures[1].profile = "split-fine";
  show.fixtures[1].mode = "16 bit";
  show.fixtures[1].patch = Patch{9, 7};
  show.fixtures[2].profile = "ies-4";
  show.fixtures[2].mode = "";
  show.fixtures[2].patch = Patch{9, 13};
  auto profiles = loadProfiles(show);
  ASSERT_TRUE(profiles.ok()) << profiles.error().str();
  show.fixtures[2].mode = profiles->at("ies-4")->modes.front().name;
  auto out = exportMvr(show, dir / "rig.mvr");
  ASSERT_TRUE(out.ok()) << out.error().str();
  auto back = importMvr(dir / "rig.mvr", dir / "back.haze.json", MvrImportOptions{.keepEmbedded = true});
  ASSERT_TRUE(back.ok()) << back.error().str();
  Show sorted = back->show;
  std::sort(sorted.fixtures.begin(), sorted.fixtures.end(), [](const FixtureDef& a, const FixtureDef& b) { return a.id < b.id; });
  Show expected = show;
  std::sort(expected.fixtures.begin(), expected.fixtures.end(), [](const FixtureDef& a, const FixtureDef& b) { return a.id < b.id; });
  for (FixtureDef& f : expected.fixtures)
    if (f.mode.empty()) f.mode = profiles->at(f.profile)->modes.front().name;
  expectSameRig(expected, sorted);
  for (const char* key : {"split-fine", "ies-4"}) {
    SCOPED_TRACE(key);
    const Profile& original = *profiles->at(key);
    ASSERT_TRUE(back->show.profiles.count(key)) << "no profile " << key << " came back";
    auto g = loadGdtf(back->show.resolve(back->show.profiles.at(key).path));
    ASSERT_TRUE(g.ok()) << g.error().str();
    ASSERT_EQ(g->profile->modes.size(), original.modes.size());
    for (std::size_t m = 0; m < original.modes.size(); ++m) {
      const DmxMode& a = original.modes[m];
      const DmxMode& b = g->profile->modes[m];
      ASSERT_EQ(b.footprint(), a.footprint()) << a.name;
      for (std::size_t c = 0; c < a.channels.size(); ++c) {
        EXPECT_EQ(b.channels[c].attribute, a.channels[c].attribute) << a.name << " slot " << c + 1;
        EXPECT_EQ(b.channels[c].byte, a.channels[c].byte) << a.name << " slot " << c + 1;
      }
    }
  }
  // The split mode as the test wrote it: pan coarse in slot 1, its fine byte in slot 3.
  const DmxMode& split = profiles->at("split-fine")->modes.front();
  EXPECT_EQ(split.channels[0].attribute, DmxAttribute::Pan);
  EXPECT_EQ(split.channels[2].attribute, DmxAttribute::Pan);
  EXPECT_EQ(split.channels[2].byte, 1);
}

TEST(MvrExport, DemoShowWithNativeProfilesRoundTrip) {
  auto demo = loadShow(std::filesystem::path(HAZE_SOURCE_DIR) / "examples/demo/demo.haze.json");
  ASSERT_TRUE(demo.ok()) << demo.error().str();
  auto profiles = loadProfiles(*demo);
  ASSERT_TRUE(profiles.ok()) << profiles.error().str();
  test::TempDir dir("mvr-demo");
  Show show = *demo;
  auto out = exportMvr(show, dir / "demo.mvr");
  ASSERT_TRUE(out.ok()) << out.error().str();
  EXPECT_EQ(out->gdtfWritten, static_cast<int>(demo->profiles.size()));
  int written = 0;
  for (const std::string& w : out->warnings) written += w.find("is written as the GDTF") != std::string::npos;
  EXPECT_EQ(written, static_cast<int>(demo->profiles.size()));
  checkStructure(sceneXml(dir / "demo.mvr"), demo->fixtures.size());
  // The venue goes in as one .glb: haze's glTF loader reads it as the same triangles where they were.
  EXPECT_TRUE(out->venueGlb);
  auto zip = ZipArchive::open(dir / "demo.mvr");
  ASSERT_TRUE(zip.ok());
  auto glb = zip->read("venue.glb");
  ASSERT_TRUE(glb.ok());
  auto packed = loadVenueFromMemory(*glb, "venue.glb");
  ASSERT_TRUE(packed.ok()) << packed.error().str();
  auto original = loadVenue(demo->resolve(demo->venueGltf));
  ASSERT_TRUE(original.ok());
  EXPECT_EQ(packed->triangleCount(), original->triangleCount());
  auto back = importMvr(dir / "demo.mvr", dir / "back.haze.json");
  ASSERT_TRUE(back.ok()) << back.error().str();
  EXPECT_EQ(back->geometryInstances, 1);
  EXPECT_EQ(back->venueTriangles, original->triangleCount());
  Show sorted = back->show;
  std::sort(sorted.fixtures.begin(), sorted.fixtures.end(), [](const FixtureDef& a, const FixtureDef& b) { return a.id < b.id; });
  Show expected = show;
  std::sort(expected.fixtures.begin(), expected.fixtures.end(), [](const FixtureDef& a, const FixtureDef& b) { return a.id < b.id; });
  for (FixtureDef& f : expected.fixtures)  // the demo leaves some modes to the profile's first
    if (f.mode.empty()) f.mode = profiles->at(f.profile)->modes.front().name;
  expectSameRig(expected, sorted);
  // Each written GDTF reads back as its profile: modes and their footprints, beam and field
  // angle, flux, pan and tilt ranges, the lens offset.
  for (const auto& [key, profile] : *profiles) {
    SCOPED_TRACE(key);
    auto g = loadGdtf(back->show.resolve(back->show.profiles.at(key).path));
    ASSERT_TRUE(g.ok()) << g.error().str();
    const Profile& p = *g->profile;
    ASSERT_EQ(p.modes.size(), profile->modes.size());
    for (std::size_t m = 0; m < p.modes.size(); ++m) {
      EXPECT_EQ(p.modes[m].name, profile->modes[m].name);
      EXPECT_EQ(p.modes[m].footprint(), profile->modes[m].footprint());
      for (std::size_t c = 0; c < p.modes[m].channels.size(); ++c) {
        if (profile->modes[m].channels[c].attribute != DmxAttribute::None) {
          EXPECT_EQ(p.modes[m].channels[c].attribute, profile->modes[m].channels[c].attribute) << p.modes[m].channels[c].name;
        }
      }
    }
    const BeamAngles a = beamAngles(*profile->distribution), b = beamAngles(*p.distribution);
    EXPECT_NEAR(b.fieldDeg(), a.fieldDeg(), 0.05 * a.fieldDeg());
    EXPECT_NEAR(b.beamDeg(), a.beamDeg(), 0.1 * a.beamDeg());
    EXPECT_NEAR(lumensOf(*p.distribution), lumensOf(*profile->distribution), 0.02 * lumensOf(*profile->distribution));
    EXPECT_NEAR(p.panDeg.min, profile->panDeg.min, 0.01);
    EXPECT_NEAR(p.tiltDeg.max, profile->tiltDeg.max, 0.01);
    EXPECT_LT(glm::length(p.lensOffset - profile->lensOffset), 1e-5f);
    EXPECT_EQ(g->pivotOffsetM, glm::vec3(0.0f));
  }
}

// --- the shared MVR scenes ---------------------------------------------------------------------

void roundTrip(const std::string& mvr, std::size_t fixtures, std::size_t focused, bool overSource) {
  if (!std::filesystem::exists(kMvrDir / mvr)) GTEST_SKIP() << "needs " << (kMvrDir / mvr).string() << " (the shared test data)";
  test::TempDir dir("mvr-roundtrip");
  // The MVR's own GDTF files, as the MVR carries them (stubs matched to the fixture library are
  // tests/cli/fixture_library.sh's): the round trip is of what the file holds.
  auto first = importMvr(kMvrDir / mvr, dir / "a.haze.json", MvrImportOptions{.keepEmbedded = true});
  ASSERT_TRUE(first.ok()) << first.error().str();
  auto a = loadShow(dir / "a.haze.json");
  ASSERT_TRUE(a.ok()) << a.error().str();
  ASSERT_EQ(a->fixtures.size(), fixtures);
  EXPECT_EQ(a->mvrSource, "a_source.mvr");
  for (const FixtureDef& f : a->fixtures) EXPECT_TRUE(isMvrUuid(f.mvrUuid)) << f.id;
  MvrExportOptions options;
  options.overSource = overSource;
  auto out = exportMvr(*a, dir / "out.mvr", options);
  ASSERT_TRUE(out.ok()) << out.error().str();
  EXPECT_EQ(out->uuidsMade, 0);  // the imported uuids are kept
  EXPECT_EQ(out->source.empty(), !overSource);
  if (overSource) {
    EXPECT_EQ(out->fixturesChanged, 0);  // nothing was moved: every Matrix stays as it was
    EXPECT_EQ(out->fixturesRemoved, 0);
  }
  checkStructure(sceneXml(dir / "out.mvr"), fixtures, !overSource);
  auto back = importMvr(dir / "out.mvr", dir / "b.haze.json", MvrImportOptions{.keepEmbedded = true});
  ASSERT_TRUE(back.ok()) << back.error().str();
  // The groups come back (Capture's GroupObjects); an export from the show alone lists grouped
  // fixtures inside their groups, so the fixtures are compared by id, not by order.
  EXPECT_EQ(back->show.groups.size(), a->groups.size());
  Show sortedA = *a, sortedB = back->show;
  for (Show* s : {&sortedA, &sortedB})
    std::sort(s->fixtures.begin(), s->fixtures.end(), [](const FixtureDef& x, const FixtureDef& y) { return x.id < y.id; });
  expectSameRig(sortedA, sortedB);
  expectSameFocus(*a, back->show, focused);
  // The same GDTF files come back, byte for byte.
  for (const auto& [key, ref] : a->profiles) {
    SCOPED_TRACE(key);
    ASSERT_TRUE(back->show.profiles.count(key));
    EXPECT_EQ(fileText(a->resolve(ref.path)), fileText(back->show.resolve(back->show.profiles.at(key).path)));
  }
}

TEST(MvrExportShared, BasicFixtureRoundTrip) { roundTrip("basic_fixture.mvr", 1, 0, false); }
TEST(MvrExportShared, SceneObjectsRoundTrip) { roundTrip("scene_objects.mvr", 72, 72, false); }
TEST(MvrExportShared, CaptureDemoShowRoundTrip) { roundTrip("capture_demo_show.mvr", 76, 0, false); }
TEST(MvrExportShared, BasicFixtureOverSourceRoundTrip) { roundTrip("basic_fixture.mvr", 1, 0, true); }
TEST(MvrExportShared, SceneObjectsOverSourceRoundTrip) { roundTrip("scene_objects.mvr", 72, 72, true); }
TEST(MvrExportShared, CaptureDemoShowOverSourceRoundTrip) { roundTrip("capture_demo_show.mvr", 76, 0, true); }

// Every element of `kind` by uuid, serialised as it is in the file.
std::map<std::string, std::string> elementsByUuid(const pugi::xml_document& doc, const std::string& kind) {
  std::map<std::string, std::string> out;
  for (pugi::xpath_node n : doc.select_nodes(("//" + kind).c_str())) {
    std::ostringstream text;
    n.node().print(text, "", pugi::format_raw);
    out[n.node().attribute("uuid").value()] = text.str();
  }
  return out;
}

// A Capture show imported, edited in haze (one fixture moved, one re-patched, one deleted, one
// added) and exported: its trusses, scene objects, groups, layers, classes and symbols are in the
// file as they were (compared as XML), every geometry file byte for byte, untouched fixtures
// keep their Matrix text; the import of the export sees the edits.
TEST(MvrExportShared, CaptureKeepsWhatHazeDoesNotUse) {
  const std::filesystem::path src = kMvrDir / "capture_demo_show.mvr";
  if (!std::filesystem::exists(src)) GTEST_SKIP() << "needs " << src.string() << " (the shared test data)";
  test::TempDir dir("mvr-keep");
  ASSERT_TRUE(importMvr(src, dir / "a.haze.json", MvrImportOptions{.keepEmbedded = true}).ok());
  auto show = loadShow(dir / "a.haze.json");
  ASSERT_TRUE(show.ok());
  Show& s = *show;
  ASSERT_EQ(s.fixtures.size(), 76u);
  const std::string movedUuid = s.fixtures[0].mvrUuid, repatchedUuid = s.fixtures[1].mvrUuid, deletedUuid = s.fixtures[2].mvrUuid,
                    untouchedUuid = s.fixtures[5].mvrUuid;
  s.fixtures[0].position.x += 1.0f;
  s.fixtures[0].rotationDeg.y += 10.0f;
  s.fixtures[1].patch = Patch{9, 101};
  FixtureDef added = s.fixtures[3];
  added.id = 999;
  added.name = "Added in haze";
  added.mvrUuid.clear();
  added.position.y -= 0.5f;
  s.fixtures.erase(s.fixtures.begin() + 2);
  s.fixtures.push_back(added);
  const Show edited = s;
  auto out = exportMvr(s, dir / "out.mvr");
  ASSERT_TRUE(out.ok()) << out.error().str();
  EXPECT_EQ(out->fixturesChanged, 1);
  EXPECT_EQ(out->fixturesRemoved, 1);
  EXPECT_EQ(out->uuidsMade, 1);

  pugi::xml_document before, after;
  ASSERT_TRUE(before.load_string(sceneXml(src).c_str(), pugi::parse_full | pugi::parse_ws_pcdata));
  ASSERT_TRUE(after.load_string(sceneXml(dir / "out.mvr").c_str(), pugi::parse_full | pugi::parse_ws_pcdata));
  for (const char* kind : {"Truss", "SceneObject", "FocusPoint", "Class", "Symdef", "Support", "VideoScreen", "Projector"}) {
    SCOPED_TRACE(kind);
    const auto a = elementsByUuid(before, kind), b = elementsByUuid(after, kind);
    EXPECT_EQ(a.size(), b.size());
    for (const auto& [uuid, text] : a) {
      auto it = b.find(uuid);
      ASSERT_NE(it, b.end()) << uuid;
      EXPECT_EQ(it->second, text) << uuid;
    }
  }
  EXPECT_EQ(before.select_nodes("//Truss").size(), 13u);
  EXPECT_EQ(before.select_nodes("//SceneObject").size(), 2078u);
  EXPECT_EQ(before.select_nodes("//GroupObject").size(), after.select_nodes("//GroupObject").size());
  EXPECT_EQ(before.select_nodes("//Layer").size() + 1, after.select_nodes("//Layer").size());  // + "haze" for the new fixture
  for (pugi::xpath_node layer : before.select_nodes("//Layer"))
    EXPECT_TRUE(after.select_node(("//Layer[@uuid='" + std::string(layer.node().attribute("uuid").value()) + "']").c_str()));
  EXPECT_EQ(after.select_nodes("//Fixture").size(), 76u);
  EXPECT_FALSE(after.select_node(("//Fixture[@uuid='" + deletedUuid + "']").c_str()));
  auto matrixOf = [](const pugi::xml_document& d, const std::string& uuid) {
    return std::string(d.select_node(("//Fixture[@uuid='" + uuid + "']/Matrix").c_str()).node().text().as_string());
  };
  EXPECT_EQ(matrixOf(before, untouchedUuid), matrixOf(after, untouchedUuid));
  EXPECT_NE(matrixOf(before, movedUuid), matrixOf(after, movedUuid));
  EXPECT_TRUE(std::regex_match(matrixOf(after, movedUuid), std::regex(R"((\{-?[0-9]+\.?[0-9]*(,-?[0-9]+\.?[0-9]*){2}\}){4})")))
      << matrixOf(after, movedUuid);
  // Every geometry file, byte for byte.
  auto za = ZipArchive::open(src), zb = ZipArchive::open(dir / "out.mvr");
  ASSERT_TRUE(za.ok() && zb.ok());
  int geometry = 0;
  for (const ZipEntry& e : za->entries()) {
    if (e.name == "GeneralSceneDescription.xml") continue;
    ASSERT_TRUE(zb->contains(e.name)) << e.name;
    auto x = za->read(e.name), y = zb->read(e.name);
    ASSERT_TRUE(x.ok() && y.ok()) << e.name;
    EXPECT_TRUE(*x == *y) << e.name;
    geometry += e.name.size() > 4 && e.name.substr(e.name.size() - 4) == ".3ds";
  }
  EXPECT_GT(geometry, 800);
  EXPECT_EQ(za->entries().size(), zb->entries().size());

  auto back = importMvr(dir / "out.mvr", dir / "b.haze.json", MvrImportOptions{.keepEmbedded = true});
  ASSERT_TRUE(back.ok()) << back.error().str();
  Show expected = edited;
  expected.fixtures.back().mvrUuid = s.fixtures.back().mvrUuid;  // made by the export
  // The import lists the fixtures in file order: the new layer comes last, as the new fixture does.
  expectSameRig(expected, back->show);
}

}  // namespace
}  // namespace haze
