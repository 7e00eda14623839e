// MVR import of the shared MVR scenes and of broken MVRs built here. The expected fixture
// counts, patch and positions are read from GeneralSceneDescription.xml by this test itself
// (pugixml, its own matrix composition and its own mm -> m, Z-up -> Y-up conversion), not by
// the importer's code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <glm/gtx/euler_angles.hpp>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "fixtures/gdtf.h"
#include "fixtures/core/zip_archive.h"
#include "shows/import/mvr_import.h"
#include "shows/show.h"
#include "shows/show_validate.h"
#include "test_data.h"
#include "unit/gdtf/zip_builder.h"
#include "unit/import/frame_place.h"

namespace haze {
namespace {

// The MVR file `name` of the test data (tests/test_data.h).
std::filesystem::path mvrFile(const std::string& name) { return test::dataFile("gdtf/mvr/" + name); }

// --- the test's own reading of the XML ---------------------------------------------------

struct Affine {  // rows of a 3x4 matrix: p' = A p + t, millimetres
  double a[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double t[3] = {0, 0, 0};
};

Affine parseAffine(const std::string& s) {
  Affine m;
  double v[12] = {};
  const int n = std::sscanf(s.c_str(), " {%lf,%lf,%lf}{%lf,%lf,%lf}{%lf,%lf,%lf}{%lf,%lf,%lf}", &v[0], &v[1], &v[2], &v[3],
                            &v[4], &v[5], &v[6], &v[7], &v[8], &v[9], &v[10], &v[11]);
  EXPECT_EQ(n, 12) << s;
  for (int axis = 0; axis < 3; ++axis)  // {u}{v}{w}: the local axes, i.e. the columns
    for (int row = 0; row < 3; ++row) m.a[row][axis] = v[axis * 3 + row];
  for (int row = 0; row < 3; ++row) m.t[row] = v[9 + row];
  return m;
}

Affine compose(const Affine& p, const Affine& c) {
  Affine r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      r.a[i][j] = 0;
      for (int k = 0; k < 3; ++k) r.a[i][j] += p.a[i][k] * c.a[k][j];
    }
    r.t[i] = p.t[i];
    for (int k = 0; k < 3; ++k) r.t[i] += p.a[i][k] * c.t[k];
  }
  return r;
}

struct XmlFixture {
  std::string name, spec, fixtureId, address;
  Affine world;
};

std::vector<XmlFixture> readFixtures(const pugi::xml_node& list, const Affine& parent) {
  std::vector<XmlFixture> out;
  for (pugi::xml_node n : list.children()) {
    Affine world = parent;
    if (pugi::xml_node m = n.child("Matrix")) world = compose(parent, parseAffine(m.text().as_string()));
    if (std::string(n.name()) == "Fixture") {
      XmlFixture f{n.attribute("name").value(), n.child("GDTFSpec").text().as_string(),
                   n.child("FixtureID").text().as_string(), n.child("Addresses").child("Address").text().as_string(), world};
      out.push_back(f);
    }
    auto sub = readFixtures(n.child("ChildList"), world);
    out.insert(out.end(), sub.begin(), sub.end());
  }
  return out;
}

std::string readXml(const std::string& mvr) {
  auto zip = ZipArchive::open(mvrFile(mvr));
  EXPECT_TRUE(zip.ok());
  auto bytes = zip->read("GeneralSceneDescription.xml");
  EXPECT_TRUE(bytes.ok());
  return std::string(bytes->begin(), bytes->end());
}

// haze metres from MVR millimetres, written out here: (x, y, z) -> (x, z, -y) / 1000.
glm::dvec3 toHaze(const double p[3]) { return glm::dvec3(p[0], p[2], -p[1]) / 1000.0; }

struct Imported {
  test::TempDir dir{"mvr"};
  std::filesystem::path show;
  Result<MvrImport> result = Error{};
  explicit Imported(const std::string& mvr, const std::string& showName = "rig.haze.json") {
    show = dir / showName;
    // The GDTF files as the MVR carries them (stubs matched to the fixture library are
    // tests/cli/fixture_library.sh's).
    result = importMvr(mvrFile(mvr), show, MvrImportOptions{.keepEmbedded = true});
  }
};

void checkAgainstXml(const std::string& mvr, std::size_t expectedFixtures) {
  Imported imp(mvr);
  ASSERT_TRUE(imp.result.ok()) << imp.result.error().str();
  const std::string xml = readXml(mvr);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str()));
  std::vector<XmlFixture> fromXml;
  for (pugi::xml_node layer : doc.child("GeneralSceneDescription").child("Scene").child("Layers").children("Layer")) {
    Affine world;
    if (pugi::xml_node m = layer.child("Matrix")) world = parseAffine(m.text().as_string());
    auto sub = readFixtures(layer.child("ChildList"), world);
    fromXml.insert(fromXml.end(), sub.begin(), sub.end());
  }
  ASSERT_EQ(fromXml.size(), expectedFixtures);
  const Show& show = imp.result->show;
  ASSERT_EQ(show.fixtures.size(), fromXml.size());
  EXPECT_EQ(imp.result->fixtureCount, static_cast<int>(fromXml.size()));

  std::map<std::string, glm::vec3> pivots;  // profile -> pivot offset, from the extracted GDTF
  for (std::size_t i = 0; i < fromXml.size(); ++i) {
    const XmlFixture& x = fromXml[i];
    const FixtureDef& f = show.fixtures[i];
    SCOPED_TRACE(mvr + " fixture " + std::to_string(i) + " \"" + x.name + "\"");
    // A name no other fixture has is kept. The bigger rigs name every fixture by its type: the
    // name gets the FixtureID (Capture), else the haze id (Vectorworks leaves FixtureID empty
    // and writes UnitNumber 0).
    const auto sameName = std::count_if(fromXml.begin(), fromXml.end(), [&](const XmlFixture& o) { return o.name == x.name; });
    if (sameName == 1) EXPECT_EQ(f.name, x.name);
    else EXPECT_EQ(f.name, x.name + " " + (x.fixtureId.empty() ? std::to_string(f.id) : x.fixtureId));
    // Patch: absolute 1-based addresses, 0 = unpatched.
    const long abs = std::strtol(x.address.c_str(), nullptr, 10);
    if (abs == 0) {
      EXPECT_FALSE(f.patch.has_value());
    } else {
      ASSERT_TRUE(f.patch.has_value());
      EXPECT_EQ(f.patch->universe, (abs - 1) / 512 + 1);
      EXPECT_EQ(f.patch->address, (abs - 1) % 512 + 1);
    }
    const long id = std::strtol(x.fixtureId.c_str(), nullptr, 10);
    if (id > 0) {
      EXPECT_EQ(f.id, id);
    }
    // Rotation: the beam (GDTF -Z, i.e. minus the matrix's third column) in haze axes.
    double w[3] = {x.world.a[0][2], x.world.a[1][2], x.world.a[2][2]};
    const double wl = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const glm::dvec3 beamExpected = -toHaze(w) * 1000.0 / wl;
    const glm::mat3 r = glm::mat3(glm::eulerAngleZYX(glm::radians(f.rotationDeg.z), glm::radians(f.rotationDeg.y),
                                                     glm::radians(f.rotationDeg.x)));
    const glm::dvec3 beam(r * glm::vec3(0, -1, 0));
    EXPECT_LT(glm::length(beam - beamExpected), 1e-3) << f.rotationDeg.x << " " << f.rotationDeg.y << " " << f.rotationDeg.z;
    // Position: the MVR origin in haze metres plus the GDTF pivot offset turned with the fixture.
    if (!pivots.count(f.profile)) {
      auto g = loadGdtf(show.resolve(show.profiles.at(f.profile).path));
      ASSERT_TRUE(g.ok()) << g.error().str();
      pivots[f.profile] = g->pivotOffsetM;
    }
    const glm::dvec3 expected = toHaze(x.world.t) + glm::dvec3(r * pivots[f.profile]);
    EXPECT_LT(glm::length(glm::dvec3(f.position) - expected), 2e-4)
        << "got " << f.position.x << " " << f.position.y << " " << f.position.z << ", expected " << expected.x << " "
        << expected.y << " " << expected.z;
  }

  // The written show loads and validates, with its profiles from the extracted GDTF files.
  auto loaded = loadShow(imp.show);
  ASSERT_TRUE(loaded.ok()) << loaded.error().str();
  EXPECT_EQ(loaded->fixtures.size(), fromXml.size());
  for (const Error& e : validateShowFile(imp.show)) ADD_FAILURE() << e.str();
}

