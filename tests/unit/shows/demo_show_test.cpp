// The bundled demo show (examples/demo/demo.haze.json) must validate, load
// with its profiles, play every cue, and survive a save/load round trip unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "shows/playback.h"
#include "shows/show_json.h"
#include "shows/show_validate.h"

namespace haze {
namespace {

const std::filesystem::path kDemo = std::filesystem::path(HAZE_SOURCE_DIR) / "examples/demo/demo.haze.json";

std::string listed(const std::vector<Error>& problems) {
  std::string s;
  for (const Error& e : problems) s += "  " + e.str() + "\n";
  return s;
}

TEST(DemoShow, Validates) {
  ASSERT_TRUE(std::filesystem::exists(kDemo)) << kDemo << " is missing";
  auto problems = validateShowFile(kDemo);
  EXPECT_TRUE(problems.empty()) << listed(problems);
}

// The demo shows what version 2 can say: groups, palettes and an effect (docs/gui.md).
TEST(DemoShow, UsesGroupsPalettesAndAnEffect) {
  auto show = loadShow(kDemo);
  ASSERT_TRUE(show.ok()) << show.error().str();
  EXPECT_EQ(show->fileVersion, 2);
  EXPECT_EQ(show->groups.size(), 3u);
  EXPECT_GE(show->palettes.size(), 5u);
  size_t references = 0, effects = 0;
  for (const CueList& list : show->cueLists)
    for (const Cue& cue : list.cues) {
      effects += cue.effects.size();
      for (const auto& [id, values] : cue.values)
        for (const std::string* name : {&values.palettes.all, &values.palettes.position, &values.palettes.color, &values.palettes.beam})
          references += !name->empty();
    }
  EXPECT_GT(references, 20u);
  EXPECT_EQ(effects, 1u);
}

TEST(DemoShow, PlaysEveryCueAndRoundTrips) {
  auto show = loadShow(kDemo);
  ASSERT_TRUE(show.ok()) << show.error().str();
  auto profiles = loadProfiles(*show);
  ASSERT_TRUE(profiles.ok()) << profiles.error().str();
  ASSERT_FALSE(show->cueLists.empty());
  for (const CueList& list : show->cueLists)
    for (size_t i = 0; i < list.cues.size(); ++i) {
      StageState full = trackedState(*show, *profiles, list, i);
      EXPECT_EQ(full.size(), show->fixtures.size());
      StageState later = stateAt(*show, *profiles, list, i, 1e6);
      // An effect keeps moving after the fade (the demo has one circle, on the Beams in 4.5):
      // its group's pan and tilt lie on the circle round the tracked aim; all else is tracked.
      for (const EffectDef& effect : list.cues[i].effects) {
        ASSERT_EQ(effect.shape, EffectShape::Circle);
        const GroupDef* group = show->findGroup(effect.group);
        ASSERT_NE(group, nullptr) << effect.group;
        for (int id : group->fixtures) {
          const double dp = later.at(id).panDeg - full.at(id).panDeg, dt = later.at(id).tiltDeg - full.at(id).tiltDeg;
          EXPECT_NEAR(std::hypot(dp, dt), effect.size, 1e-3) << "fixture " << id;
          later.at(id).panDeg = full.at(id).panDeg;
          later.at(id).tiltDeg = full.at(id).tiltDeg;
        }
      }
      EXPECT_EQ(later, full) << list.name << " cue " << list.cues[i].number;
    }
  std::string text = showToText(*show);
  ShowParse again = parseShowText(text, kDemo);
  ASSERT_TRUE(again.problems.empty()) << listed(again.problems);
  EXPECT_EQ(showToText(again.show), text);
  EXPECT_TRUE(validateShowText(text, kDemo).empty());
}

}  // namespace
}  // namespace haze
