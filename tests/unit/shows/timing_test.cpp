// A cue's own timing (docs/show-format.md, "Timing"): intensity up and down times, position,
// colour and beam times, a fan of delays and fades across a group's order, and the fade curves,
// each checked against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "show_test_data.h"
#include "shows/cue_player.h"
#include "shows/cue_timeline.h"
#include "shows/playback.h"
#include "shows/show_json.h"
#include "shows/show_validate.h"

namespace haze {
namespace {

constexpr const char* kProfile = R"("spot": { "format": "haze-fixture", "version": 1, "name": "Spot",
  "photometry": { "beam_angle": 20, "field_angle": 30, "peak_candela": 1000 }, "zoom": { "min": 10, "max": 40 },
  "gobo_wheels": [ { "name": "G", "slots": [ { "name": "Open" }, { "name": "Dots" } ] } ] })";

Show load(const test::ScratchDir& dir, const std::string& text) {
  const auto file = dir.path / "timing.haze.json";
  std::ofstream(file) << text;
  auto show = loadShow(file);
  EXPECT_TRUE(show.ok()) << (show ? "" : show.error().str());
  return show ? *show : Show{};
}

double sCurve(double p) { return p * p * (3.0 - 2.0 * p); }

TEST(Timing, CurvesFollowTheirClosedForms) {
  for (double p = 0.0; p <= 1.0; p += 0.0625) {
    EXPECT_DOUBLE_EQ(curveProgress(FadeCurve::Linear, p), p);
    EXPECT_DOUBLE_EQ(curveProgress(FadeCurve::SCurve, p), 3 * p * p - 2 * p * p * p);
  }
  EXPECT_EQ(curveProgress(FadeCurve::SCurve, -1.0), -1.0);  // the delay stays the delay
  // An s-curve cue fading intensity 0 -> 1 over 4 s after a 1 s delay, and the same cue linear.
  test::ScratchDir dir;
  for (const char* curve : {"linear", "s-curve"}) {
    const Show show = load(dir, std::string(R"({"format": "haze-show", "version": 2, "profiles": {)") + kProfile +
                                    R"(}, "fixtures": [ { "id": 1, "profile": "spot" } ],
      "cue_lists": [ { "name": "Main", "cues": [ { "number": "1", "delay": 1, "fade": 4,
        "timing": { "curve": ")" + curve + R"(" }, "values": { "1": { "intensity": 1, "pan": 80 } } } ] } ] })");
    auto profiles = loadProfiles(show);
    ASSERT_TRUE(profiles.ok());
    for (double t = 0.0; t <= 6.0; t += 0.125) {
      const double p = std::clamp((t - 1.0) / 4.0, 0.0, 1.0);
      const double want = std::string(curve) == "linear" ? p : sCurve(p);
      const Attributes a = stateAt(show, *profiles, show.cueLists[0], 0, t).at(1);
      EXPECT_NEAR(a.intensity, t < 1.0 ? 0.0 : want, 1e-6) << curve << " at " << t;
      EXPECT_NEAR(a.panDeg, t < 1.0 ? 0.0 : 80.0 * want, 1e-4) << curve << " at " << t;
    }
  }
}

// Cue 1 snaps fixture 1 up and sets a look; cue 2 takes 1 down and 2 up with separate up and
// down times, and moves, colours and changes the beam of fixture 1 on their own times.
constexpr const char* kParts = R"(
  "fixtures": [ { "id": 1, "profile": "spot" }, { "id": 2, "profile": "spot" } ],
  "cue_lists": [ { "name": "Main", "cues": [
    { "number": "1", "values": { "1": { "intensity": 1, "pan": 0, "color": [1, 1, 1], "zoom": 10 } } },
    { "number": "2", "delay": 0.5, "fade": 10, "follow": 1,
      "timing": { "up": { "fade": 2 }, "down": { "delay": 1, "fade": 6 }, "position": { "delay": 2, "fade": 4 },
                  "color": { "fade": 8 }, "beam": { "delay": 3, "fade": 1 } },
      "values": { "1": { "intensity": 0, "pan": 40, "color": [1, 0, 0], "zoom": 30, "gobo": "Dots" },
                  "2": { "intensity": 1 } } },
    { "number": "3", "values": { "2": { "intensity": 0.5 } } } ] } ] })";

