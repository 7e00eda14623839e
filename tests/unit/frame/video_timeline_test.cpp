// The video timeline: a cue list played as on stage and sampled every 1/fps seconds. Expected
// values come from the cues' own times (GO, delay, fade, hold) worked out by hand here.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "shows/frame/video_timeline.h"
#include "unit/dmx/test_show.h"

namespace haze {
namespace {

// Cue 1 snaps to 0.2; cue 2 fades to 0.8 in 2 s; cue 3 snaps to 0.
test::TestShow threeCues() {
  test::TestShow t = test::makeTestShow();
  CueList l;
  l.name = "Main";
  l.cues = {test::intensityCue("1", 0.2f, 0.0, "00:00:01:00"), test::intensityCue("2", 0.8f, 2.0, "00:00:02:00"),
            test::intensityCue("3", 0.0f)};
  t.show.cueLists.push_back(l);
  return t;
}

std::vector<VideoTimeline::Frame> playAll(VideoTimeline& timeline) {
  std::vector<VideoTimeline::Frame> frames;
  for (int f = 0; f < timeline.frames(); ++f) {
    auto frame = timeline.next();
    EXPECT_TRUE(frame.ok()) << frame.error().str();
    if (!frame.ok()) break;
    frames.push_back(*frame);
  }
  return frames;
}

// GO 1 at 0 s; its hold of 1 s ends at 1 s: GO 2, fading 1..3 s; hold to 4 s: GO 3 (a snap);
// the video ends 1 s later, at 5 s: 50 frames at 10 fps.
TEST(VideoTimeline, ARangeWithHoldsFadesAtTheCuesTimes) {
  const test::TestShow t = threeCues();
  VideoPlan plan{.list = &t.show.cueLists[0], .from = 0, .to = 2, .holdS = 1.0, .fps = 10, .realMovement = false};
  VideoTimeline timeline(t.show, t.profiles, plan);
  EXPECT_DOUBLE_EQ(timeline.endS(), 5.0);
  ASSERT_EQ(timeline.frames(), 50);
  const auto frames = playAll(timeline);
  ASSERT_EQ(frames.size(), 50u);
  const auto level = [&](int f) { return frames[f].state.at(101).intensity; };
  EXPECT_FLOAT_EQ(level(0), 0.2f);
  EXPECT_EQ(frames[0].cue, 0u);
  EXPECT_NEAR(level(20), 0.2f + 0.6f * 0.5f, 1e-5f);  // 2 s: half-way through the 2 s fade
  EXPECT_EQ(frames[20].cue, 1u);
  EXPECT_NEAR(level(30), 0.8f, 1e-5f);
  EXPECT_FLOAT_EQ(level(45), 0.0f);
  EXPECT_EQ(frames[45].cue, 2u);
  for (int f = 10; f < 30; ++f) EXPECT_LE(level(f), level(f + 1) + 1e-6f) << "frame " << f;
  for (size_t f = 0; f < frames.size(); ++f) EXPECT_DOUBLE_EQ(frames[f].timeS, f / 10.0);
}

TEST(VideoTimeline, ADurationCutsOrExtendsTheVideo) {
  const test::TestShow t = threeCues();
  VideoPlan plan{.list = &t.show.cueLists[0], .from = 1, .to = 1, .holdS = 1.0, .durationS = 0.95, .fps = 20,
                 .realMovement = false};
  VideoTimeline timeline(t.show, t.profiles, plan);
  EXPECT_EQ(timeline.frames(), 19);
  const auto frames = playAll(timeline);
  // From cue 2 alone: cue 1's full state is on stage at 0 s, the GO into 2 at 0 s.
  EXPECT_FLOAT_EQ(frames.front().state.at(101).intensity, 0.2f);
  EXPECT_NEAR(frames[10].state.at(101).intensity, 0.2f + 0.6f * 0.25f, 1e-5f);
}

// Timecode from 00:00:00:00 at 25 fps: cue 1 fires at frame 25 of the timecode (1 s), cue 2 at
// 2 s; the video ends a hold after cue 2's fade, at 2 + 2 + 1 = 5 s.
TEST(VideoTimeline, TimecodeFiresTheTimedCuesAtTheirFrames) {
  const test::TestShow t = threeCues();
  VideoPlan plan{.list = &t.show.cueLists[0], .holdS = 1.0, .fps = 25, .realMovement = false,
                 .timecodeStart = Timecode{}, .timecodeRate = 25};
  VideoTimeline timeline(t.show, t.profiles, plan);
  EXPECT_DOUBLE_EQ(timeline.endS(), 5.0);
  const auto frames = playAll(timeline);
  ASSERT_EQ(frames.size(), 125u);
  std::vector<int> firedAt;
  for (const auto& f : frames)
    if (!f.fired.empty()) firedAt.push_back(f.index);
  EXPECT_EQ(firedAt, (std::vector<int>{25, 50}));
  ASSERT_TRUE(frames[25].timecode.has_value());
  EXPECT_EQ(frames[25].timecode->str(), "00:00:01:00");
  EXPECT_FLOAT_EQ(frames[24].state.at(101).intensity, 0.0f);
  EXPECT_FLOAT_EQ(frames[25].state.at(101).intensity, 0.2f);
  EXPECT_NEAR(frames[75].state.at(101).intensity, 0.5f, 1e-5f);
}

TEST(VideoTimeline, TimecodePastMidnightIsAnErrorAtThatFrame) {
  const test::TestShow t = threeCues();
  VideoPlan plan{.list = &t.show.cueLists[0], .durationS = 2.0, .fps = 25, .realMovement = false,
                 .timecodeStart = Timecode{23, 59, 59, 0}, .timecodeRate = 25};
  VideoTimeline timeline(t.show, t.profiles, plan);
  int good = 0;
  for (int f = 0; f < timeline.frames(); ++f) {
    auto frame = timeline.next();
    if (!frame.ok()) {
      EXPECT_NE(frame.error().message.find("24:00:00:00"), std::string::npos) << frame.error().message;
      break;
    }
    ++good;
  }
  EXPECT_EQ(good, 25);
}

// Heads travel: a pan snap in a cue is a jump of the command, but the head arrives later.
TEST(VideoTimeline, RealMovementLagsASnapInstantDoesNot) {
  test::TestShow t = threeCues();
  t.show.cueLists[0].cues[1].values[101].panDeg = 180.0f;
  t.show.cueLists[0].cues[1].fadeS = 0.0;
  for (bool real : {false, true}) {
    VideoPlan plan{.list = &t.show.cueLists[0], .from = 0, .to = 1, .holdS = 1.0, .fps = 10, .realMovement = real};
    VideoTimeline timeline(t.show, t.profiles, plan);
    const auto frames = playAll(timeline);
    ASSERT_GT(frames.size(), 12u);
    // GO 2 at 1 s: frame 11 is 0.1 s later.
    if (real)
      EXPECT_LT(frames[11].state.at(101).panDeg, 180.0f);
    else
      EXPECT_FLOAT_EQ(frames[11].state.at(101).panDeg, 180.0f);
  }
}

TEST(VideoTimeline, ATimelineFileGivesTheGOsAndRefusesBadOnes) {
  const test::TestShow t = threeCues();
  const auto dir = std::filesystem::temp_directory_path() / ("haze-timeline-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto write = [&](const char* name, const char* text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const CueList& list = t.show.cueLists[0];
  auto good = readTimeline(write("good.json", R"({"go": [{"cue": "1", "at": 0}, {"cue": "3", "at": 2.5}]})"), t.show,
                           list, 1.0);
  ASSERT_TRUE(good.ok()) << good.error().str();
  ASSERT_EQ(good->gos.size(), 2u);
  EXPECT_EQ(good->gos[1].cueIndex, 2u);
  EXPECT_DOUBLE_EQ(good->endS, 3.5);
  auto backwards = readTimeline(write("back.json", R"({"go": [{"cue": "1", "at": 2}, {"cue": "2", "at": 1}]})"),
                                t.show, list, 1.0);
  ASSERT_FALSE(backwards.ok());
  EXPECT_EQ(backwards.error().place, "/go/1/at");
  auto unknown = readTimeline(write("unknown.json", R"({"go": [{"cue": "9", "at": 0}]})"), t.show, list, 1.0);
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().place, "/go/0/cue");
  auto truncated = readTimeline(write("cut.json", R"({"go": [{"cue": "1", )"), t.show, list, 1.0);
  ASSERT_FALSE(truncated.ok());
  EXPECT_NE(truncated.error().file.find("cut.json"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace haze
