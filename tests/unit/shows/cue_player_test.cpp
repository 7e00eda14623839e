// The clock-driven player: GO, BACK, GOTO, follow chains, GO during a fade. Times are given, so
// nothing here waits; expected values follow by hand from the cues of valid.haze.json.
#include <gtest/gtest.h>

#include "show_test_data.h"
#include "shows/cue_player.h"

namespace haze {
namespace {

using test::loadValidShow;

TEST(CuePlayer, StartsDarkAndGoesCueByCue) {
  auto s = loadValidShow();
  CuePlayer p(s.show, s.profiles, s.main());
  EXPECT_FALSE(p.currentCue());
  EXPECT_EQ(p.state(0.0), defaultState(s.show));
  ASSERT_TRUE(p.go(10.0));                                   // cue 1, fade 2
  EXPECT_FLOAT_EQ(p.state(11.0).at(102).intensity, 0.25f);  // half way to 0.5
  EXPECT_EQ(p.state(12.0), trackedState(s.show, s.profiles, s.main(), 0));
  ASSERT_TRUE(p.go(20.0));                                   // cue 2: delay 1, fade 4
  EXPECT_FLOAT_EQ(p.state(20.5).at(101).panDeg, 0.0f);
  EXPECT_TRUE(p.fading(20.5));
  EXPECT_NEAR(p.state(23.0).at(101).panDeg, 45.0f, 1e-4);
  EXPECT_FALSE(p.fading(25.0));
  EXPECT_EQ(*p.currentCue(), 1u);
}

TEST(CuePlayer, FollowChainRunsByItself) {
  auto s = loadValidShow();
  CuePlayer p(s.show, s.profiles, s.main());
  ASSERT_TRUE(p.jumpTo(2, 0.0));  // full state of cue 3
  ASSERT_TRUE(p.go(100.0));       // cue 3.5: fade 2, follow 1 -> cue 4 GOes at 103
  EXPECT_EQ(*p.nextFollowAtS(), 103.0);
  EXPECT_EQ(*p.currentCue(), 3u);
  EXPECT_FLOAT_EQ(p.state(102.9).at(101).iris, 1.0f);
  EXPECT_EQ(*p.currentCue(), 3u);
  // Cue 4: fade 1 (iris 1 -> 0.5), follow 0.5 -> cue 5 GOes at 103 + 1 + 0.5 = 104.5.
  EXPECT_NEAR(p.state(103.5).at(101).iris, 0.75f, 1e-6);
  EXPECT_EQ(*p.currentCue(), 4u);
  EXPECT_EQ(*p.nextFollowAtS(), 104.5);
  // Cue 5: fade 3, 201 intensity 1 -> 0, no follow: the chain stops there.
  EXPECT_NEAR(p.state(106.0).at(201).intensity, 0.5f, 1e-6);
  EXPECT_EQ(*p.currentCue(), 5u);
  EXPECT_FALSE(p.nextFollowAtS());
  EXPECT_EQ(p.state(1000.0), trackedState(s.show, s.profiles, s.main(), 5));
  EXPECT_EQ(*p.currentCue(), 5u);
}

TEST(CuePlayer, FollowsFireAtTheirOwnTimeHoweverSeldomTheClockIsRead) {
  auto s = loadValidShow();
  CuePlayer once(s.show, s.profiles, s.main());
  once.jumpTo(2, 0.0);
  once.go(0.0);
  CuePlayer often(s.show, s.profiles, s.main());
  often.jumpTo(2, 0.0);
  often.go(0.0);
  for (int frame = 0; frame <= 600; ++frame) often.update(frame / 100.0);
  // One read at 6 s, after the whole chain, sees what 600 frames saw.
  EXPECT_EQ(once.state(6.0), often.state(6.0));
  EXPECT_EQ(once.currentCue(), often.currentCue());
}

TEST(CuePlayer, BackUsesThePreviousCuesTimes) {
  auto s = loadValidShow();
  CuePlayer p(s.show, s.profiles, s.main());
  p.jumpTo(5, 0.0);             // cue 5: 201 dark
  ASSERT_TRUE(p.back(10.0));    // to cue 4 with cue 4's fade of 1 s: 201 back to 1
  EXPECT_EQ(*p.currentCue(), 4u);
  EXPECT_NEAR(p.state(10.5).at(201).intensity, 0.5f, 1e-6);
  EXPECT_EQ(p.state(11.0), trackedState(s.show, s.profiles, s.main(), 4));
  // BACK arms no follow, even though cue 4 has one.
  EXPECT_FALSE(p.nextFollowAtS());
  EXPECT_EQ(*p.currentCue(), 4u);
  ASSERT_TRUE(p.jumpTo(0, 20.0));
  EXPECT_FALSE(p.back(21.0));  // nothing before the first cue
}

TEST(CuePlayer, GotoFadesFromTheCurrentStateWithTheTargetCuesTimes) {
  auto s = loadValidShow();
  CuePlayer p(s.show, s.profiles, s.main());
  p.jumpTo(0, 0.0);                  // cue 1: 101 pan 0, intensity 1, iris 1
  ASSERT_TRUE(p.gotoCue(6, 50.0));   // cue 10 (fade 2): pan -90, intensity 0.25, iris 0.5 tracked
  StageState mid = p.state(51.0);
  EXPECT_NEAR(mid.at(101).panDeg, -45.0f, 1e-4);
  EXPECT_NEAR(mid.at(101).intensity, 0.625f, 1e-6);
  EXPECT_NEAR(mid.at(101).iris, 0.75f, 1e-6);
  EXPECT_EQ(mid.at(101).gobo, "Star");
  EXPECT_EQ(p.state(52.0), trackedState(s.show, s.profiles, s.main(), 6));
  EXPECT_FALSE(p.gotoCue(7, 60.0));
  EXPECT_FALSE(p.go(60.0));          // past the last cue: nothing happens
  EXPECT_EQ(*p.currentCue(), 6u);
}

TEST(CuePlayer, GoDuringAFadeStartsFromWhatIsOnStage) {
  auto s = loadValidShow();
  CuePlayer p(s.show, s.profiles, s.main());
  p.jumpTo(0, 0.0);
  p.go(0.0);        // cue 2: pan 0 -> 90 from t = 1 to 5
  p.go(3.0);        // pan is 45 now: cue 3 (delay 0.5, fade 0) starts from there
  EXPECT_NEAR(p.state(3.4).at(101).panDeg, 45.0f, 1e-4);   // its delay: nothing moves
  EXPECT_NEAR(p.state(3.4).at(101).intensity, 1.0f, 1e-6);
  // Then it snaps to cue 3's tracked state, which holds cue 2's pan of 90.
  EXPECT_NEAR(p.state(3.6).at(101).panDeg, 90.0f, 1e-4);
  EXPECT_NEAR(p.state(3.6).at(101).intensity, 0.25f, 1e-6);
}

}  // namespace
}  // namespace haze