TEST(MvrImport, BasicFixture) {
  checkAgainstXml("basic_fixture.mvr", 1);
  Imported imp("basic_fixture.mvr");
  ASSERT_TRUE(imp.result.ok());
  const FixtureDef& f = imp.result->show.fixtures.at(0);
  // Matrix origin (5000, 5000, 5000) mm, identity rotation: haze (5, 5, -5) plus the pivot.
  EXPECT_EQ(f.rotationDeg, glm::vec3(0.0f));
  EXPECT_FALSE(f.patch.has_value());  // Address 0
  EXPECT_EQ(f.id, 1);                 // FixtureID 0 is no id: the first free one
  EXPECT_TRUE(std::filesystem::exists(imp.dir / "rig_gdtf" / "LED PAR 64 RGBW.gdtf"));
  // No geometry in this scene: the venue is a floor at MVR z = 0, 10 m around the fixture
  // (MVR x = y = 5000 mm: haze x = 5, z = -5), and that is warned.
  ASSERT_EQ(imp.result->show.venueGltf, "rig_venue.gltf");
  std::ifstream in(imp.dir / "rig_venue.gltf");
  const auto gltf = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(gltf.is_discarded());
  ASSERT_EQ(gltf["nodes"].size(), 1u);
  const auto& acc = gltf["accessors"][0];
  EXPECT_EQ(acc["min"][1].get<double>(), 0.0);
  EXPECT_EQ(acc["max"][1].get<double>(), 0.0);
  EXPECT_LE(acc["min"][0].get<double>(), 5.0 - 9.5);
  EXPECT_GE(acc["max"][0].get<double>(), 5.0 + 9.5);
  EXPECT_LE(acc["min"][2].get<double>(), -5.0 - 9.5);
  EXPECT_GE(acc["max"][2].get<double>(), -5.0 + 9.5);
  bool floorWarned = false;
  for (const auto& w : imp.result->warnings) floorWarned |= w.find("places no geometry; the venue is a floor") != std::string::npos;
  EXPECT_TRUE(floorWarned);
  // The overview camera holds the fixture and where its beam (straight down, identity Matrix)
  // meets that floor, (5, 0, -5), in its picture, looking from the audience side (+Z).
  ASSERT_EQ(imp.result->show.cameras.size(), 1u);
  const CameraDef& cam = imp.result->show.cameras[0];
  for (const glm::vec3 p : {f.position, glm::vec3(5, 0, -5)}) {
    const glm::vec2 at = framePlace(cam, p);
    EXPECT_LE(std::abs(at.x), 1.0f) << p.y;
    EXPECT_LE(std::abs(at.y), 1.0f) << p.y;
  }
  EXPECT_GT(cam.position.z, -5.0f + 1.0f);
  // Unused MVR fields are warned with their XML place.
  bool castShadowWarned = false;
  for (const auto& w : imp.result->warnings)
    castShadowWarned |= w.find("GeneralSceneDescription.xml line 31 <CastShadow>") != std::string::npos;
  EXPECT_TRUE(castShadowWarned);
}

