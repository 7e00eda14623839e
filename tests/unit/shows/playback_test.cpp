// The pure face of playback against tests/data/shows/valid.haze.json, whose cues were built so
// that every expected value below follows by hand from docs/show-format.md's tracking model.
#include <gtest/gtest.h>

#include "show_test_data.h"
#include "shows/playback.h"

namespace haze {
namespace {

using test::loadValidShow;

size_t cue(const CueList& list, const char* number) {
  auto i = findCue(list, number);
  EXPECT_TRUE(i.ok()) << number;
  return i.ok() ? *i : 0;
}

TEST(Playback, TrackingThroughSevenCues) {
  auto s = loadValidShow();
  const CueList& m = s.main();
  ASSERT_EQ(m.cues.size(), 7u);
  // Cue 1 sets 101's colour; no later cue touches it: still there in cue 5 and cue 10.
  for (const char* n : {"1", "2", "3", "3.5", "4", "5", "10"}) {
    StageState st = trackedState(s.show, s.profiles, m, cue(m, n));
    EXPECT_EQ(st.at(101).color, glm::vec3(1.0f, 0.8f, 0.6f)) << "cue " << n;
    EXPECT_FLOAT_EQ(st.at(101).tiltDeg, 20.0f) << "cue " << n;
  }
  // 101's intensity: 1 from cue 1, changed to 0.25 in cue 3, tracked after.
  EXPECT_FLOAT_EQ(trackedState(s.show, s.profiles, m, cue(m, "2")).at(101).intensity, 1.0f);
  for (const char* n : {"3", "3.5", "4", "5", "10"})
    EXPECT_FLOAT_EQ(trackedState(s.show, s.profiles, m, cue(m, n)).at(101).intensity, 0.25f) << n;
  // Pan: 0 (cue 1), 90 (cue 2), tracked to 5, -90 in cue 10.
  EXPECT_FLOAT_EQ(trackedState(s.show, s.profiles, m, cue(m, "5")).at(101).panDeg, 90.0f);
  EXPECT_FLOAT_EQ(trackedState(s.show, s.profiles, m, cue(m, "10")).at(101).panDeg, -90.0f);
}

TEST(Playback, UnsetAttributesTakeTheirDefaults) {
  auto s = loadValidShow();
  StageState st = trackedState(s.show, s.profiles, s.main(), 0);
  ASSERT_EQ(st.size(), 3u);  // every fixture of the show, set in the cue or not
  const Attributes& par = st.at(201);
  EXPECT_FLOAT_EQ(par.panDeg, 0.0f);
  EXPECT_FLOAT_EQ(par.iris, 1.0f);
  EXPECT_EQ(par.gobo, "Open");
  EXPECT_FALSE(par.zoomDeg.has_value());  // the profile's field angle
  EXPECT_EQ(st.at(102).color, glm::vec3(1.0f));
  // Before cue 1, at GO time 0 with fade 2: everything is still at its default intensity 0.
  EXPECT_FLOAT_EQ(stateAt(s.show, s.profiles, s.main(), 0, 0.0).at(102).intensity, 0.0f);
  EXPECT_FLOAT_EQ(stateAt(s.show, s.profiles, s.main(), 0, 1.0).at(102).intensity, 0.25f);
}

TEST(Playback, DelayThenLinearFade) {
  auto s = loadValidShow();
  const CueList& m = s.main();
  size_t c2 = cue(m, "2");  // delay 1, fade 4: 101 pan 0 -> 90, zoom (25) -> 18; 102 tilt 0 -> -45
  struct Row { double t; float pan, tilt, zoom; };
  for (Row r : {Row{0.0, 0, 0, 25}, Row{0.5, 0, 0, 25}, Row{1.0, 0, 0, 25}, Row{2.0, 22.5f, -11.25f, 23.25f},
                Row{3.0, 45, -22.5f, 21.5f}, Row{5.0, 90, -45, 18}, Row{60.0, 90, -45, 18}}) {
    StageState st = stateAt(s.show, s.profiles, m, c2, r.t);
    EXPECT_NEAR(st.at(101).panDeg, r.pan, 1e-4) << "t=" << r.t;
    EXPECT_NEAR(st.at(102).tiltDeg, r.tilt, 1e-4) << "t=" << r.t;
    ASSERT_TRUE(st.at(101).zoomDeg || r.t < 1.0) << "t=" << r.t;
    if (st.at(101).zoomDeg) {
      EXPECT_NEAR(*st.at(101).zoomDeg, r.zoom, 1e-4) << "t=" << r.t;
    }
  }
  // Attributes the cue does not change stay put through the fade.
  EXPECT_FLOAT_EQ(stateAt(s.show, s.profiles, m, c2, 3.0).at(101).intensity, 1.0f);
}

TEST(Playback, ColourFadesPerChannel) {
  auto s = loadValidShow();
  // Cue 1 fades 201's colour from the default white to red over 2 s: at 0.5 s a quarter of the way.
  StageState st = stateAt(s.show, s.profiles, s.main(), 0, 0.5);
  EXPECT_NEAR(st.at(201).color.r, 1.0f, 1e-6);
  EXPECT_NEAR(st.at(201).color.g, 0.75f, 1e-6);
  EXPECT_NEAR(st.at(201).color.b, 0.75f, 1e-6);
}

TEST(Playback, GoboSwitchesWhenTheFadeStarts) {
  auto s = loadValidShow();
  size_t c2 = cue(s.main(), "2");  // 102: gobo Open -> Star, delay 1
  EXPECT_EQ(stateAt(s.show, s.profiles, s.main(), c2, 0.99).at(102).gobo, "Open");
  StageState atStart = stateAt(s.show, s.profiles, s.main(), c2, 1.0);
  EXPECT_EQ(atStart.at(102).gobo, "Star");
  EXPECT_FLOAT_EQ(atStart.at(102).tiltDeg, 0.0f);  // the continuous part has not moved yet
  // Cue 1: no delay, so the gobo is in from the first instant of the 2 s fade.
  StageState c1 = stateAt(s.show, s.profiles, s.main(), 0, 0.0);
  EXPECT_EQ(c1.at(101).gobo, "Dots");
  EXPECT_FLOAT_EQ(c1.at(101).intensity, 0.0f);
}

TEST(Playback, FadeZeroSnapsAfterTheDelay) {
  auto s = loadValidShow();
  size_t c3 = cue(s.main(), "3");  // delay 0.5, fade 0: 101 intensity 1 -> 0.25, 201 colour red -> blue
  StageState before = stateAt(s.show, s.profiles, s.main(), c3, 0.49);
  EXPECT_FLOAT_EQ(before.at(101).intensity, 1.0f);
  EXPECT_EQ(before.at(101).gobo, "Dots");
  EXPECT_EQ(before.at(201).color, glm::vec3(1, 0, 0));
  StageState after = stateAt(s.show, s.profiles, s.main(), c3, 0.5);
  EXPECT_FLOAT_EQ(after.at(101).intensity, 0.25f);
  EXPECT_EQ(after.at(101).gobo, "Star");
  EXPECT_EQ(after.at(201).color, glm::vec3(0, 0, 1));
}

TEST(Playback, BeyondDelayPlusFadeIsTheFullState) {
  auto s = loadValidShow();
  for (size_t i = 0; i < s.main().cues.size(); ++i)
    EXPECT_EQ(stateAt(s.show, s.profiles, s.main(), i, 1000.0), trackedState(s.show, s.profiles, s.main(), i)) << i;
}

TEST(Playback, FindCueComparesNumbers) {
  auto s = loadValidShow();
  EXPECT_EQ(*findCue(s.main(), "3.5"), 3u);
  EXPECT_EQ(*findCue(s.main(), "3.50"), 3u);
  EXPECT_EQ(*findCue(s.main(), "10"), 6u);
  auto missing = findCue(s.main(), "7");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("\"Main\" has no cue \"7\""), std::string::npos) << missing.error().message;
  EXPECT_FALSE(findCue(s.main(), "abc").ok());
}

TEST(Playback, FadeProgressShape) {
  CueTiming t{2.0, 4.0};
  EXPECT_EQ(fadeProgress(t, 1.999), -1.0);
  EXPECT_EQ(fadeProgress(t, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(fadeProgress(t, 3.0), 0.25);
  EXPECT_EQ(fadeProgress(t, 6.0), 1.0);
  EXPECT_EQ(fadeProgress(CueTiming{0.0, 0.0}, 0.0), 1.0);
  EXPECT_EQ(fadeProgress(CueTiming{1.0, 0.0}, 0.5), -1.0);
}

}  // namespace
}  // namespace haze
