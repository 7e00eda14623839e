// The live session's core without sockets: OSC datagrams and timecode readings go into the cue
// engine and the log, the console's DMX is laid over the playback, and the heads start where the
// first DMX puts them. Times are passed in; expected levels are the cues' own (fades of 0).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shows/frame/live_session.h"
#include "unit/dmx/test_show.h"

namespace haze {
namespace {

using test::timedShow;

// An OSC message without arguments, from the OSC 1.0 specification: the address and the type
// tags ",", each NUL-padded to 4 bytes.
std::vector<uint8_t> oscMessage(const std::string& address) {
  std::vector<uint8_t> b;
  for (const std::string& s : {address, std::string(",")}) {
    b.insert(b.end(), s.begin(), s.end());
    do b.push_back(0); while (b.size() % 4);
  }
  return b;
}

struct Logged {
  std::vector<std::string> lines;
  LiveSession::Log log() {
    return [this](const std::string& line) { lines.push_back(line); };
  }
};

TEST(LiveSession, OscGoPlaysTheListAndIsLogged) {
  const test::TestShow t = timedShow();
  Logged logged;
  LiveSession s(t.show, t.profiles, {.cueList = &t.show.cueLists[0], .playback = true}, logged.log());
  const double now = LiveSession::clockS();
  EXPECT_FALSE(s.osc(oscMessage("/haze/go"), "127.0.0.1:9000", now).empty()) << "every command gets a reply";
  s.update(now + 0.1, {}, {}, false);
  EXPECT_FLOAT_EQ(s.commanded().at(101).intensity, 0.2f);
  EXPECT_EQ(s.stats().oscCommands, 1u);
  ASSERT_EQ(logged.lines.size(), 1u);
  EXPECT_EQ(logged.lines[0], "OSC /haze/go from 127.0.0.1:9000: cue 1");
}

TEST(LiveSession, RefusalsAreCountedAndTheFirstTwentyLogged) {
  const test::TestShow t = timedShow();
  Logged logged;
  LiveSession s(t.show, t.profiles, {.cueList = &t.show.cueLists[0], .playback = true}, logged.log());
  for (int i = 0; i < 25; ++i) s.osc(oscMessage("/haze/nonsense"), "127.0.0.1:9000", LiveSession::clockS());
  EXPECT_EQ(s.stats().oscRefused, 25u);
  EXPECT_EQ(s.stats().oscCommands, 0u);
  ASSERT_EQ(logged.lines.size(), 20u);
  EXPECT_EQ(logged.lines[0].rfind("OSC from 127.0.0.1:9000 refused: ", 0), 0u) << logged.lines[0];
  const std::string tail = "(further refusals are only counted)";
  EXPECT_EQ(logged.lines[19].substr(logged.lines[19].size() - tail.size()), tail);
}

TEST(LiveSession, TimecodeFiresTheCueItReaches) {
  const test::TestShow t = timedShow();
  Logged logged;
  LiveSession s(t.show, t.profiles, {.cueList = &t.show.cueLists[0], .playback = true}, logged.log());
  const double now = LiveSession::clockS();
  s.timecode(*parseTimecode("00:00:02:00"), 25.0, "MTC", now);
  s.update(now + 0.1, {}, {}, false);
  EXPECT_FLOAT_EQ(s.commanded().at(101).intensity, 0.4f) << "a first reading chases to the cue at its time";
  EXPECT_EQ(s.stats().timecodeFired, 1u);
  ASSERT_EQ(logged.lines.size(), 1u);
  EXPECT_EQ(logged.lines[0].rfind("MTC 00:00:02:00: ", 0), 0u) << logged.lines[0];
}

TEST(LiveSession, TheConsolesFixturesFollowItOverThePlayback) {
  const test::TestShow t = timedShow();
  LiveSession s(t.show, t.profiles, {.cueList = &t.show.cueLists[0], .playback = true}, nullptr);
  const double now = LiveSession::clockS();
  s.osc(oscMessage("/haze/go"), "127.0.0.1:9000", now);
  StageState dmx;
  dmx[101].intensity = 0.9f;
  s.update(now + 0.1, dmx, {101}, true);
  EXPECT_FLOAT_EQ(s.commanded().at(101).intensity, 0.9f);
  s.update(now + 0.2, dmx, {}, true);
  EXPECT_FLOAT_EQ(s.commanded().at(101).intensity, 0.2f) << "not driven by DMX: the cue's level";
}

TEST(LiveSession, WithoutPlaybackTheStageIsTheDmxAndOscIsRefused) {
  const test::TestShow t = timedShow();
  LiveSession s(t.show, t.profiles, {.cueList = &t.show.cueLists[0], .playback = false}, nullptr);
  StageState dmx;
  dmx[201].intensity = 0.5f;
  s.update(LiveSession::clockS(), dmx, {201}, true);
  EXPECT_EQ(s.commanded().size(), 1u);
  EXPECT_FLOAT_EQ(s.commanded().at(201).intensity, 0.5f);
  s.osc(oscMessage("/haze/go"), "127.0.0.1:9000", LiveSession::clockS());
  EXPECT_EQ(s.stats().oscRefused, 1u);
  EXPECT_TRUE(s.programmer().empty());
  EXPECT_EQ(s.camera(), "");
}

// The heads at the third pass, after DMX moved fixture 101's pan from 0 to 90 at the second;
// `arrived`: whether that second pass brought the session's first DMX.
float panAfterAJump(bool arrived) {
  const test::TestShow t = timedShow();
  LiveSession s(t.show, t.profiles, {.playback = false, .followHeads = true}, nullptr);
  StageState a, b;
  a[101].panDeg = 0.0f;
  b[101].panDeg = 90.0f;
  const double now = LiveSession::clockS();
  s.update(now + 0.01, a, {101}, false);
  s.update(now + 0.02, b, {101}, arrived);
  s.update(now + 0.03, b, {101}, arrived);
  return s.moved().at(101).panDeg;
}

TEST(LiveSession, HeadsStartWhereTheFirstDmxPutsThemThenTravel) {
  EXPECT_FLOAT_EQ(panAfterAJump(true), 90.0f) << "switched on at the console's look";
  const float travelled = panAfterAJump(false);
  EXPECT_GT(travelled, 0.0f);
  EXPECT_LT(travelled, 5.0f) << "10 ms at the profile's pan speed (216 deg/s by default)";
}

}  // namespace
}  // namespace haze
