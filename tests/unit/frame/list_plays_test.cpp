// `--play LIST=CUE[@MASTER][+GO_S]`: the grammar, and several lists played at once (the last GO
// of a moment wins what both lists set; a master scales a list's intensities).
#include <gtest/gtest.h>

#include "shows/frame/list_plays.h"
#include "unit/dmx/test_show.h"

namespace haze {
namespace {

TEST(ListPlays, ParsesEveryPart) {
  auto p = parseListPlay("Main=2.5@0.5+3");
  ASSERT_TRUE(p.ok()) << p.error().str();
  EXPECT_EQ(p->list, "Main");
  EXPECT_EQ(p->cue, "2.5");
  EXPECT_DOUBLE_EQ(p->master, 0.5);
  EXPECT_DOUBLE_EQ(p->goAtS, 3.0);
  auto plain = parseListPlay("Specials=1");
  ASSERT_TRUE(plain.ok());
  EXPECT_DOUBLE_EQ(plain->master, 1.0);
  EXPECT_DOUBLE_EQ(plain->goAtS, 0.0);
}

TEST(ListPlays, RefusesWhatIsNotAPlay) {
  for (const char* bad : {"", "Main", "=2", "Main=", "Main=two", "Main=2@1.5", "Main=2@-0.1", "Main=2+-1", "Main=2+x",
                          "Main=2@", "Main=2+nan"}) {
    auto p = parseListPlay(bad);
    EXPECT_FALSE(p.ok()) << "'" << bad << "' was taken";
    if (!p.ok()) {
      EXPECT_EQ(p.error().place, "--play");
    }
  }
}

test::TestShow twoLists() {
  test::TestShow t = test::makeTestShow();
  for (const char* name : {"Main", "Specials"}) {
    CueList l;
    l.name = name;
    for (int i = 1; i <= 2; ++i) {
      Cue c;
      c.number = std::to_string(i);
      c.values[101].intensity = name[0] == 'M' ? 0.25f * i : 0.9f;
      c.values[102].intensity = 0.5f;
      l.cues.push_back(c);
    }
    t.show.cueLists.push_back(l);
  }
  return t;
}

TEST(ListPlays, TheLaterGOWinsAndMastersScale) {
  const test::TestShow t = twoLists();
  // Main GOes into 2 at 0 s, Specials into 1 at 1 s: at 2 s Specials' 0.9 holds fixture 101.
  auto later = playListsAt(t.show, t.profiles, {{"Main", "2"}, {"Specials", "1", 1.0, 1.0}}, 2.0, false);
  ASSERT_TRUE(later.ok()) << later.error().str();
  EXPECT_FLOAT_EQ(later->at(101).intensity, 0.9f);
  // Before Specials' GO, fixture 101 is Main's cue 2 and Specials stands in its cue before 1.
  auto before = playListsAt(t.show, t.profiles, {{"Main", "2"}, {"Specials", "1", 1.0, 1.0}}, 0.5, false);
  ASSERT_TRUE(before.ok());
  EXPECT_FLOAT_EQ(before->at(101).intensity, 0.5f);
  // One list alone at master 0.5: its intensities halve.
  auto half = playListsAt(t.show, t.profiles, {{"Main", "2", 0.5}}, 1.0, false);
  ASSERT_TRUE(half.ok());
  EXPECT_FLOAT_EQ(half->at(101).intensity, 0.25f);
}

TEST(ListPlays, UnknownListsCuesAndRepeatsAreErrors) {
  const test::TestShow t = twoLists();
  auto unknown = playListsAt(t.show, t.profiles, {{"Nope", "1"}}, 0.0, false);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().message.find("Specials"), std::string::npos) << unknown.error().message;
  auto cue = playListsAt(t.show, t.profiles, {{"Main", "7"}}, 0.0, false);
  ASSERT_FALSE(cue.ok());
  auto twice = playListsAt(t.show, t.profiles, {{"Main", "1"}, {"Main", "2"}}, 0.0, false);
  ASSERT_FALSE(twice.ok());
  EXPECT_NE(twice.error().message.find("twice"), std::string::npos);
  EXPECT_EQ(describeListPlays({{"Main", "2"}, {"Specials", "1", 0.5, 2.0}}),
            "Main cue 2, Specials cue 1 at master 0.5 GO at 2 s");
}

}  // namespace
}  // namespace haze
