// Loading a show into the model and writing it back: every field of docs/show-format.md arrives,
// a save reloads to the same show, and saving twice gives the same bytes (diffable files).
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "show_test_data.h"
#include "shows/show_json.h"

namespace haze {
namespace {

using test::validShowPath;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ShowIo, LoadsEveryPart) {
  auto r = loadShow(validShowPath());
  ASSERT_TRUE(r.ok()) << r.error().str();
  const Show& s = *r;
  EXPECT_EQ(s.venueGltf, "../shared/venues/Cube/Cube.gltf");
  EXPECT_FLOAT_EQ(s.atmosphere.scattering, 0.03f);
  EXPECT_EQ(s.atmosphere.phase, "hazy");
  EXPECT_EQ(s.atmosphere.ambient, glm::vec3(0.02f));
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].position, glm::vec3(0, 4, 18));
  EXPECT_EQ(s.cameras[0].up, glm::vec3(0, 1, 0));  // default
  EXPECT_FLOAT_EQ(s.cameras[0].farM, 100.0f);       // default
  ASSERT_EQ(s.profiles.size(), 2u);
  EXPECT_EQ(s.profiles.at("spot").path, "profiles/test-spot.json");
  EXPECT_TRUE(s.profiles.at("par").inlineObject && s.profiles.at("par").inlineWrapped);
  ASSERT_EQ(s.fixtures.size(), 3u);
  EXPECT_EQ(s.fixtures[1].id, 102);
  EXPECT_EQ(s.fixtures[1].mode, "Standard");
  EXPECT_EQ(s.fixtures[1].position, glm::vec3(3, 7, 0));
  ASSERT_TRUE(s.fixtures[1].patch);
  EXPECT_EQ(s.fixtures[1].patch->address, 11);
  ASSERT_EQ(s.cueLists.size(), 2u);
  const Cue& c = s.cueLists[0].cues[1];
  EXPECT_EQ(c.number, "2");
  EXPECT_DOUBLE_EQ(c.delayS, 1.0);
  EXPECT_DOUBLE_EQ(c.fadeS, 4.0);
  EXPECT_FALSE(c.followS);
  EXPECT_EQ(*s.cueLists[0].cues[3].followS, 1.0);
  EXPECT_EQ(*c.values.at(102).gobo, "Star");
  EXPECT_FLOAT_EQ(*c.values.at(102).tiltDeg, -45.0f);
  EXPECT_FALSE(c.values.at(102).intensity);
  EXPECT_EQ(s.findCueList("")->name, "Main");
  EXPECT_EQ(s.findCueList("Effects")->cues.size(), 1u);
  EXPECT_EQ(s.findCueList("Nope"), nullptr);
  EXPECT_EQ(s.resolve("profiles/x.json"), validShowPath().parent_path() / "profiles/x.json");
  ASSERT_TRUE(s.stamp);
  EXPECT_EQ(*s.stamp, stampOf(slurp(validShowPath())));
}

TEST(ShowIo, LoadsProfilesFromFilesAndInline) {
  auto s = loadShow(validShowPath());
  ASSERT_TRUE(s.ok());
  auto p = loadProfiles(*s);
  ASSERT_TRUE(p.ok()) << p.error().str();
  EXPECT_EQ(p->at("spot")->name, "Test Spot");
  EXPECT_FLOAT_EQ(p->at("spot")->zoomDeg.max, 40.0f);
  EXPECT_EQ(p->at("par")->name, "Test Par");
  ASSERT_NE(p->at("spot")->findMode("Standard"), nullptr);
  EXPECT_EQ(p->at("spot")->findMode("Standard")->footprint(), 10);
}

TEST(ShowIo, WrittenTextReloadsToTheSameShowAndIsStable) {
  auto a = loadShow(validShowPath());
  ASSERT_TRUE(a.ok());
  std::string text = showToText(*a);
  ShowParse b = parseShowText(text, validShowPath());
  ASSERT_TRUE(b.problems.empty()) << b.problems[0].str() << "\n" << text;
  EXPECT_EQ(showToText(b.show), text);  // a second save changes no byte
  const Show& s = b.show;
  ASSERT_EQ(s.fixtures.size(), a->fixtures.size());
  for (size_t i = 0; i < s.fixtures.size(); ++i) {
    EXPECT_EQ(s.fixtures[i].id, a->fixtures[i].id);
    EXPECT_EQ(s.fixtures[i].position, a->fixtures[i].position);
    EXPECT_EQ(s.fixtures[i].patch->address, a->fixtures[i].patch->address);
  }
  for (size_t l = 0; l < s.cueLists.size(); ++l)
    for (size_t c = 0; c < s.cueLists[l].cues.size(); ++c) {
      const Cue& x = s.cueLists[l].cues[c];
      const Cue& y = a->cueLists[l].cues[c];
      EXPECT_EQ(x.number, y.number);
      EXPECT_EQ(x.label, y.label);
      EXPECT_EQ(x.fadeS, y.fadeS);
      EXPECT_EQ(x.delayS, y.delayS);
      EXPECT_EQ(x.followS, y.followS);
      EXPECT_EQ(x.values, y.values);
    }
  EXPECT_EQ(s.profiles.at("par").inlineObject, a->profiles.at("par").inlineObject);
  EXPECT_EQ(s.atmosphere.ambient, a->atmosphere.ambient);
}

