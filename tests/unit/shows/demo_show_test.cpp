// The bundled demo show (examples/demo/demo.haze.json, written by the lead) must validate, load
// with its profiles, play every cue, and survive a save/load round trip unchanged.
#include <gtest/gtest.h>

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
      EXPECT_EQ(stateAt(*show, *profiles, list, i, 1e6), full) << list.name << " cue " << list.cues[i].number;
    }
  std::string text = showToText(*show);
  ShowParse again = parseShowText(text, kDemo);
  ASSERT_TRUE(again.problems.empty()) << listed(again.problems);
  EXPECT_EQ(showToText(again.show), text);
  EXPECT_TRUE(validateShowText(text, kDemo).empty());
}

}  // namespace
}  // namespace haze