TEST(MvrImport, SceneObjectsTheatre) {
  checkAgainstXml("scene_objects.mvr", 72);
  Imported imp("scene_objects.mvr");
  ASSERT_TRUE(imp.result.ok());
  // 100 Geometry3D .glb files: 28 of the 28 scene objects (walls, ceiling, chandeliers) are
  // placed in the venue; the 72 of the focus points are drawing markers, left out and warned
  // (each would be a 0.46 m square in the middle of a beam, shadowing it).
  EXPECT_EQ(imp.result->geometryInstances, 28);
  ASSERT_EQ(imp.result->show.venueGltf, "rig_venue.gltf");
  std::ifstream in(imp.dir / "rig_venue.gltf");
  const auto gltf = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(gltf.is_discarded());
  EXPECT_EQ(gltf["nodes"].size(), 28u);
  int markersWarned = 0;
  for (const auto& w : imp.result->warnings) markersWarned += w.find("<FocusPoint name=") != std::string::npos && w.find("marker") != std::string::npos;
  EXPECT_EQ(markersWarned, 72);
  bool firstMarkerWarned = false;
  for (const auto& w : imp.result->warnings)
    firstMarkerWarned |= w.rfind("GeneralSceneDescription.xml line 1952 <FocusPoint name=\"A1\">: ", 0) == 0;
  EXPECT_TRUE(firstMarkerWarned);
  EXPECT_TRUE(std::filesystem::exists(imp.dir / "rig_venue.bin"));
  ASSERT_EQ(imp.result->show.cueLists.size(), 1u);
  const Cue& focus = imp.result->show.cueLists[0].cues.at(0);
  EXPECT_EQ(focus.values.size(), 72u);
  // Pendants hang straight down over their focus points (same x, y in the XML): tilt 0.
  for (const auto& [id, v] : focus.values) EXPECT_NEAR(*v.tiltDeg, 0.0f, 0.05f) << id;
}

TEST(MvrImport, CaptureDemoShow) {
  HAZE_NEED_DATA("gdtf/mvr/capture_demo_show.mvr");
  checkAgainstXml("capture_demo_show.mvr", 76);
  Imported imp("capture_demo_show.mvr");
  ASSERT_TRUE(imp.result.ok());
  // Trusses (13 Symbols of a symdef with one .3ds) and scene objects become venue geometry.
  EXPECT_GT(imp.result->geometryInstances, 2000);
  EXPECT_GT(imp.result->venueTriangles, 1000u);
}

