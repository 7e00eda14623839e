// Several cue lists at once (shows/playbacks.h, docs/shows.md "Several cue lists at once"):
// intensities merge HTP with each list's master, the other attributes LTP by the order of the
// GOs, a list taking an attribute over fades it from what was on stage. Every expected value is
// worked out by hand from tests/data/shows/playbacks.haze.json:
//   Main      1 (snap)    1: intensity 0.6, pan 30    2: intensity 0.2
//             2 (fade 4)  1: intensity 0.3
//   Specials  1 (fade 2)  1: intensity 0.5, pan 90    2: intensity 0.8
//             2 (snap)    2: tilt 45, color blue
// and fixture 3 is in no cue.
#include <gtest/gtest.h>

#include <fstream>

#include "show_test_data.h"
#include "shows/cue_player.h"
#include "shows/playbacks.h"

namespace haze {
namespace {

struct Loaded {
  Show show;
  ProfileSet profiles;
};

Loaded loadFile(const std::filesystem::path& file) {
  auto show = loadShow(file);
  EXPECT_TRUE(show.ok()) << (show ? "" : show.error().str());
  if (!show) return {};
  auto profiles = loadProfiles(*show);
  EXPECT_TRUE(profiles.ok());
  if (!profiles) return {};
  return {std::move(*show), std::move(*profiles)};
}

Loaded loadPlaybacksShow() { return loadFile(test::showsDir() / "playbacks.haze.json"); }

constexpr size_t kMain = 0, kSpecials = 1;

TEST(Playbacks, IntensitiesMergeHighestTakesPrecedenceWithMasters) {
  const Loaded s = loadPlaybacksShow();
  Playbacks p(s.show, s.profiles);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p.find("Specials"), kSpecials);
  EXPECT_EQ(p.state(0.0), defaultState(s.show));  // nothing played yet

  ASSERT_TRUE(p.go(kMain, 0.0));
  EXPECT_FLOAT_EQ(p.state(0.5).at(1).intensity, 0.6f);
  EXPECT_FLOAT_EQ(p.state(0.5).at(2).intensity, 0.2f);
  ASSERT_TRUE(p.go(kSpecials, 1.0));  // fade 2: half way at 2 s
  StageState st = p.state(2.0);
  EXPECT_FLOAT_EQ(st.at(1).intensity, 0.6f);   // max(0.6, 0.25)
  EXPECT_FLOAT_EQ(st.at(2).intensity, 0.4f);   // max(0.2, 0.4)
  EXPECT_EQ(st.at(3), Attributes{});           // driven by no list
  st = p.state(3.0);
  EXPECT_FLOAT_EQ(st.at(1).intensity, 0.6f);   // max(0.6, 0.5)
  EXPECT_FLOAT_EQ(st.at(2).intensity, 0.8f);   // max(0.2, 0.8)

  p.setMaster(kSpecials, 0.5);
  st = p.state(3.0);
  EXPECT_FLOAT_EQ(st.at(1).intensity, 0.6f);   // max(0.6, 0.5 x 0.5)
  EXPECT_FLOAT_EQ(st.at(2).intensity, 0.4f);   // max(0.2, 0.5 x 0.8)
  p.setMaster(kMain, 0.25);
  st = p.state(3.0);
  EXPECT_FLOAT_EQ(st.at(1).intensity, 0.25f);  // max(0.25 x 0.6, 0.5 x 0.5)
  EXPECT_FLOAT_EQ(st.at(2).intensity, 0.4f);   // max(0.25 x 0.2, 0.5 x 0.8)
  p.setMaster(kMain, 1.0);
  p.setMaster(kSpecials, 0.0);
  st = p.state(3.0);
  EXPECT_FLOAT_EQ(st.at(1).intensity, 0.6f);
  EXPECT_FLOAT_EQ(st.at(2).intensity, 0.2f);
  EXPECT_FLOAT_EQ(st.at(1).panDeg, 90.0f);  // a list at master 0 still holds its positions
  p.setMaster(kSpecials, 7.0);
  EXPECT_EQ(p.master(kSpecials), 1.0);       // clamped

