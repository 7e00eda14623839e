// Hazers in cues (docs/shows.md, "Hazers in cues"): read and written back, refused where they
// name no hazer or leave 0..1, tracked through a list, and the schedule a GO makes against the
// closed form of a delayed linear fade.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "show_test_data.h"
#include "shows/hazer_levels.h"
#include "shows/show_json.h"

namespace haze {
namespace {

// The valid show in version 2 with one hazer (warmup 30 s), and `hazers` on cues of Main by index.
std::string withHazers(const std::map<int, std::string>& byCue, int version = 2) {
  auto text = readShowBytes(test::validShowPath());
  EXPECT_TRUE(text.ok());
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(*text);
  j["version"] = version;
  j["atmosphere"]["density"] =
      nlohmann::ordered_json::parse(R"({"warmup": 30, "hazers": [{"position": [0, 0.5, 0], "output": 2}]})");
  for (const auto& [cue, hazers] : byCue) j["cue_lists"][0]["cues"][cue]["hazers"] = nlohmann::ordered_json::parse(hazers);
  return j.dump(2);
}

std::string problemsOf(const std::string& text) {
  std::string all;
  for (const Error& e : parseShowText(text, test::validShowPath()).problems) all += e.str() + "\n";
  return all;
}

TEST(HazerLevels, ReadAndWrittenBack) {
  ShowParse p = parseShowText(withHazers({{0, R"({"1": {"output": 0.25}})"}, {2, R"({"1": {"output": 1, "fan": 0.5}})"}}),
                              test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  const CueList& main = p.show.cueLists[0];
  ASSERT_EQ(main.cues[0].hazers.size(), 1u);
  EXPECT_EQ(main.cues[0].hazers.at(1), (HazerCueDef{0.25f, std::nullopt}));
  EXPECT_EQ(main.cues[2].hazers.at(1), (HazerCueDef{1.0f, 0.5f}));
  EXPECT_TRUE(main.cues[1].hazers.empty());
  const std::string text = showToText(p.show);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty()) << q.problems[0].str();
  EXPECT_EQ(q.show.cueLists[0].cues[2].hazers, main.cues[2].hazers);
  EXPECT_EQ(showToText(q.show), text);
}

TEST(HazerLevels, BadLevelsNameTheirPlace) {
  const std::string missing = problemsOf(withHazers({{1, R"({"2": {"output": 1}})"}}));
  EXPECT_NE(missing.find("/cue_lists/0/cues/1/hazers/2: hazer 2 does not exist: atmosphere.density has 1 hazer"),
            std::string::npos) << missing;
  const std::string high = problemsOf(withHazers({{1, R"({"1": {"fan": 1.5}})"}}));
  EXPECT_NE(high.find("/cue_lists/0/cues/1/hazers/1/fan"), std::string::npos) << high;
  EXPECT_NE(problemsOf(withHazers({{1, R"({"01": {"fan": 1}})"}})).find("expected a hazer number"), std::string::npos);
  EXPECT_NE(problemsOf(withHazers({{1, R"({"1": {"smoke": 1}})"}})).find("/cue_lists/0/cues/1/hazers/1/smoke"),
            std::string::npos);
  const std::string old = problemsOf(withHazers({{1, R"({"1": {"output": 1}})"}}, 1));
  EXPECT_NE(old.find("needs format version 2"), std::string::npos) << old;
}

TEST(HazerLevels, TrackThroughTheList) {
  ShowParse p = parseShowText(withHazers({{0, R"({"1": {"output": 0.25, "fan": 0}})"}, {2, R"({"1": {"output": 1}})"}}),
                              test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  const CueList& main = p.show.cueLists[0];
  EXPECT_EQ(trackedHazers(main, 1).at(1), (HazerCueDef{0.25f, 0.0f}));
  EXPECT_EQ(trackedHazers(main, 4).at(1), (HazerCueDef{1.0f, 0.0f}));  // the fan tracks from cue 1
  EXPECT_TRUE(trackedHazers(p.show.cueLists[1], 0).empty());
}

TEST(HazerLevels, AGoFadesFromTheCueBeforeOverTheCuesDelayAndFade) {
  ShowParse p = parseShowText(withHazers({{0, R"({"1": {"output": 0.25, "fan": 0}})"}, {2, R"({"1": {"output": 1}})"}}),
                              test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  Show& show = p.show;
  CueList& main = show.cueLists[0];
  main.cues[2].delayS = 2.0;
  main.cues[2].fadeS = 8.0;
  // GO into the third cue at playback time 0, from the second's state: simulation time 30 + t.
  const HazerSchedule s = hazerSchedule(show, {{&main, 1}}, {{&main, 2, 0.0}});
  EXPECT_FLOAT_EQ(s.at(0, 0.0).output, 0.25f);    // the warmup at cue 2's levels
  EXPECT_FLOAT_EQ(s.at(0, 31.5).output, 0.25f);   // in the delay
  EXPECT_FLOAT_EQ(s.at(0, 36.0).output, 0.25f + 0.75f * 0.5f);
  EXPECT_FLOAT_EQ(s.at(0, 36.0).fan, 0.0f);       // the fan is not the cue's to move
  EXPECT_FLOAT_EQ(s.at(0, 50.0).output, 1.0f);
  // Cue 3's own state from the start.
  EXPECT_FLOAT_EQ(hazerSchedule(show, {{&main, 2}}, {}).at(0, 0.0).output, 1.0f);
  // A later GO into cue 5 (tracking cue 3's output) leaves it; a show without levels has none.
  EXPECT_FLOAT_EQ(hazerSchedule(show, {{&main, 1}}, {{&main, 2, 0.0}, {&main, 4, 5.0}}).at(0, 100.0).output, 1.0f);
  for (CueList& l : show.cueLists)
    for (Cue& c : l.cues) c.hazers.clear();
  EXPECT_TRUE(hazerSchedule(show, {{&main, 1}}, {{&main, 2, 0.0}}).empty());
}

}  // namespace
}  // namespace haze