// A 2.5 m truss piece (capture_demo_show's symdef "DT34/3-250", a .3ds in mm) comes out 2.5 m
// long in the venue: the .3ds unit and the node matrices' scale are right.
TEST(MvrImport, TrussSymbolIsTwoAndAHalfMetresLong) {
  HAZE_NEED_DATA("gdtf/mvr/capture_demo_show.mvr");
  Imported imp("capture_demo_show.mvr");
  ASSERT_TRUE(imp.result.ok());
  std::ifstream in(imp.dir / "rig_venue.gltf");
  const auto gltf = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(gltf.is_discarded());
  bool found = false;
  for (const auto& mesh : gltf["meshes"]) {
    if (mesh["name"] != "0x27B6408E.3ds") continue;
    const auto& acc = gltf["accessors"][mesh["primitives"][0]["attributes"]["POSITION"].get<int>()];
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, acc["max"][k].get<double>() - acc["min"][k].get<double>());
    EXPECT_NEAR(longest, 2500.0, 60.0);  // mm in the mesh; the node matrix scales by 1/1000
    found = true;
  }
  EXPECT_TRUE(found);
}

// The venue's geometry lands where the XML puts it, in haze's frame: a truss piece (a .3ds,
// mm, Z-up, placed by a Symbol) and a focus point marker (a .glb, m, Y-up).
std::pair<glm::dvec3, glm::dvec3> boundsOf(const nlohmann::json& gltf, const nlohmann::json& n) {
  {
    const auto& m = n["matrix"];
    const auto& acc = gltf["accessors"][gltf["meshes"][n["mesh"].get<int>()]["primitives"][0]["attributes"]["POSITION"].get<int>()];
    glm::dvec3 lo(1e30), hi(-1e30);
    for (int corner = 0; corner < 8; ++corner) {
      double p[3];
      for (int k = 0; k < 3; ++k) p[k] = ((corner >> k) & 1) ? acc["max"][k].get<double>() : acc["min"][k].get<double>();
      for (int r = 0; r < 3; ++r) {
        double v = m[12 + r].get<double>();
        for (int c = 0; c < 3; ++c) v += m[4 * c + r].get<double>() * p[c];
        lo[r] = std::min(lo[r], v);
        hi[r] = std::max(hi[r], v);
      }
    }
    return {lo, hi};
  }
}

std::pair<glm::dvec3, glm::dvec3> nodeBounds(const nlohmann::json& gltf, const std::string& nodeName) {
  for (const auto& n : gltf["nodes"])
    if (n["name"] == nodeName) return boundsOf(gltf, n);
  ADD_FAILURE() << "no venue node named " << nodeName;
  return {};
}

TEST(MvrImport, CaptureVenueGeometryIsPlacedInHazeFrame) {
  HAZE_NEED_DATA("gdtf/mvr/capture_demo_show.mvr");
  {
    Imported imp("capture_demo_show.mvr");
    ASSERT_TRUE(imp.result.ok());
    std::ifstream in(imp.dir / "rig_venue.gltf");
    const auto gltf = nlohmann::json::parse(in, nullptr, false);
    // Line 155: the Symbol of the Truss at line 152, whose Matrix turns the truss's local X
    // (its 2.5 m length) to MVR -Z and puts its middle at (-6823.1, -884.5, 2351.6) mm.
    const auto [lo, hi] = nodeBounds(gltf, "GeneralSceneDescription.xml line 155 <Symbol>");
    const double mid[3] = {-6823.14355, -884.489563, 2351.63037};
    const glm::dvec3 centre = toHaze(mid);
    EXPECT_NEAR(hi.y - lo.y, 2.5, 0.02);  // upright in haze: Y is up
    EXPECT_LT(hi.x - lo.x, 0.5);
    EXPECT_LT(hi.z - lo.z, 0.5);
    EXPECT_LT(glm::length(0.5 * (lo + hi) - centre), 0.02);
    // Nothing of the set lies below the stage floor (MVR z = 0): a .3ds read in the wrong axes
    // puts the floor pieces tens of metres under it.
    double lowest = 1e30, highest = -1e30;
    for (const auto& node : gltf["nodes"]) {
      const auto [nlo, nhi] = boundsOf(gltf, node);
      lowest = std::min(lowest, nlo.y);
      highest = std::max(highest, nhi.y);
    }
    EXPECT_GT(lowest, -0.5);
    EXPECT_LT(highest, 20.0);
  }
}

