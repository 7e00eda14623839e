// Groups and palettes (docs/show-format.md, "Groups and palettes"): a palette's value resolves
// when a cue plays, so updating it reaches exactly the cues whose state comes from it; broken
// references are refused with their JSON pointer; a version-1 show migrates without loss.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <tuple>

#include "show_test_data.h"
#include "shows/palettes.h"
#include "shows/playback.h"
#include "shows/show_json.h"
#include "shows/show_save.h"
#include "shows/show_validate.h"

namespace haze {
namespace {

// Fixtures 1..4 in groups Left (1, 2) and Right (3, 4). Cue 1 puts everyone in "Centre"; cue 2
// moves fixture 1 by hand (pan and tilt), so nothing of its position comes from the palette any
// more; cue 3 sends fixture 3 to "Wide" and fixture 4 to a literal tilt; cue 4 colours fixture 2
// by "Red". The list "Other" uses only "Wide" and literal values.
constexpr const char* kShow = R"({
  "format": "haze-show", "version": 2,
  "profiles": { "spot": { "format": "haze-fixture", "version": 1, "name": "Spot",
                          "photometry": { "beam_angle": 20, "field_angle": 30, "peak_candela": 1000 } } },
  "fixtures": [ { "id": 1, "profile": "spot" }, { "id": 2, "profile": "spot" },
                { "id": 3, "profile": "spot" }, { "id": 4, "profile": "spot" } ],
  "groups": [ { "name": "Left", "fixtures": [1, 2] }, { "name": "Right", "fixtures": [3, 4] },
              { "name": "All", "fixtures": [1, 2, 3, 4] } ],
  "palettes": [
    { "name": "Centre", "kind": "position",
      "groups": { "Left": { "pan": 10, "tilt": 20 }, "Right": { "pan": -10, "tilt": 20 } },
      "fixtures": { "2": { "pan": 12 } } },
    { "name": "Wide", "kind": "position", "groups": { "All": { "pan": 60, "tilt": 45 } } },
    { "name": "Red", "kind": "color", "groups": { "All": { "color": [1, 0, 0] } } }
  ],
  "cue_lists": [
    { "name": "Main", "cues": [
      { "number": "1", "values": { "1": { "intensity": 1, "palettes": { "position": "Centre" } },
                                   "2": { "intensity": 1, "palettes": { "position": "Centre" } },
                                   "3": { "intensity": 1, "palettes": { "position": "Centre" } },
                                   "4": { "intensity": 1, "palettes": { "position": "Centre" } } } },
      { "number": "2", "fade": 2, "values": { "1": { "pan": 50, "tilt": 60 } } },
      { "number": "3", "values": { "3": { "palettes": { "position": "Wide" } }, "4": { "tilt": 5 } } },
      { "number": "4", "values": { "2": { "palettes": { "color": "Red" } } } }
    ] },
    { "name": "Other", "cues": [
      { "number": "1", "values": { "1": { "intensity": 1, "palettes": { "position": "Wide" } }, "2": { "pan": 7 } } }
    ] }
  ]
})";

Show load(const test::ScratchDir& dir, const std::string& text, const char* name = "pal.haze.json") {
  const auto file = dir.path / name;
  std::ofstream(file) << text;
  auto show = loadShow(file);
  EXPECT_TRUE(show.ok()) << (show ? "" : show.error().str());
  return show ? *show : Show{};
}

// Every (list, cue, fixture, attribute) whose tracked value differs between two shows.
using Change = std::tuple<std::string, std::string, int, std::string>;
std::set<Change> changes(const Show& a, const Show& b, const ProfileSet& profiles) {
  std::set<Change> out;
  for (size_t l = 0; l < a.cueLists.size(); ++l)
    for (size_t c = 0; c < a.cueLists[l].cues.size(); ++c) {
      const StageState sa = trackedState(a, profiles, a.cueLists[l], c);
      const StageState sb = trackedState(b, profiles, b.cueLists[l], c);
      for (const auto& [id, x] : sa) {
        const Attributes& y = sb.at(id);
        const Change base{a.cueLists[l].name, a.cueLists[l].cues[c].number, id, ""};
        auto note = [&](bool differ, const char* what) {
          if (differ) out.insert({std::get<0>(base), std::get<1>(base), id, what});
        };
        note(x.panDeg != y.panDeg, "pan");
        note(x.tiltDeg != y.tiltDeg, "tilt");
        note(x.color != y.color, "color");
        note(x.intensity != y.intensity, "intensity");
        note(!(x == y) && x.panDeg == y.panDeg && x.tiltDeg == y.tiltDeg && x.color == y.color &&
                 x.intensity == y.intensity,
             "other");
      }
    }
  return out;
}

