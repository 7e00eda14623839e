// Cell values in shows (docs/cells.md): read from and saved to the file, tracked and faded per
// cell, and refused past the profile's cells.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>

#include "show_test_data.h"
#include "shows/playback.h"
#include "shows/show_save.h"
#include "shows/show_validate.h"

namespace haze {
namespace {

constexpr const char* kShow = R"({
  "format": "haze-show", "version": 1,
  "profiles": { "par": { "format": "haze-fixture", "version": 1, "name": "Par",
                         "photometry": { "beam_angle": 20, "field_angle": 30, "peak_candela": 1000 } } },
  "fixtures": [ { "id": 1, "name": "A", "profile": "par", "position": [0, 5, 0] } ],
  "cue_lists": [ { "name": "Main", "cues": [
    { "number": "1", "values": { "1": { "intensity": 1, "cells": { "2": { "intensity": 0.5, "color": [1, 0, 0] } } } } },
    { "number": "2", "fade": 2, "values": { "1": { "cells": { "1": { "intensity": 0 }, "2": { "intensity": 1 } } } } }
  ] } ]
})";

Show writeAndLoad(const test::ScratchDir& dir, const std::string& text) {
  const auto file = dir.path / "cells.haze.json";
  std::ofstream(file) << text;
  auto show = loadShow(file);
  EXPECT_TRUE(show.ok()) << (show ? "" : show.error().str());
  return show ? *show : Show{};
}

TEST(Cells, CueValuesTrackFadeAndSaveBack) {
  test::ScratchDir dir;
  Show show = writeAndLoad(dir, kShow);
  ASSERT_EQ(show.cueLists.size(), 1u);
  const CueValues& v = show.cueLists[0].cues[0].values.at(1);
  ASSERT_EQ(v.cells.count(1), 1u);  // "2" in the file is index 1
  EXPECT_FLOAT_EQ(*v.cells.at(1).intensity, 0.5f);

  auto profiles = loadProfiles(show);
  ASSERT_TRUE(profiles.ok()) << profiles.error().str();
  const CueList& list = show.cueLists[0];
  const StageState one = trackedState(show, *profiles, list, 0);
  ASSERT_EQ(one.at(1).cells.size(), 2u);
  EXPECT_FLOAT_EQ(one.at(1).cells[0].intensity, 1.0f);  // unset: 1 and white
  EXPECT_EQ(one.at(1).cells[1].color, glm::vec3(1, 0, 0));
  // Cue 2 at half its fade: cell 1 from 1 to 0, cell 2 from 0.5 to 1; cell 2's colour tracks.
  const StageState half = stateAt(show, *profiles, list, 1, 1.0);
  EXPECT_FLOAT_EQ(half.at(1).cells[0].intensity, 0.5f);
  EXPECT_FLOAT_EQ(half.at(1).cells[1].intensity, 0.75f);
  EXPECT_EQ(half.at(1).cells[1].color, glm::vec3(1, 0, 0));

  ASSERT_TRUE(saveShow(show, dir.path / "saved.haze.json").ok());
  auto again = loadShow(dir.path / "saved.haze.json");
  ASSERT_TRUE(again.ok()) << again.error().str();
  EXPECT_EQ(again->cueLists[0].cues[0].values.at(1), v);
  EXPECT_EQ(again->cueLists[0].cues[1].values.at(1), show.cueLists[0].cues[1].values.at(1));
}

TEST(Cells, RefusesCellsTheProfileLacksAndBadNumbers) {
  test::ScratchDir dir;
  Show show = writeAndLoad(dir, kShow);
  auto profiles = loadProfiles(show);
  ASSERT_TRUE(profiles.ok()) << profiles.error().str();
  const auto problems = validateShow(show, *profiles);  // the parametric Par has no cells
  ASSERT_FALSE(problems.empty());
  EXPECT_EQ(problems.front().place, "/cue_lists/0/cues/0/values/1/cells/2") << problems.front().str();
  EXPECT_NE(problems.front().message.find("has no cells"), std::string::npos) << problems.front().str();

  std::string bad = kShow;
  bad.replace(bad.find("\"2\": { \"intensity\": 0.5"), 3, "\"0\"");
  std::ofstream(dir.path / "bad.haze.json") << bad;
  auto refused = loadShow(dir.path / "bad.haze.json");
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("expected a cell number"), std::string::npos) << refused.error().str();
}

}  // namespace
}  // namespace haze