TEST(MvrImport, TheatreVenueGeometryIsPlacedInHazeFrame) {
  {
    Imported imp("scene_objects.mvr");
    ASSERT_TRUE(imp.result.ok());
    std::ifstream in(imp.dir / "rig_venue.gltf");
    const auto gltf = nlohmann::json::parse(in, nullptr, false);
    // Line 31: a wall (.glb, metres, Y-up) whose SceneObject's Matrix (line 27) is the identity
    // rotation at (-14706.6, -1371.6, 4572) mm: the wall's middle. In MVR it stands 30 ft
    // (9.144 m) tall along Z and runs along Y; in haze it must stand along Y and run along Z.
    const auto [lo, hi] = nodeBounds(gltf, "GeneralSceneDescription.xml line 31 <Geometry3D>");
    const double origin[3] = {-14706.6, -1371.6, 4572.0};
    EXPECT_LT(glm::length(0.5 * (lo + hi) - toHaze(origin)), 2e-3);
    EXPECT_NEAR(hi.y - lo.y, 9.144, 2e-3);
    EXPECT_NEAR(lo.y, 0.0, 2e-3);          // on the floor
    EXPECT_GT(hi.z - lo.z, 15.0);          // runs along haze Z (MVR Y)
    EXPECT_LT(hi.x - lo.x, 0.2);           // thin along X
    // The focus point markers (line 1957 is A1's) are not in the venue.
    for (const auto& n : gltf["nodes"]) EXPECT_NE(n["name"], "GeneralSceneDescription.xml line 1957 <Geometry3D>");
  }
}

// The overview camera of the theatre stands inside the room: inside the four walls, whose
// middles the XML gives (the Matrix lines 27, 39, 51, 63), below every piece of ceiling
// (the venue nodes of layer "Theatre FloorPlan" above 7 m, bounds read from the written glTF),
// and nothing of the venue lies between it and its target.
TEST(MvrImport, OverviewCameraIsInsideTheTheatre) {
  Imported imp("scene_objects.mvr");
  ASSERT_TRUE(imp.result.ok());
  const CameraDef* cam = nullptr;
  for (const CameraDef& c : imp.result->show.cameras)
    if (c.name == "MVR overview") cam = &c;
  ASSERT_NE(cam, nullptr);
  const double west[3] = {-14706.6, -1371.6, 0}, east[3] = {15621.0, -1371.6, 0};
  const double north[3] = {457.2, 7696.2, 0}, south[3] = {457.2, -10439.4, 0};
  EXPECT_GT(cam->position.x, toHaze(west).x);
  EXPECT_LT(cam->position.x, toHaze(east).x);
  EXPECT_GT(cam->position.z, toHaze(north).z);  // MVR +Y is haze -Z
  EXPECT_LT(cam->position.z, toHaze(south).z);
  EXPECT_GT(cam->position.y, 0.0f);
  std::ifstream in(imp.dir / "rig_venue.gltf");
  const auto gltf = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(gltf.is_discarded());
  double ceilingLowest = 1e30;
  for (const auto& n : gltf["nodes"]) {
    const auto [lo, hi] = boundsOf(gltf, n);
    if (lo.y > 7.0) ceilingLowest = std::min(ceilingLowest, lo.y);
  }
  ASSERT_LT(ceilingLowest, 1e29);
  EXPECT_LT(cam->position.y, ceilingLowest);
  // Every pendant, its focus point (y 2.4384) and the floor below it are in the picture.
  for (const FixtureDef& f : imp.result->show.fixtures) {
    for (const float y : {f.position.y, 2.4384f, 0.0f}) {
      const glm::vec2 at = framePlace(*cam, {f.position.x, y, f.position.z});
      EXPECT_LE(std::abs(at.x), 1.0f) << f.id << " at y " << y;
      EXPECT_LE(std::abs(at.y), 1.0f) << f.id << " at y " << y;
    }
  }
}

// --- broken MVRs ---------------------------------------------------------------------------

std::string gdtfBytes() {
  auto zip = ZipArchive::open(mvrFile("basic_fixture.mvr"));
  EXPECT_TRUE(zip.ok());
  auto bytes = zip->read("LED PAR 64 RGBW.gdtf");
  EXPECT_TRUE(bytes.ok());
  return std::string(bytes->begin(), bytes->end());
}

std::string sceneXml(const std::string& children, const std::string& aux = "") {
  return "<?xml version=\"1.0\"?>\n<GeneralSceneDescription verMajor=\"1\" verMinor=\"5\">\n<Scene>\n<AUXData>" + aux +
         "</AUXData>\n<Layers>\n<Layer name=\"L\" uuid=\"1\">\n<ChildList>\n" + children +
         "</ChildList>\n</Layer>\n</Layers>\n</Scene>\n</GeneralSceneDescription>\n";
}

