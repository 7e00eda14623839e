// Effects (docs/show-format.md, "Effects"): every shape's value at t against its closed form,
// the phase spread across the group's order, the growth with the cue's fade, the random shape's
// determinism, and the player showing the same as stateAt.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "show_test_data.h"
#include "shows/cue_player.h"
#include "shows/effects.h"
#include "shows/playback.h"
#include "shows/show_json.h"

namespace haze {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Four fixtures in the group's order 4, 3, 2, 1; cue 1 fades them in over 2 s with five effects.
constexpr const char* kShow = R"({"format": "haze-show", "version": 2,
  "profiles": { "spot": { "format": "haze-fixture", "version": 1, "name": "Spot",
    "photometry": { "beam_angle": 20, "field_angle": 30, "peak_candela": 1000 }, "zoom": { "min": 10, "max": 40 } } },
  "fixtures": [ { "id": 1, "profile": "spot" }, { "id": 2, "profile": "spot" },
                { "id": 3, "profile": "spot" }, { "id": 4, "profile": "spot" } ],
  "groups": [ { "name": "Back", "fixtures": [4, 3, 2, 1] } ],
  "cue_lists": [ { "name": "Main", "cues": [
    { "number": "1", "fade": 2,
      "values": { "1": { "intensity": 0.5, "iris": 0.5 }, "2": { "intensity": 0.5, "iris": 0.5 },
                  "3": { "intensity": 0.5, "iris": 0.5 }, "4": { "intensity": 0.5, "iris": 0.5 } },
      "effects": [
        { "shape": "sine", "attribute": "intensity", "group": "Back", "rate": 0.5, "size": 0.25, "spread": 360 },
        { "shape": "circle", "group": "Back", "rate": -0.25, "size": 10, "phase": 90, "spread": 180 },
        { "shape": "square", "attribute": "iris", "group": "Back", "rate": 1.5, "size": 0.2 },
        { "shape": "ramp", "attribute": "gobo_rotation", "group": "Back", "rate": 1, "size": 90, "spread": 90 },
        { "shape": "random", "attribute": "zoom", "group": "Back", "rate": 2, "size": 5, "seed": 7 } ] } ] } ] })";

double frac(double x) { return x - std::floor(x); }

TEST(Effects, EachShapeMatchesItsClosedForm) {
  test::ScratchDir dir;
  std::ofstream(dir.path / "fx.haze.json") << kShow;
  auto show = loadShow(dir.path / "fx.haze.json");
  ASSERT_TRUE(show.ok()) << show.error().str();
  auto profiles = loadProfiles(*show);
  ASSERT_TRUE(profiles.ok());
  const CueList& list = show->cueLists[0];
  const std::vector<int> order{4, 3, 2, 1};
  for (double t : {0.0, 0.37, 1.3, 2.0, 3.71, 10.2, 47.9}) {
    const StageState s = stateAt(*show, *profiles, list, 0, t);
    const double g = std::min(1.0, t / 2.0);  // the fade's progress: the effects grow with it
    for (size_t k = 0; k < 4; ++k) {
      const Attributes& a = s.at(order[k]);
      const double kk = static_cast<double>(k);
      const double intensity = 0.5 * g + 0.25 * g * std::sin(2 * kPi * (0.5 * t + kk * 360 / 4 / 360));
      EXPECT_NEAR(a.intensity, intensity, 1e-6) << "t " << t << " k " << k;
      const double xc = -0.25 * t + (90 + kk * 180 / 4) / 360;
      EXPECT_NEAR(a.panDeg, 10 * g * std::sin(2 * kPi * xc), 1e-4) << "t " << t << " k " << k;
      EXPECT_NEAR(a.tiltDeg, 10 * g * std::cos(2 * kPi * xc), 1e-4) << "t " << t << " k " << k;
      const double iris = 1.0 + (0.5 - 1.0) * g + 0.2 * g * (frac(1.5 * t) < 0.5 ? 1 : -1);
      EXPECT_NEAR(a.iris, iris, 1e-6) << "t " << t << " k " << k;
      EXPECT_NEAR(a.goboRotationDeg, 90 * g * (2 * frac(t + kk * 90 / 4 / 360) - 1), 1e-3) << "t " << t << " k " << k;
      // Random: within size of the profile's field angle, and the same value within a cycle.
      ASSERT_TRUE(a.zoomDeg);
      EXPECT_LE(std::abs(*a.zoomDeg - 30.0), 5.0 * g + 1e-4);
    }
  }
  // The player shows what stateAt shows, GO at any clock time.
  CuePlayer player(*show, *profiles, list);
  player.go(100.0);
  EXPECT_EQ(player.state(103.71), stateAt(*show, *profiles, list, 0, 3.71));
}