// A cue's timecode is written only when set, so shows without timecodes keep their exact text.
TEST(ShowIo, CueTimecodeRoundTripsAndIsWrittenOnlyWhenSet) {
  auto a = loadShow(validShowPath());
  ASSERT_TRUE(a.ok());
  ASSERT_FALSE(a->cueLists.empty());
  EXPECT_EQ(showToText(*a).find("timecode"), std::string::npos);
  a->cueLists[0].cues[0].timecode = "01:02:03:04";
  const std::string text = showToText(*a);
  EXPECT_NE(text.find("\"timecode\": \"01:02:03:04\""), std::string::npos);
  ShowParse b = parseShowText(text, validShowPath());
  ASSERT_TRUE(b.problems.empty()) << b.problems[0].str();
  EXPECT_EQ(b.show.cueLists[0].cues[0].timecode, "01:02:03:04");
  EXPECT_EQ(b.show.cueLists[0].cues[1].timecode, "");
}

// atmosphere.shadows: soft unless the show says hard, written only when hard (docs/show-format.md).
TEST(ShowIo, ShadowsAreSoftByDefaultAndHardRoundTrips) {
  auto a = loadShow(validShowPath());
  ASSERT_TRUE(a.ok());
  EXPECT_TRUE(a->atmosphere.softShadows);
  EXPECT_EQ(showToText(*a).find("shadows"), std::string::npos);
  a->atmosphere.softShadows = false;
  const std::string text = showToText(*a);
  EXPECT_NE(text.find("\"shadows\": \"hard\""), std::string::npos);
  ShowParse b = parseShowText(text, validShowPath());
  ASSERT_TRUE(b.problems.empty()) << b.problems[0].str();
  EXPECT_FALSE(b.show.atmosphere.softShadows);
  EXPECT_EQ(showToText(b.show), text);
  std::string bad = text;
  bad.replace(bad.find("\"hard\""), 6, "\"fuzzy\"");
  ShowParse c = parseShowText(bad, validShowPath());
  ASSERT_EQ(c.problems.size(), 1u);
  EXPECT_EQ(c.problems[0].place, "/atmosphere/shadows");
  EXPECT_EQ(c.problems[0].message, "unknown shadow kind \"fuzzy\"; expected soft or hard");
}

TEST(ShowIo, WrittenTextIsDiffable) {
  auto a = loadShow(validShowPath());
  ASSERT_TRUE(a.ok());
  std::string text = showToText(*a);
  // The key order of docs/show-format.md, numbers in their short form, number arrays on one line.
  EXPECT_LT(text.find("\"format\""), text.find("\"version\""));
  EXPECT_LT(text.find("\"version\""), text.find("\"venue\""));
  EXPECT_LT(text.find("\"atmosphere\""), text.find("\"cameras\""));
  EXPECT_LT(text.find("\"profiles\""), text.find("\"fixtures\""));
  EXPECT_LT(text.find("\"fixtures\""), text.find("\"cue_lists\""));
  EXPECT_NE(text.find("\n  \"version\": 2,\n"), std::string::npos);  // a version-1 file saves as version 2
  EXPECT_NE(text.find("\"scattering\": 0.03,"), std::string::npos) << text;
  EXPECT_NE(text.find("\"color\": [1, 0.8, 0.6]"), std::string::npos);
  EXPECT_NE(text.find("\"position\": [-3, 7, 0]"), std::string::npos);
  EXPECT_EQ(text.find("0.800000"), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
  // One fixture per block: each fixture's id starts its own line, at the same depth.
  size_t ids = 0;
  for (size_t at = 0; (at = text.find("\n      \"id\": ", at)) != std::string::npos; ++at) ++ids;
  EXPECT_EQ(ids, 3u);
}

TEST(ShowIo, UnknownVersionsAreRefusedClearly) {
  std::string text = slurp(validShowPath());
  auto v2 = text;
  v2.replace(v2.find("\"version\": 1"), 12, "\"version\": 7");
  ShowParse p = parseShowText(v2, "new.haze.json");
  ASSERT_EQ(p.problems.size(), 1u);
  EXPECT_EQ(p.problems[0].place, "/version");
  EXPECT_EQ(p.problems[0].message,
            "this show has format version 7, newer than this haze reads (up to 2); open it with a newer haze");
}

TEST(ShowIo, LoadShowFailsWithTheFirstProblemAndCountsTheRest) {
  auto dir = std::filesystem::temp_directory_path() / ("haze-shows-io-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto file = dir / "bad.haze.json";
  {
    std::ofstream out(file);
    out << R"({"format": "haze-show", "version": 1, "profiles": {}, "fixtures": [{"id": -1, "profile": 3}]})";
  }
  auto r = loadShow(file);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, file.string());
  EXPECT_EQ(r.error().place, "/fixtures/0/id");
  EXPECT_NE(r.error().message.find("and 1 more problems"), std::string::npos) << r.error().message;
  EXPECT_FALSE(loadShow(dir / "missing.haze.json").ok());
  EXPECT_FALSE(loadShow(dir).ok());  // a folder is not a show
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace haze