std::string fixtureXml(const std::string& name, const std::string& spec, const std::string& address,
                       const std::string& matrix = "{1,0,0}{0,1,0}{0,0,1}{0,0,6000}", const std::string& id = "") {
  return "<Fixture name=\"" + name + "\" uuid=\"u-" + name + "\">\n<Matrix>" + matrix + "</Matrix>\n<GDTFSpec>" + spec +
         "</GDTFSpec>\n<GDTFMode>Default</GDTFMode>\n<FixtureID>" + id + "</FixtureID>\n<Addresses><Address break=\"0\">" +
         address + "</Address></Addresses>\n</Fixture>\n";
}

struct Built {
  test::TempDir dir{"mvrbad"};
  Result<MvrImport> result = Error{};
  Built(bool isZip, const std::vector<test::ZipItem>& items) {
    const auto file = dir / "in.mvr";
    if (isZip) EXPECT_TRUE(test::writeZip(file, items));
    else test::writeFile(file, items.at(0).data);
    result = importMvr(file, dir / "out.haze.json");
  }
  bool warned(const std::string& part) const {
    for (const auto& w : result->warnings)
      if (w.find(part) != std::string::npos) return true;
    return false;
  }
};

TEST(MvrBroken, NotAZip) {
  Built b(false, {{"x", "this is not a zip file at all"}});
  ASSERT_FALSE(b.result.ok());
  EXPECT_NE(b.result.error().str().find("in.mvr"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(b.dir / "out.haze.json"));
}

TEST(MvrBroken, NoSceneDescription) {
  Built b(true, {{"other.xml", "<a/>"}});
  ASSERT_FALSE(b.result.ok());
  EXPECT_NE(b.result.error().message.find("GeneralSceneDescription.xml"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(b.dir / "out.haze.json"));
}

TEST(MvrBroken, MalformedXmlNamesTheLine) {
  Built b(true, {{"GeneralSceneDescription.xml", "<?xml version=\"1.0\"?>\n<GeneralSceneDescription>\n<Scene>\n<Layers></Scene>"}});
  ASSERT_FALSE(b.result.ok());
  EXPECT_NE(b.result.error().place.find("line 4"), std::string::npos) << b.result.error().str();
}

TEST(MvrBroken, NotASceneDescription) {
  Built b(true, {{"GeneralSceneDescription.xml", "<?xml version=\"1.0\"?>\n<Something/>"}});
  ASSERT_FALSE(b.result.ok());
  EXPECT_NE(b.result.error().message.find("GeneralSceneDescription"), std::string::npos);
}

TEST(MvrBroken, MissingGdtfIsWarnedAndTheRestImports) {
  const std::string xml = sceneXml(fixtureXml("A", "Missing@Fixture.gdtf", "1") + fixtureXml("B", "par.gdtf", "1025", "{1,0,0}{0,1,0}{0,0,1}{1000,2000,3000}", "7"));
  Built b(true, {{"GeneralSceneDescription.xml", xml}, {"par.gdtf", gdtfBytes()}});
  ASSERT_TRUE(b.result.ok()) << b.result.error().str();
  EXPECT_TRUE(b.warned("line 8 <Fixture name=\"A\">: GDTFSpec \"Missing@Fixture.gdtf\" is not in the archive"));
  ASSERT_EQ(b.result->show.fixtures.size(), 1u);
  const FixtureDef& f = b.result->show.fixtures[0];
  EXPECT_EQ(f.id, 7);
  ASSERT_TRUE(f.patch.has_value());
  EXPECT_EQ(f.patch->universe, 3);
  EXPECT_EQ(f.patch->address, 1);
  auto g = loadGdtf(b.dir / "out_gdtf" / "par.gdtf");
  ASSERT_TRUE(g.ok());
  const glm::vec3 expected = glm::vec3(1.0f, 3.0f, -2.0f) + g->pivotOffsetM;
  EXPECT_LT(glm::length(f.position - expected), 1e-4f);
  for (const Error& e : validateShowFile(b.dir / "out.haze.json")) ADD_FAILURE() << e.str();
}

// GroupObjects become haze groups: nested ones give a fixture to each group around it, unnamed
// ones that hold fixtures are numbered from 1, and fixtures whose GDTF does not import are left out of them.
TEST(MvrGroups, GroupObjectsBecomeGroups) {
  const std::string xml = sceneXml(
      "<GroupObject name=\"Truss\" uuid=\"g1\"><ChildList>\n" + fixtureXml("A", "par.gdtf", "1", "{1,0,0}{0,1,0}{0,0,1}{0,0,6000}", "1") +
      "<GroupObject name=\"Left\" uuid=\"g2\"><ChildList>\n" + fixtureXml("B", "par.gdtf", "20", "{1,0,0}{0,1,0}{0,0,1}{0,0,6000}", "2") +
      fixtureXml("C", "Missing@Fixture.gdtf", "40", "{1,0,0}{0,1,0}{0,0,1}{0,0,6000}", "3") +
      "</ChildList></GroupObject>\n</ChildList></GroupObject>\n" +
      "<GroupObject uuid=\"g3\"><ChildList>\n" + fixtureXml("D", "par.gdtf", "60", "{1,0,0}{0,1,0}{0,0,1}{0,0,6000}", "4") +
      "</ChildList></GroupObject>\n<GroupObject name=\"Empty\" uuid=\"g4\"><ChildList>\n" +
      fixtureXml("E", "Missing@Fixture.gdtf", "80", "{1,0,0}{0,1,0}{0,0,1}{0,0,6000}", "5") + "</ChildList></GroupObject>\n" +
      fixtureXml("F", "par.gdtf", "100", "{1,0,0}{0,1,0}{0,0,1}{0,0,6000}", "6"));
  Built b(true, {{"GeneralSceneDescription.xml", xml}, {"par.gdtf", gdtfBytes()}});
  ASSERT_TRUE(b.result.ok()) << b.result.error().str();
  const std::vector<GroupDef> expected = {GroupDef{"Truss", {1, 2}}, GroupDef{"Left", {2}}, GroupDef{"MVR group 1", {4}}};
  EXPECT_EQ(b.result->show.groups, expected);
  for (const Error& e : validateShowFile(b.dir / "out.haze.json")) ADD_FAILURE() << e.str();
}

// A GDTF whose beam does not point along its own -Z at rest (the LED PAR's Beam turned 90
// degrees about GDTF Y, to -X): the GDTF import's warning is passed on with the GDTF's name, and
// the fixture is placed by its -Z: with the Matrix's w = MVR -Y, the beam at rest points along
// MVR +Y, which is haze -Z (docs/mvr.md, README).
TEST(MvrOrientation, BeamNotAlongMinusZIsWarnedAndFollowsTheFixturesMinusZ) {
  test::TempDir dir("mvrbeam");
  test::writeFile(dir / "par.gdtf", gdtfBytes());
  auto par = ZipArchive::open(dir / "par.gdtf");
  ASSERT_TRUE(par.ok());
  std::vector<test::ZipItem> items;
  bool turned = false;
  for (const ZipEntry& e : par->entries()) {
    auto bytes = par->read(e.name);
    ASSERT_TRUE(bytes.ok());
    std::string data(bytes->begin(), bytes->end());
    if (e.name == "description.xml") {
      const std::string rest = "Position=\"{1.000000,0.000000,0.000000,0.000000}{0.000000,1.000000,0.000000,0.000000}"
                               "{0.000000,0.000000,1.000000,-0.134000}{0,0,0,1}\"";
      const auto at = data.find(rest);
      ASSERT_NE(at, std::string::npos);
      data.replace(at, rest.size(), "Position=\"{0,0,1,0}{0,1,0,0}{-1,0,0,-0.134}{0,0,0,1}\"");
      turned = true;
    }
    items.push_back({e.name, data});
  }
  ASSERT_TRUE(turned);
  ASSERT_TRUE(test::writeZip(dir / "turned.gdtf", items));
  const std::string xml = sceneXml(fixtureXml("T", "turned.gdtf", "1", "{1,0,0}{0,0,1}{0,-1,0}{1000,2000,3000}"));
  Built b(true, {{"GeneralSceneDescription.xml", xml}, {"turned.gdtf", test::readFile(dir / "turned.gdtf")}});
  ASSERT_TRUE(b.result.ok()) << b.result.error().str();
  EXPECT_TRUE(b.warned("turned.gdtf: description.xml line "));
  EXPECT_TRUE(b.warned("the beam does not point along the fixture's -Z at rest"));
  ASSERT_EQ(b.result->show.fixtures.size(), 1u);
  const FixtureDef& f = b.result->show.fixtures[0];
  const glm::mat3 r = glm::mat3(glm::eulerAngleZYX(glm::radians(f.rotationDeg.z), glm::radians(f.rotationDeg.y), glm::radians(f.rotationDeg.x)));
  EXPECT_LT(glm::length(r * glm::vec3(0, -1, 0) - glm::vec3(0, 0, -1)), 1e-4f);
}

TEST(MvrBroken, BadFieldsAreWarnedNotFatal) {
  const std::string xml = sceneXml(fixtureXml("A", "par", "banana", "{1,0,0}{0,1,0}{oops}{0,0,0}") +
                                   "<Mystery name=\"m\"/>\n<SceneObject name=\"S\" uuid=\"s\"><Geometries><Geometry3D fileName=\"absent.3ds\"/>"
                                   "<Symbol uuid=\"y\" symdef=\"loop\"/></Geometries></SceneObject>\n",
                                   "<Symdef uuid=\"loop\" name=\"loop\"><ChildList><Symbol uuid=\"z\" symdef=\"loop\"/></ChildList></Symdef>");
  Built b(true, {{"GeneralSceneDescription.xml", xml}, {"par.gdtf", gdtfBytes()}});
  ASSERT_TRUE(b.result.ok()) << b.result.error().str();
  EXPECT_TRUE(b.warned("<Matrix>: Matrix"));
  EXPECT_TRUE(b.warned("Address \"banana\""));
  EXPECT_TRUE(b.warned("<Mystery name=\"m\">: unknown scene element"));
  EXPECT_TRUE(b.warned("absent.3ds"));
  EXPECT_TRUE(b.warned("symbols nested deeper"));  // a symdef that uses itself ends, warned
  ASSERT_EQ(b.result->show.fixtures.size(), 1u);
  EXPECT_FALSE(b.result->show.fixtures[0].patch.has_value());
}

// Symbols of symbols multiply: 10 levels of 10 would be 10^10 placements. The import stops at
// its limit with a warning instead of running out of memory.
TEST(MvrBroken, SymbolExplosionIsBounded) {
  std::string aux;
  for (int level = 0; level < 10; ++level) {
    aux += "<Symdef uuid=\"s" + std::to_string(level) + "\" name=\"s\"><ChildList>";
    for (int i = 0; i < 10; ++i)
      aux += level == 9 ? "<Geometry3D fileName=\"none.3ds\"/>" : "<Symbol uuid=\"x\" symdef=\"s" + std::to_string(level + 1) + "\"/>";
    aux += "</ChildList></Symdef>";
  }
  const std::string xml = sceneXml("<SceneObject name=\"S\" uuid=\"o\"><Geometries><Symbol uuid=\"y\" symdef=\"s0\"/></Geometries></SceneObject>\n", aux);
  Built b(true, {{"GeneralSceneDescription.xml", xml}});
  ASSERT_TRUE(b.result.ok()) << b.result.error().str();
  EXPECT_TRUE(b.warned("geometry placements; the rest is left out"));
  EXPECT_TRUE(b.warned("none.3ds"));
}

// The camera's rays keep at most 2 million placed triangles: 2100 placements of the theatre's
// 972-triangle chandelier (2.04 million) import whole, with a warning that the camera saw the
// first 2 million only.
TEST(MvrBroken, PlacedTrianglesForTheCameraAreBounded) {
  const std::string chandelier = "f9af9d23-3867-48c1-b7f3-6ae621dd6021.glb";
  auto theatre = ZipArchive::open(mvrFile("scene_objects.mvr"));
  ASSERT_TRUE(theatre.ok());
  auto mesh = theatre->read(chandelier);
  ASSERT_TRUE(mesh.ok());
  std::string geometries;
  for (int i = 0; i < 2100; ++i)
    geometries += "<Geometry3D fileName=\"" + chandelier + "\"><Matrix>{1,0,0}{0,1,0}{0,0,1}{" + std::to_string(3000 * (i % 50)) +
                  "," + std::to_string(3000 * (i / 50)) + ",0}</Matrix></Geometry3D>\n";
  const std::string xml = sceneXml(fixtureXml("A", "par.gdtf", "1") + "<SceneObject name=\"S\" uuid=\"s\"><Geometries>" + geometries +
                                   "</Geometries></SceneObject>\n");
  Built b(true, {{"GeneralSceneDescription.xml", xml}, {"par.gdtf", gdtfBytes()}, {chandelier, std::string(mesh->begin(), mesh->end())}});
  ASSERT_TRUE(b.result.ok()) << b.result.error().str();
  EXPECT_EQ(b.result->geometryInstances, 2100);
  EXPECT_TRUE(b.warned("the venue places more than 2000000 triangles; the overview camera is placed against the first ones only"));
  ASSERT_EQ(b.result->show.cameras.size(), 1u);
}

TEST(MvrBroken, RefusesToOverwriteAnExistingShow) {
  test::TempDir dir("mvrexists");
  test::writeFile(dir / "s.haze.json", "{}");
  auto r = importMvr(mvrFile("basic_fixture.mvr"), dir / "s.haze.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("already exists"), std::string::npos);
  EXPECT_EQ(test::readFile(dir / "s.haze.json"), "{}");
  MvrImportOptions force;
  force.force = true;
  EXPECT_TRUE(importMvr(mvrFile("basic_fixture.mvr"), dir / "s.haze.json", force).ok());
}

}  // namespace
}  // namespace haze