TEST(Timing, EachPartRunsOnItsOwnTimes) {
  test::ScratchDir dir;
  const Show show = load(dir, std::string(R"({"format": "haze-show", "version": 2, "profiles": {)") + kProfile + "}," + kParts);
  auto profiles = loadProfiles(show);
  ASSERT_TRUE(profiles.ok());
  const CueList& list = show.cueLists[0];
  auto at = [&](double t) { return stateAt(show, *profiles, list, 1, t); };
  // Up: the cue's delay 0.5, fade 2. Down: delay 1, fade 6. Position: delay 2, fade 4. Colour:
  // delay 0.5, fade 8. Beam: delay 3, fade 1 (the gobo switches at 3).
  for (double t : {0.25, 0.75, 1.5, 2.5, 3.0, 3.5, 5.0, 7.5, 9.0}) {
    auto lin = [&](double delay, double fade) { return std::clamp((t - delay) / fade, 0.0, 1.0); };
    const StageState s = at(t);
    EXPECT_NEAR(s.at(2).intensity, lin(0.5, 2), 1e-6) << t;
    EXPECT_NEAR(s.at(1).intensity, 1.0 - lin(1, 6), 1e-6) << t;
    EXPECT_NEAR(s.at(1).panDeg, 40.0 * lin(2, 4), 1e-4) << t;
    EXPECT_NEAR(s.at(1).color.y, 1.0 - lin(0.5, 8), 1e-6) << t;
    EXPECT_NEAR(*s.at(1).zoomDeg, 10.0 + 20.0 * lin(3, 1), 1e-4) << t;
    EXPECT_EQ(s.at(1).gobo, t >= 3.0 ? "Dots" : "Open") << t;
  }
  // Every part has its own fade here, so the cue lasts until its last part ends (colour: 0.5 + 8),
  // not the cue's own 0.5 + 10; its follow fires 1 s after that.
  EXPECT_DOUBLE_EQ(cueDurationS(show, list.cues[1]), 8.5);
  CuePlayer player(show, *profiles, list);
  player.jumpTo(0, 0.0);
  player.go(100.0);
  ASSERT_TRUE(player.nextFollowAtS());
  EXPECT_DOUBLE_EQ(*player.nextFollowAtS(), 100.0 + 8.5 + 1.0);
  EXPECT_TRUE(player.fading(108.4));
  EXPECT_FALSE(player.fading(108.6));
  EXPECT_EQ(player.state(102.0), at(2.0));  // the player and stateAt agree
}

// Twelve fixtures in a group whose order is not their id order; cue 2 snaps each up 0.25 s
// after the one before it in the group's order (after the cue's 0.5 s delay), and cue 3 fades
// them down with fades that grow 0.5 s per fixture.
std::string fanShow() {
  std::string fixtures, order;
  for (int i = 0; i < 12; ++i) {
    fixtures += std::string(i ? ", " : "") + "{ \"id\": " + std::to_string(101 + i) + ", \"profile\": \"spot\" }";
    order += std::string(i ? ", " : "") + std::to_string(112 - ((i * 5) % 12));  // a permutation of 101..112
  }
  return std::string(R"({"format": "haze-show", "version": 2, "profiles": {)") + kProfile + "}, \"fixtures\": [" +
         fixtures + "], \"groups\": [ { \"name\": \"Row\", \"fixtures\": [" + order + R"(] } ],
    "cue_lists": [ { "name": "Main", "cues": [
      { "number": "1", "values": {} },
      { "number": "2", "delay": 0.5, "timing": { "fan": { "group": "Row", "delay": 0.25 } },
        "values": { "101": { "intensity": 1 }, "102": { "intensity": 1 }, "103": { "intensity": 1 },
                    "104": { "intensity": 1 }, "105": { "intensity": 1 }, "106": { "intensity": 1 },
                    "107": { "intensity": 1 }, "108": { "intensity": 1 }, "109": { "intensity": 1 },
                    "110": { "intensity": 1 }, "111": { "intensity": 1 }, "112": { "intensity": 1 } } },
      { "number": "3", "fade": 1, "timing": { "fan": { "group": "Row", "fade": 0.5 } },
        "values": { "101": { "intensity": 0 }, "102": { "intensity": 0 }, "103": { "intensity": 0 },
                    "104": { "intensity": 0 }, "105": { "intensity": 0 }, "106": { "intensity": 0 },
                    "107": { "intensity": 0 }, "108": { "intensity": 0 }, "109": { "intensity": 0 },
                    "110": { "intensity": 0 }, "111": { "intensity": 0 }, "112": { "intensity": 0 } } } ] } ] })";
}