TEST(Palettes, ValuesResolvePerGroupThenPerFixture) {
  test::ScratchDir dir;
  const Show show = load(dir, kShow);
  auto profiles = loadProfiles(show);
  ASSERT_TRUE(profiles.ok());
  const StageState one = trackedState(show, *profiles, show.cueLists[0], 0);
  EXPECT_EQ(one.at(1).panDeg, 10.0f);
  EXPECT_EQ(one.at(1).tiltDeg, 20.0f);
  EXPECT_EQ(one.at(2).panDeg, 12.0f);  // the palette's fixture entry over its group entry
  EXPECT_EQ(one.at(2).tiltDeg, 20.0f);
  EXPECT_EQ(one.at(3).panDeg, -10.0f);
  const StageState four = trackedState(show, *profiles, show.cueLists[0], 3);
  EXPECT_EQ(four.at(1).panDeg, 50.0f);   // cue 2's own values
  EXPECT_EQ(four.at(3).panDeg, 60.0f);   // Wide from cue 3
  EXPECT_EQ(four.at(4).panDeg, -10.0f);  // Centre tracked from cue 1, tilt by hand in cue 3
  EXPECT_EQ(four.at(4).tiltDeg, 5.0f);
  EXPECT_EQ(four.at(2).color, glm::vec3(1, 0, 0));
  EXPECT_EQ(four.at(2).panDeg, 12.0f);
  // Half-way through cue 2's fade, fixture 1 moves from the palette's value to its own.
  const StageState half = stateAt(show, *profiles, show.cueLists[0], 1, 1.0);
  EXPECT_FLOAT_EQ(half.at(1).panDeg, 30.0f);
  EXPECT_FLOAT_EQ(half.at(1).tiltDeg, 40.0f);
}

TEST(Palettes, UpdatingAPaletteReachesExactlyTheCuesThatUseIt) {
  test::ScratchDir dir;
  const Show before = load(dir, kShow);
  auto profiles = loadProfiles(before);
  ASSERT_TRUE(profiles.ok());
  Show after = before;
  for (PaletteDef& p : after.palettes)
    if (p.name == "Centre") p.groups.at("Left") = CueValues{.panDeg = 30.0f, .tiltDeg = 40.0f};
  // By hand from kShow: fixture 1 pan and tilt and fixture 2 tilt (its pan is its own entry)
  // in cue 1; fixture 1 is by hand from cue 2 on; fixture 2 keeps Centre's tilt through cues 2-4.
  // Right (3, 4), the list "Other" and the cues' own values do not change.
  const std::set<Change> want = {
      {"Main", "1", 1, "pan"}, {"Main", "1", 1, "tilt"}, {"Main", "1", 2, "tilt"},
      {"Main", "2", 2, "tilt"}, {"Main", "3", 2, "tilt"}, {"Main", "4", 2, "tilt"},
  };
  EXPECT_EQ(changes(before, after, *profiles), want);
  // The cues still hold the reference, not copies of the values.
  EXPECT_EQ(after.cueLists[0].cues[0].values.at(1).palettes.position, "Centre");
  EXPECT_FALSE(after.cueLists[0].cues[0].values.at(1).panDeg);

  // Updating "Red" reaches fixture 2 in cue 4 only.
  Show red = before;
  red.palettes[2].groups.at("All").color = glm::vec3(0, 0, 1);
  EXPECT_EQ(changes(before, red, *profiles), (std::set<Change>{{"Main", "4", 2, "color"}}));
}

TEST(Palettes, SaveAndReloadKeepGroupsPalettesAndReferences) {
  test::ScratchDir dir;
  Show show = load(dir, kShow);
  const std::string text = showToText(show);
  ASSERT_TRUE(saveShow(show, dir.path / "saved.haze.json").ok());
  const Show again = load(dir, text, "again.haze.json");
  EXPECT_EQ(showToText(again), text);
  ASSERT_EQ(again.groups.size(), 3u);
  EXPECT_EQ(again.groups[2].fixtures, (std::vector<int>{1, 2, 3, 4}));
  ASSERT_EQ(again.palettes.size(), 3u);
  EXPECT_EQ(again.palettes[0].kind, PaletteKind::Position);
  EXPECT_EQ(*again.palettes[0].fixtures.at(2).panDeg, 12.0f);
  EXPECT_EQ(again.cueLists[0].cues[3].values.at(2).palettes.color, "Red");
  EXPECT_TRUE(validateShowText(text, dir.path / "again.haze.json").empty());
}

