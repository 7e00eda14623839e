// The cue range played to video: GO times by hand from the cues' delay, fade, follow and the
// hold, and the same times driving CuePlayer land on the cue the timeline says.
#include <gtest/gtest.h>

#include "shows/cue_player.h"
#include "shows/cue_timeline.h"

namespace haze {
namespace {

CueList demoLikeList() {
  // The timing of examples/demo's Main list.
  CueList list;
  list.name = "Main";
  const struct { const char* number; double delay, fade; std::optional<double> follow; } cues[] = {
      {"1", 0, 5, {}}, {"2", 0, 6, {}}, {"3", 2, 8, {}}, {"4", 0, 3, 2.0}, {"4.5", 0, 5, {}}, {"5", 0, 4, {}}};
  for (const auto& c : cues) {
    Cue cue;
    cue.number = c.number;
    cue.delayS = c.delay;
    cue.fadeS = c.fade;
    cue.followS = c.follow;
    list.cues.push_back(cue);
  }
  return list;
}

TEST(CueTimeline, HoldsAfterManualCuesAndFollowsByThemselves) {
  const CueList list = demoLikeList();
  const CueTimeline t = playCueRange(Show{}, list, 0, 5, 2.0);
  ASSERT_EQ(t.gos.size(), 6u);
  const double at[] = {0, 7, 15, 27, 32, 39};  // 0+5+2, 7+6+2, 15+2+8+2, 27+3+follow 2, 32+5+2
  const bool byFollow[] = {false, false, false, false, true, false};
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(t.gos[i].cueIndex, i);
    EXPECT_DOUBLE_EQ(t.gos[i].atS, at[i]) << "cue " << list.cues[i].number;
    EXPECT_EQ(t.gos[i].byFollow, byFollow[i]) << "cue " << list.cues[i].number;
  }
  EXPECT_DOUBLE_EQ(t.endS, 45.0);  // 39 + 4 + hold 2
}

TEST(CueTimeline, ARangeEndingOnAFollowStopsWhenItWouldFire) {
  const CueList list = demoLikeList();
  const CueTimeline t = playCueRange(Show{}, list, 3, 3, 10.0);  // cue 4 alone: fade 3, follow 2
  ASSERT_EQ(t.gos.size(), 1u);
  EXPECT_DOUBLE_EQ(t.endS, 5.0);
  const CueTimeline single = playCueRange(Show{}, list, 1, 1, 0.0);  // cue 2, no hold: its fade only
  EXPECT_DOUBLE_EQ(single.endS, 6.0);
}

TEST(CueTimeline, DrivesThePlayerOntoTheCuesItNames) {
  const CueList list = demoLikeList();
  Show show;
  ProfileSet profiles;
  const CueTimeline t = playCueRange(Show{}, list, 1, 5, 1.0);
  CuePlayer player(show, profiles, list);
  player.jumpTo(0, 0.0);
  for (const CueGo& go : t.gos) {
    if (!go.byFollow) player.gotoCue(go.cueIndex, go.atS);
    player.update(go.atS);
    EXPECT_EQ(player.currentCue(), go.cueIndex) << "at " << go.atS;
  }
  player.update(t.endS);
  EXPECT_EQ(player.currentCue(), 5u);
}

}  // namespace
}  // namespace haze