TEST(Timing, AFanLandsEachFixtureAtItsOwnTime) {
  test::ScratchDir dir;
  const Show show = load(dir, fanShow());
  auto profiles = loadProfiles(show);
  ASSERT_TRUE(profiles.ok());
  const CueList& list = show.cueLists[0];
  const std::vector<int>& order = show.groups[0].fixtures;
  ASSERT_EQ(order.size(), 12u);
  for (size_t k = 0; k < 12; ++k) {
    const double landS = 0.5 + 0.25 * static_cast<double>(k);
    const StageState before = stateAt(show, *profiles, list, 1, landS - 0.001);
    const StageState after = stateAt(show, *profiles, list, 1, landS + 0.001);
    for (size_t j = 0; j < 12; ++j) {
      EXPECT_EQ(before.at(order[j]).intensity, j < k ? 1.0f : 0.0f) << "fixture " << order[j] << " at " << landS - 0.001;
      EXPECT_EQ(after.at(order[j]).intensity, j <= k ? 1.0f : 0.0f) << "fixture " << order[j] << " at " << landS + 0.001;
    }
  }
  EXPECT_DOUBLE_EQ(cueDurationS(show, list.cues[1]), 0.5 + 11 * 0.25);
  // Fade fan: the k-th fixture fades over 1 + 0.5 k seconds, all from GO.
  for (double t : {0.3, 0.9, 2.0, 4.5}) {
    const StageState s = stateAt(show, *profiles, list, 2, t);
    for (size_t k = 0; k < 12; ++k)
      EXPECT_NEAR(s.at(order[k]).intensity, 1.0 - std::min(1.0, t / (1.0 + 0.5 * static_cast<double>(k))), 1e-6);
  }
  const CueTimeline timeline = playCueRange(show, list, 1, 2, 0.0);
  EXPECT_DOUBLE_EQ(timeline.gos[1].atS, 0.5 + 11 * 0.25);
  EXPECT_DOUBLE_EQ(timeline.endS, 0.5 + 11 * 0.25 + 1.0 + 11 * 0.5);
}

TEST(Timing, SavesBackAndRefusesWhatItCannotPlay) {
  test::ScratchDir dir;
  const Show show = load(dir, std::string(R"({"format": "haze-show", "version": 2, "profiles": {)") + kProfile + "}," + kParts);
  const std::string text = showToText(show);
  EXPECT_NE(text.find("\"timing\""), std::string::npos);
  ShowParse again = parseShowText(text, dir.path / "again.haze.json");
  ASSERT_TRUE(again.problems.empty()) << again.problems[0].str();
  EXPECT_EQ(again.show.cueLists[0].cues[1].timing, show.cueLists[0].cues[1].timing);
  EXPECT_EQ(showToText(again.show), text);
  const Show fan = load(dir, fanShow());
  const std::string fanText = showToText(fan);
  EXPECT_EQ(showToText(parseShowText(fanText, dir.path / "fan.haze.json").show), fanText);

  auto firstProblem = [&](std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    const auto file = dir.path / "bad.haze.json";
    std::ofstream(file) << text;
    auto bad = loadShow(file);
    return bad ? Error{} : bad.error();
  };
  Error e = firstProblem(fanShow(), "\"group\": \"Row\", \"delay\"", "\"group\": \"Rwo\", \"delay\"");
  EXPECT_EQ(e.place, "/cue_lists/0/cues/1/timing/fan/group");
  EXPECT_EQ(e.message, "the fan names group \"Rwo\", which is not in /groups; expected one of: \"Row\"");
  e = firstProblem(fanShow(), "\"delay\": 0.25", "\"delay\": -0.25");
  EXPECT_EQ(e.place, "/cue_lists/0/cues/1/timing/fan/delay");
  e = firstProblem(std::string(R"({"format": "haze-show", "version": 2, "profiles": {)") + kProfile + "}," + kParts,
                   "\"color\": { \"fade\": 8 }", "\"color\": { \"fade\": 8 }, \"curve\": \"cosine\"");
  EXPECT_EQ(e.place, "/cue_lists/0/cues/1/timing/curve");
  EXPECT_EQ(e.message, "unknown fade curve \"cosine\"; expected linear or s-curve");
  e = firstProblem(std::string(R"({"format": "haze-show", "version": 1, "profiles": {)") + kProfile + "}," + kParts,
                   "\"number\": \"3\"", "\"number\": \"3\"");
  EXPECT_EQ(e.place, "/cue_lists/0/cues/1/timing");
}

}  // namespace
}  // namespace haze