// A colour wave: two fixtures half a cycle apart run from the cue's white towards red, then
// blue (a sine through two colours), and a ramp through three; depth 0.8 grown with the fade.
constexpr const char* kColorShow = R"({"format": "haze-show", "version": 2,
  "profiles": { "wash": { "format": "haze-fixture", "version": 1, "name": "Wash",
    "photometry": { "beam_angle": 20, "field_angle": 30, "peak_candela": 1000 } } },
  "fixtures": [ { "id": 1, "profile": "wash" }, { "id": 2, "profile": "wash" }, { "id": 3, "profile": "wash" } ],
  "groups": [ { "name": "Pair", "fixtures": [1, 2] }, { "name": "Third", "fixtures": [3] } ],
  "cue_lists": [ { "name": "Main", "cues": [
    { "number": "1", "fade": 2,
      "values": { "1": { "intensity": 1, "color": [1, 1, 1] }, "2": { "intensity": 1, "color": [1, 1, 1] },
                  "3": { "intensity": 1, "color": [0.5, 0.5, 0.5] } },
      "effects": [
        { "shape": "sine", "attribute": "color", "group": "Pair", "rate": 0.5, "size": 0.8, "spread": 180,
          "colors": [[1, 0, 0], [0, 0, 1]] },
        { "shape": "ramp", "attribute": "color", "group": "Third", "rate": 0.25, "size": 1,
          "colors": [[1, 0, 0], [0, 1, 0], [0, 0, 1]] } ] } ] } ] })";

TEST(Effects, ColourWavesRunThroughTheirColours) {
  test::ScratchDir dir;
  std::ofstream(dir.path / "colour.haze.json") << kColorShow;
  auto show = loadShow(dir.path / "colour.haze.json");
  ASSERT_TRUE(show.ok()) << show.error().str();
  auto profiles = loadProfiles(*show);
  ASSERT_TRUE(profiles.ok());
  const glm::vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1), white(1);
  for (double t : {0.0, 0.4, 1.0, 2.0, 2.9, 5.25, 13.6}) {
    const StageState s = stateAt(*show, *profiles, show->cueLists[0], 0, t);
    const float depth = static_cast<float>(0.8 * std::min(1.0, t / 2.0));
    for (int k = 0; k < 2; ++k) {
      const double w = std::sin(2 * kPi * (0.5 * t + k * 180.0 / 2 / 360));
      const glm::vec3 target = red + (blue - red) * static_cast<float>((w + 1) / 2);
      const glm::vec3 want = white + (target - white) * depth;
      const glm::vec3 got = s.at(k + 1).color;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5) << "t " << t << " fixture " << k + 1;
    }
    // The ramp: -1..1 over each 4 s cycle is red -> green -> blue; depth 1 replaces the grey.
    const double u = frac(0.25 * t) * 2;  // 0..2 along the three colours
    const glm::vec3 target = u < 1 ? red + (green - red) * static_cast<float>(u) : green + (blue - green) * static_cast<float>(u - 1);
    const float g = static_cast<float>(std::min(1.0, t / 2.0));
    const glm::vec3 grey = glm::vec3(1.0f) + (glm::vec3(0.5f) - glm::vec3(1.0f)) * g;  // faded from white
    const glm::vec3 want = grey + (target - grey) * g;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.at(3).color[c], want[c], 1e-5) << "t " << t;
  }
  // Saved and read back the same; the colours are in the file.
  const std::string text = showToText(*show);
  EXPECT_NE(text.find("\"colors\""), std::string::npos);
  ShowParse again = parseShowText(text, dir.path / "again.haze.json");
  ASSERT_TRUE(again.problems.empty());
  EXPECT_EQ(again.show.cueLists[0].cues[0].effects, show->cueLists[0].cues[0].effects);

  auto problemAt = [&](const std::string& from, const std::string& to) {
    std::string t = kColorShow;
    t.replace(t.find(from), from.size(), to);
    ShowParse bad = parseShowText(t, dir.path / "bad.haze.json");
    return bad.problems.empty() ? std::string("(loaded)") : bad.problems[0].place + ": " + bad.problems[0].message;
  };
  EXPECT_EQ(problemAt(",\n          \"colors\": [[1, 0, 0], [0, 0, 1]]", ""),
            "/cue_lists/0/cues/0/effects/0/colors: a colour effect needs \"colors\": the [r, g, b] colours it runs "
            "through, at least two");
  EXPECT_EQ(problemAt("[[1, 0, 0], [0, 0, 1]]", "[[1, 0, 0]]"),
            "/cue_lists/0/cues/0/effects/0/colors: expected 2 to 64 colours, got 1");
  EXPECT_EQ(problemAt("\"size\": 0.8", "\"size\": 2"),
            "/cue_lists/0/cues/0/effects/0/size: expected a colour effect's depth from 0 to 1, got 2");
  EXPECT_EQ(problemAt("\"attribute\": \"color\", \"group\": \"Pair\"", "\"attribute\": \"iris\", \"group\": \"Pair\""),
            "/cue_lists/0/cues/0/effects/0/colors: \"colors\" belongs to a colour effect (attribute \"color\")");
}

