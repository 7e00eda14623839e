// The GDTF files embedded in the MVR scenes of the test data, unpacked with ZipArchive (as the MVR
// importer will) and imported from memory. Which ones import is recorded in docs/gdtf.md.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "fixtures/gdtf.h"
#include "fixtures/core/zip_archive.h"
#include "test_data.h"

namespace haze {
namespace {

struct Imported {
  std::string name;        // the fixture type
  bool defaultBeam = false;  // warned: no <Beam>, the default one is used
};

// file name inside the MVR -> what it imported as.
std::map<std::string, Imported> importEmbedded(const std::string& mvr, std::vector<std::string>& failures) {
  std::map<std::string, Imported> out;
  auto zip = ZipArchive::open(test::dataFile("gdtf/mvr/" + mvr));
  EXPECT_TRUE(zip.ok()) << zip.error().str();
  if (!zip.ok()) return out;
  EXPECT_TRUE(zip->contains("GeneralSceneDescription.xml"));
  for (const ZipEntry& e : zip->entries()) {
    if (e.name.size() < 5 || e.name.substr(e.name.size() - 5) != ".gdtf") continue;
    auto bytes = zip->read(e.name);
    EXPECT_TRUE(bytes.ok()) << bytes.error().str();
    if (!bytes.ok()) continue;
    auto g = loadGdtfFromMemory(std::move(*bytes), mvr + ":" + e.name);
    if (g.ok()) {
      bool defaultBeam = false;
      for (const auto& w : g->warnings) defaultBeam |= w.find("has no <Beam>") != std::string::npos;
      out[e.name] = {g->profile->name, defaultBeam};
      EXPECT_FALSE(g->profile->modes.empty()) << e.name;
    } else {
      failures.push_back(g.error().str());
    }
  }
  return out;
}

TEST(MvrEmbedded, BasicFixture) {
  std::vector<std::string> failures;
  auto got = importEmbedded("basic_fixture.mvr", failures);
  EXPECT_TRUE(failures.empty()) << failures.front();
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got.begin()->first, "LED PAR 64 RGBW.gdtf");
  EXPECT_EQ(got.begin()->second.name, "LED PAR 64 RGBW");
  EXPECT_FALSE(got.begin()->second.defaultBeam);
}

TEST(MvrEmbedded, SceneObjects) {
  std::vector<std::string> failures;
  auto got = importEmbedded("scene_objects.mvr", failures);
  EXPECT_TRUE(failures.empty()) << failures.front();
  // Two copies of one custom fixture type under two names.
  ASSERT_EQ(got.size(), 2u);
  for (const auto& [file, imported] : got) {
    EXPECT_EQ(imported.name, "Light Source Pendant 44deg") << file;
    EXPECT_FALSE(imported.defaultBeam) << file;
  }
  EXPECT_TRUE(got.count("Custom@Light_Source_Pendant_44deg@fix_beam.gdtf"));
}

TEST(MvrEmbedded, CaptureDemoShow) {
  HAZE_NEED_DATA("gdtf/mvr/capture_demo_show.mvr");
  std::vector<std::string> failures;
  auto got = importEmbedded("capture_demo_show.mvr", failures);
  for (const auto& f : failures) ADD_FAILURE() << f;
  // Capture exports stubs: one Geometry, no Beam, custom DimmerN attributes. They import with
  // the default Beam and a warning.
  const std::map<std::string, std::string> expected = {
      {"ADB@ALC4@r3012.gdtf", "ALC4"},
      {"Clay Paky@A.leda Wash K20@r3044.gdtf", "A.leda Wash K20"},
      {"Clay Paky@Alpha Spot QWO 800@r3048.gdtf", "Alpha Spot QWO 800"},
      {"Robe@Robin MMX Spot@r3046.gdtf", "Robin MMX Spot"},
      {"Robe@Robin MMX WashBeam@r3039.gdtf", "Robin MMX WashBeam"},
  };
  ASSERT_EQ(got.size(), expected.size());
  for (const auto& [file, name] : expected) {
    ASSERT_TRUE(got.count(file)) << file;
    EXPECT_EQ(got[file].name, name) << file;
    EXPECT_TRUE(got[file].defaultBeam) << file;
  }
}

}  // namespace
}  // namespace haze