// Each broken variant: loadShow refuses it with one line at the pointer, and validate lists it.
void expectRefused(const std::string& text, const std::string& pointer, const std::string& message) {
  test::ScratchDir dir;
  const auto file = dir.path / "bad.haze.json";
  std::ofstream(file) << text;
  auto show = loadShow(file);
  ASSERT_FALSE(show.ok()) << pointer;
  EXPECT_EQ(show.error().place, pointer);
  // Its own message first; follow-on problems of the same mistake are counted after it.
  EXPECT_EQ(show.error().message.substr(0, message.size()), message);
  EXPECT_EQ(show.error().str().find('\n'), std::string::npos);
  EXPECT_NE(show.error().str().find(file.string()), std::string::npos);
  bool listed = false;
  for (const Error& e : validateShowFile(file)) listed = listed || (e.place == pointer && e.message == message);
  EXPECT_TRUE(listed) << pointer;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(Palettes, BrokenReferencesAreRefusedAtTheirPlace) {
  expectRefused(replaced(kShow, R"("position": "Wide" } }, "4")", R"("position": "Wdie" } }, "4")"),
                "/cue_lists/0/cues/2/values/3/palettes/position",
                "no palette \"Wdie\"; expected one of: \"Centre\", \"Wide\", \"Red\"");
  expectRefused(replaced(kShow, R"("fixtures": [3, 4])", R"("fixtures": [3, 44])"), "/groups/1/fixtures/1",
                "group \"Right\" names fixture 44, which is not in /fixtures; expected the id of a fixture of the show");
  expectRefused(replaced(kShow, R"({ "color": "Red" })", R"({ "color": "Wide" })"),
                "/cue_lists/0/cues/3/values/2/palettes/color",
                "palette \"Wide\" is a position palette; expected a color palette here");
  expectRefused(replaced(kShow, R"("Right": { "pan": -10, "tilt": 20 })", R"("Right": { "pan": -10, "zoom": 20 })"),
                "/palettes/0/groups/Right/zoom",
                "a position palette cannot hold zoom; expected pan and tilt only (or make it an \"all\" palette)");
  expectRefused(replaced(kShow, R"("groups": { "All": { "pan": 60)", R"("groups": { "Al": { "pan": 60)"),
                "/palettes/1/groups/Al",
                "palette \"Wide\" has values for group \"Al\", which is not in /groups; expected one of: \"Left\", "
                "\"Right\", \"All\"");
  // A palette holding a palette reference would open the door to cycles: it is not a palette key.
  test::ScratchDir dir;
  ShowParse p = parseShowText(
      replaced(kShow, R"("fixtures": { "2": { "pan": 12 } })", R"("fixtures": { "2": { "palettes": { "position": "Centre" } } })"),
      dir.path / "cycle.haze.json");
  ASSERT_FALSE(p.problems.empty());
  EXPECT_EQ(p.problems[0].place, "/palettes/0/fixtures/2/palettes");
}

// The demo as it was in format version 1 (tests/data/shows/demo-v1.haze.json) reads as version 2, saves as version 2, and every cue plays
// the same, at its full state and through its fade, from the saved file.
TEST(Palettes, VersionOneDemoMigratesWithoutLoss) {
  const auto demo = std::filesystem::path(HAZE_SOURCE_DIR) / "tests/data/shows/demo-v1.haze.json";
  auto v1 = loadShow(demo);
  ASSERT_TRUE(v1.ok()) << v1.error().str();
  EXPECT_EQ(v1->fileVersion, 1);
  auto profiles = loadProfiles(*v1);
  ASSERT_TRUE(profiles.ok());
  test::ScratchDir dir;
  Show copy = *v1;
  ASSERT_TRUE(saveShow(copy, dir.path / "demo.haze.json").ok());
  auto v2 = loadShow(dir.path / "demo.haze.json");
  ASSERT_TRUE(v2.ok()) << v2.error().str();
  EXPECT_EQ(v2->fileVersion, 2);
  auto profiles2 = loadProfiles(*v2);
  ASSERT_TRUE(profiles2.ok());
  ASSERT_EQ(v2->cueLists.size(), v1->cueLists.size());
  for (size_t l = 0; l < v1->cueLists.size(); ++l)
    for (size_t c = 0; c < v1->cueLists[l].cues.size(); ++c)
      for (double t : {0.0, 0.5, 1.0, 2.5, 4.0, 7.0, 1e6})
        EXPECT_EQ(stateAt(*v1, *profiles, v1->cueLists[l], c, t), stateAt(*v2, *profiles2, v2->cueLists[l], c, t))
            << "cue " << v1->cueLists[l].cues[c].number << " at " << t;
  EXPECT_TRUE(validateShowFile(dir.path / "demo.haze.json").empty());
  // A version-1 file cannot hold the version-2 sections.
  ShowParse p = parseShowText(R"({"format": "haze-show", "version": 1, "profiles": {}, "fixtures": [], "groups": []})",
                              dir.path / "old.haze.json");
  ASSERT_EQ(p.problems.size(), 1u);
  EXPECT_EQ(p.problems[0].place, "/groups");
}

}  // namespace
}  // namespace haze