TEST(Effects, RandomIsDeterministicPerCycleAndSeed) {
  EffectDef e;
  e.shape = EffectShape::Random;
  e.rateHz = 2.0;
  e.seed = 7;
  EXPECT_EQ(effectWave(e, 1, 4, 10.1), effectWave(e, 1, 4, 10.2));     // cycle 20 at 2 Hz
  EXPECT_NE(effectWave(e, 1, 4, 10.1), effectWave(e, 1, 4, 10.6));     // cycle 21
  EXPECT_NE(effectWave(e, 1, 4, 10.1), effectWave(e, 2, 4, 10.1));     // another fixture
  EffectDef other = e;
  other.seed = 8;
  EXPECT_NE(effectWave(e, 1, 4, 10.1), effectWave(other, 1, 4, 10.1));  // another seed
  double sum = 0.0, lo = 1.0, hi = -1.0;
  for (int c = 0; c < 4000; ++c) {
    const double w = effectWave(e, 0, 1, (c + 0.5) / 2.0);
    sum += w;
    lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  // Uniform on -1..1: the mean of 4000 has a standard deviation of 0.009; 0.05 is over 5 of them.
  EXPECT_LT(std::abs(sum / 4000), 0.05);
  EXPECT_GE(lo, -1.0);
  EXPECT_LT(hi, 1.0);
  EXPECT_LT(lo, -0.99);
  EXPECT_GT(hi, 0.99);
}

TEST(Effects, SaveBackAndBadEffectsAreRefused) {
  test::ScratchDir dir;
  ShowParse p = parseShowText(kShow, dir.path / "fx.haze.json");
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  const std::string text = showToText(p.show);
  ShowParse again = parseShowText(text, dir.path / "again.haze.json");
  ASSERT_TRUE(again.problems.empty());
  EXPECT_EQ(again.show.cueLists[0].cues[0].effects, p.show.cueLists[0].cues[0].effects);
  EXPECT_EQ(showToText(again.show), text);

  auto problemAt = [&](const std::string& from, const std::string& to) {
    std::string t = kShow;
    t.replace(t.find(from), from.size(), to);
    std::ofstream(dir.path / "bad.haze.json") << t;
    auto bad = loadShow(dir.path / "bad.haze.json");
    return bad ? std::string("(loaded)") : bad.error().place + ": " + bad.error().message;
  };
  EXPECT_EQ(problemAt("\"shape\": \"ramp\"", "\"shape\": \"saw\""),
            "/cue_lists/0/cues/0/effects/3/shape: unknown effect shape \"saw\"; expected sine, circle, square, ramp or random");
  EXPECT_EQ(problemAt("\"attribute\": \"iris\"", "\"attribute\": \"gobo\""),
            "/cue_lists/0/cues/0/effects/2/attribute: an effect cannot move \"gobo\"; expected intensity, pan, tilt, zoom, "
            "iris, frost, gobo_rotation, gobo2_rotation, prism_rotation or color (or a circle on position)");
  EXPECT_EQ(problemAt("\"group\": \"Back\", \"rate\": 1.5", "\"group\": \"Front\", \"rate\": 1.5"),
            "/cue_lists/0/cues/0/effects/2/group: the effect names group \"Front\", which is not in /groups; expected "
            "one of: \"Back\"");
}

}  // namespace
}  // namespace haze
