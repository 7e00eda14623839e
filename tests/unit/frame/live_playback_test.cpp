// The live cue engine: OSC commands on the cue player, timecode firing at the cue's frame and
// chasing on jumps, DMX and programmer laid over playback. Expected states are the cues' own
// values (fades of 0, so no timing enters).
#include <gtest/gtest.h>

#include "shows/frame/live_playback.h"
#include "unit/dmx/test_show.h"

namespace haze {
namespace {

using test::timedShow;

float intensity(LivePlayback& p, double now) { return p.stage(now, {}, {}).at(101).intensity; }

TEST(LivePlayback, OscGoBackGoto) {
  const test::TestShow t = timedShow();
  LivePlayback p(t.show, t.profiles, &t.show.cueLists[0]);
  RemoteCommand c;
  c.kind = RemoteCommand::Kind::Back;
  EXPECT_FALSE(p.apply(c, 0.0)) << "nothing before the first GO";
  c.kind = RemoteCommand::Kind::Go;
  EXPECT_EQ(*p.apply(c, 0.0), "cue 1");
  EXPECT_EQ(*p.apply(c, 0.1), "cue 2");
  c.kind = RemoteCommand::Kind::Back;
  EXPECT_EQ(*p.apply(c, 0.2), "cue 1");
  EXPECT_FLOAT_EQ(intensity(p, 0.3), 0.2f);
  c.kind = RemoteCommand::Kind::Goto;
  c.cue = "3";
  EXPECT_EQ(*p.apply(c, 0.4), "cue 3");
  EXPECT_FLOAT_EQ(intensity(p, 0.5), 0.6f);
  c.cue = "9";
  EXPECT_FALSE(p.apply(c, 0.6));
  c.kind = RemoteCommand::Kind::SetFixture;
  c.fixture = 102;
  c.values.panDeg = 45.0f;
  EXPECT_TRUE(p.apply(c, 0.7));
  EXPECT_FLOAT_EQ(p.stage(0.7, {}, {}).at(102).panDeg, 45.0f);
  c.fixture = 999;
  EXPECT_FALSE(p.apply(c, 0.7)) << "no such fixture";
  c.kind = RemoteCommand::Kind::ClearAll;
  EXPECT_TRUE(p.apply(c, 0.8));
  EXPECT_FLOAT_EQ(p.stage(0.8, {}, {}).at(102).panDeg, 0.0f);
}

TEST(LivePlayback, CameraMustBeOneOfTheShows) {
  test::TestShow t = timedShow();
  t.show.cameras.clear();
  t.show.cameras.push_back(CameraDef{.name = "FOH"});
  t.show.cameras.push_back(CameraDef{.name = "Side"});
  LivePlayback p(t.show, t.profiles, &t.show.cueLists[0]);
  EXPECT_EQ(p.camera(), "") << "the command line's camera until a message chooses one";
  RemoteCommand c;
  c.kind = RemoteCommand::Kind::Camera;
  c.camera = "Side";
  EXPECT_EQ(*p.apply(c, 0.0), "camera \"Side\"");
  c.camera = "Balcony";
  const auto refused = p.apply(c, 0.1);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().str().find("it has \"FOH\", \"Side\""), std::string::npos) << refused.error().str();
  EXPECT_EQ(p.camera(), "Side") << "a refused name leaves the camera as it was";
}

TEST(LivePlayback, TimecodeFiresCuesAtTheirFrameAndChasesOnJumps) {
  const test::TestShow t = timedShow();
  LivePlayback p(t.show, t.profiles, &t.show.cueLists[0]);
  std::vector<std::pair<std::string, std::string>> fired;  // timecode, what
  double now = 0.0;
  auto run = [&](Timecode from, int frames) {
    int total = ((from.hours * 60 + from.minutes) * 60 + from.seconds) * 25 + from.frames;
    for (int k = 0; k < frames; ++k, ++total, now += 0.04) {
      Timecode tc{total / 90000, total / 1500 % 60, total / 25 % 60, total % 25};
      const std::string what = p.timecode(tc, 25.0, now);
      if (!what.empty()) fired.push_back({tc.str(), what});
    }
  };
  run({0, 0, 0, 0}, 80);  // 00:00:00:00 .. 00:00:03:04
  ASSERT_EQ(fired.size(), 3u);
  EXPECT_EQ(fired[0], std::make_pair(std::string("00:00:01:00"), std::string("fired cue 1")));
  EXPECT_EQ(fired[1], std::make_pair(std::string("00:00:02:00"), std::string("fired cue 2")));
  EXPECT_EQ(fired[2], std::make_pair(std::string("00:00:03:00"), std::string("fired cue 3")));
  EXPECT_FLOAT_EQ(intensity(p, now), 0.6f);
  // A jump backwards chases to the cue of that time, at once.
  fired.clear();
  run({0, 0, 1, 12}, 1);
  ASSERT_EQ(fired.size(), 1u);
  EXPECT_EQ(fired[0].second, "chased to cue 1");
  EXPECT_FLOAT_EQ(intensity(p, now), 0.2f);
  // Running on from there fires cue 2 again at its frame.
  fired.clear();
  run({0, 0, 1, 13}, 20);
  ASSERT_EQ(fired.size(), 1u);
  EXPECT_EQ(fired[0].first, "00:00:02:00");
  // Before the first timed cue: defaults. A jump ahead of more than a second chases forward.
  fired.clear();
  run({0, 0, 0, 5}, 1);
  run({0, 0, 2, 20}, 1);
  ASSERT_EQ(fired.size(), 2u);
  EXPECT_EQ(fired[0].second, "before the first timed cue: the stage at its defaults");
  EXPECT_EQ(fired[1].second, "chased to cue 2");
  // A timecode that skips frames (a slow sender) still fires every cue passed, in order.
  fired.clear();
  p.timecode({0, 0, 2, 24}, 25.0, now);
  p.timecode({0, 0, 3, 10}, 25.0, now);
  EXPECT_EQ(p.currentCue(), std::optional<size_t>(2));
}

TEST(LivePlayback, DmxFixturesFollowTheConsole) {
  const test::TestShow t = timedShow();
  LivePlayback p(t.show, t.profiles, &t.show.cueLists[0]);
  RemoteCommand go;
  ASSERT_TRUE(p.apply(go, 0.0));
  StageState dmx = defaultState(t.show);
  dmx[101].intensity = 0.9f;
  EXPECT_FLOAT_EQ(p.stage(0.1, dmx, {101}).at(101).intensity, 0.9f);
  EXPECT_FLOAT_EQ(p.stage(0.1, dmx, {}).at(101).intensity, 0.2f);
}

// /haze/list/NAME/...: a second list GOes, BACKs and is mastered by name beside the played one;
// intensity merges HTP (docs/shows.md, "Several cue lists at once").
TEST(LivePlayback, OscDrivesOtherListsByName) {
  test::TestShow t = timedShow();
  CueList specials;
  specials.name = "Specials";
  specials.cues = {test::intensityCue("1", 0.5f), test::intensityCue("2", 0.1f)};
  specials.cues[1].values[102].panDeg = 30.0f;
  t.show.cueLists.push_back(specials);
  LivePlayback p(t.show, t.profiles, &t.show.cueLists[0]);
  RemoteCommand c;
  EXPECT_EQ(*p.apply(c, 0.0), "cue 1");  // Main: 101 at 0.2
  c.kind = RemoteCommand::Kind::ListGo;
  c.list = "Specials";
  EXPECT_EQ(*p.apply(c, 0.1), "cue list \"Specials\": cue 1");
  EXPECT_FLOAT_EQ(intensity(p, 0.2), 0.5f);  // max(0.2, 0.5)
  c.kind = RemoteCommand::Kind::ListMaster;
  c.level = 0.25;
  EXPECT_EQ(*p.apply(c, 0.3), "cue list \"Specials\": master 0.25");
  EXPECT_FLOAT_EQ(intensity(p, 0.3), 0.2f);  // max(0.2, 0.25 x 0.5)
  c.kind = RemoteCommand::Kind::ListGo;
  EXPECT_EQ(*p.apply(c, 0.4), "cue list \"Specials\": cue 2");
  EXPECT_FLOAT_EQ(p.stage(0.4, {}, {}).at(102).panDeg, 30.0f);
  EXPECT_FALSE(p.apply(c, 0.5)) << "no cue after 2";
  c.kind = RemoteCommand::Kind::ListBack;
  EXPECT_EQ(*p.apply(c, 0.6), "cue list \"Specials\": cue 1");
  EXPECT_EQ(p.currentCue(), std::optional<size_t>(0));  // the played list did not move
  c.list = "Nope";
  auto bad = p.apply(c, 0.7);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("its lists are \"Main\", \"Specials\""), std::string::npos) << bad.error().message;
}

}  // namespace
}  // namespace haze