  // Main's cue 2 takes 1 down from 0.6 to 0.3 over 4 s; above 0.5 Main is the highest, below it Specials.
  ASSERT_TRUE(p.go(kMain, 5.0));
  EXPECT_NEAR(p.state(6.0).at(1).intensity, 0.525f, 1e-6);
  EXPECT_FLOAT_EQ(p.state(7.0).at(1).intensity, 0.5f);   // max(0.45, 0.5)
  EXPECT_FLOAT_EQ(p.state(9.0).at(1).intensity, 0.5f);   // max(0.3, 0.5)
}

TEST(Playbacks, PanIsLatestTakesPrecedenceByTheOrderOfTheGos) {
  const Loaded s = loadPlaybacksShow();
  {
    Playbacks p(s.show, s.profiles);
    ASSERT_TRUE(p.go(kMain, 0.0));
    ASSERT_TRUE(p.go(kSpecials, 1.0));
    // Specials takes pan over and fades it from what was on stage (Main's 30), not from its own 0.
    EXPECT_FLOAT_EQ(p.state(1.5).at(1).panDeg, 45.0f);  // 30 + (90 - 30) / 4
    EXPECT_FLOAT_EQ(p.state(2.0).at(1).panDeg, 60.0f);
    EXPECT_FLOAT_EQ(p.state(3.0).at(1).panDeg, 90.0f);
    EXPECT_EQ(p.holder({1, LtpAttribute::Pan, 0}), kSpecials);
    // Main's cue 2 holds no pan: Specials keeps it.
    ASSERT_TRUE(p.go(kMain, 5.0));
    EXPECT_FLOAT_EQ(p.state(10.0).at(1).panDeg, 90.0f);
    // GOTO Main's cue 1 asserts its whole tracked state, pan 30 included (a snap).
    ASSERT_TRUE(p.gotoCue(kMain, 0, 10.0));
    EXPECT_FLOAT_EQ(p.state(10.0).at(1).panDeg, 30.0f);
    EXPECT_EQ(p.holder({1, LtpAttribute::Pan, 0}), kMain);
    EXPECT_EQ(p.startOrder(), (std::vector<size_t>{kSpecials, kMain}));
  }
  {
    Playbacks p(s.show, s.profiles);  // the other order: Main GOes last, its 30 wins
    ASSERT_TRUE(p.go(kSpecials, 0.0));
    ASSERT_TRUE(p.go(kMain, 0.0));
    EXPECT_FLOAT_EQ(p.state(5.0).at(1).panDeg, 30.0f);
    EXPECT_FLOAT_EQ(p.state(5.0).at(1).intensity, 0.6f);  // intensity does not care about order
    EXPECT_FLOAT_EQ(p.state(5.0).at(2).intensity, 0.8f);
  }
}

TEST(Playbacks, BackFadesWhatTheListHeldToItsDefaults) {
  const Loaded s = loadPlaybacksShow();
  Playbacks p(s.show, s.profiles);
  ASSERT_TRUE(p.go(kMain, 0.0));
  ASSERT_TRUE(p.go(kSpecials, 1.0));
  ASSERT_TRUE(p.gotoCue(kMain, 0, 10.0));  // pan 30 from Main
  ASSERT_TRUE(p.go(kSpecials, 12.0));      // cue 2, a snap: 2 tilts to 45 in blue
  StageState st = p.state(12.0);
  EXPECT_FLOAT_EQ(st.at(2).tiltDeg, 45.0f);
  EXPECT_EQ(st.at(2).color, glm::vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(st.at(1).panDeg, 30.0f);  // cue 2 holds no pan of 1
  // BACK to Specials' cue 1 (fade 2): it asserts cue 1's pan 90 again, faded from Main's 30, and
  // takes tilt and colour of 2 back to their defaults on the same fade.
  ASSERT_TRUE(p.back(kSpecials, 13.0));
  st = p.state(14.0);
  EXPECT_FLOAT_EQ(st.at(1).panDeg, 60.0f);
  EXPECT_FLOAT_EQ(st.at(2).tiltDeg, 22.5f);
  EXPECT_EQ(st.at(2).color, glm::vec3(0.5f, 0.5f, 1.0f));
  st = p.state(15.0);
  EXPECT_FLOAT_EQ(st.at(1).panDeg, 90.0f);
  EXPECT_FLOAT_EQ(st.at(2).tiltDeg, 0.0f);
  EXPECT_FALSE(p.back(kSpecials, 16.0));  // no cue before cue 1
  EXPECT_FALSE(p.go(5, 16.0));            // no such list
}

// One list alone plays exactly as CuePlayer does: GO, fades, BACK, GOTO, a follow chain.
TEST(Playbacks, OneListAloneIsTheCuePlayer) {
  auto s = test::loadValidShow();
  Playbacks p(s.show, s.profiles);
  CuePlayer one(s.show, s.profiles, s.main());
  auto both = [&](auto&& action) { EXPECT_EQ(action(p, 0), action(one)); };
  both([](auto& x, auto... i) { return x.go(i..., 0.0); });
  both([](auto& x, auto... i) { return x.go(i..., 1.0); });         // during cue 1's fade
  both([](auto& x, auto... i) { return x.back(i..., 3.5); });       // during cue 2's
  both([](auto& x, auto... i) { return x.gotoCue(i..., 3, 6.0); }); // 3.5: follows to 4 and 5
  for (double t = 0.0; t < 14.0; t += 0.0625) EXPECT_EQ(p.state(t), one.state(t)) << "at " << t;
  EXPECT_EQ(p.currentCue(0), one.currentCue());
  both([](auto& x, auto... i) { return x.jumpTo(i..., 1, 20.0); });
  both([](auto& x, auto... i) { return x.go(i..., 21.0); });
  for (double t = 20.0; t < 24.0; t += 0.125) EXPECT_EQ(p.state(t), one.state(t)) << "at " << t;
}

// Follows of two lists fire in the order of their times, however seldom the clock is read.
TEST(Playbacks, FollowsOfSeveralListsFireInTimeOrder) {
  test::ScratchDir dir;
  for (const auto& [followA, followB, wantPan] : {std::tuple{3.0, 1.0, 10.0f}, std::tuple{0.5, 1.0, 50.0f}}) {
    const auto file = dir.path / "follows.haze.json";
    std::ofstream(file) << R"({"format": "haze-show", "version": 2, "profiles": { "p": { "format": "haze-fixture",
      "version": 1, "name": "P", "photometry": { "beam_angle": 20, "field_angle": 30, "peak_candela": 1000 } } },
      "fixtures": [ { "id": 1, "profile": "p" } ], "cue_lists": [
      { "name": "A", "cues": [ { "number": "1", "follow": )" << followA << R"(, "values": { "1": { "intensity": 1 } } },
                               { "number": "2", "values": { "1": { "pan": 10 } } } ] },
      { "name": "B", "cues": [ { "number": "1", "follow": )" << followB << R"(, "values": { "1": { "intensity": 1 } } },
                               { "number": "2", "values": { "1": { "pan": 50 } } } ] } ] })";
    const Loaded s = loadFile(file);
    Playbacks seldom(s.show, s.profiles), often(s.show, s.profiles);
    for (Playbacks* p : {&seldom, &often}) {
      ASSERT_TRUE(p->go(0, 0.0));
      ASSERT_TRUE(p->go(1, 0.0));
    }
    for (double t = 0.0; t <= 10.0; t += 0.01) often.state(t);
    EXPECT_FLOAT_EQ(seldom.state(10.0).at(1).panDeg, wantPan) << followA << " " << followB;
    EXPECT_EQ(seldom.state(10.0), often.state(10.0));
    EXPECT_EQ(seldom.currentCue(0), 1u);
    EXPECT_EQ(seldom.currentCue(1), 1u);
  }
}

}  // namespace
}  // namespace haze
