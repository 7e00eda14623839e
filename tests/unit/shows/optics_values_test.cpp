// The optics attributes of a cue (docs/show-format.md): read, written back byte-stable, refused
// at their place when malformed, tracked and faded (frost, rotations and blades fade; prism and
// shutter switch when the fade starts).
#include <gtest/gtest.h>

#include "show_test_data.h"
#include "shows/playback.h"
#include "shows/show_json.h"

namespace haze {
namespace {

// The valid show with one cue whose values for fixture 101 are `values`.
std::string withValues(const std::string& values) {
  auto a = loadShow(test::validShowPath());
  EXPECT_TRUE(a.ok());
  a->cueLists = {CueList{"Main", {Cue{.number = "1", .label = "", .fadeS = 2.0, .delayS = 0.0, .followS = {}, .values = {}}}}};
  std::string text = showToText(*a);
  const std::string key = "\"values\": {}";
  const size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << text;
  text.replace(at, key.size(), "\"values\": {\"101\": " + values + "}");
  return text;
}

TEST(OpticsValues, ReadAndWriteBack) {
  ShowParse p = parseShowText(withValues(R"({"intensity": 1, "frost": 0.5, "prism": "3-facet", "prism_rotation": 30,
      "blades": [[0.1, 0.2], [0, 0], [0.5, 0.25], [0, 1]], "blade_rotation": -10,
      "shutter": {"strobe_hz": 12.5, "duty": 0.3, "mode": "random"}})"), test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  const CueValues& v = p.show.cueLists[0].cues[0].values.at(101);
  EXPECT_FLOAT_EQ(*v.frost, 0.5f);
  EXPECT_EQ(*v.prism, "3-facet");
  EXPECT_FLOAT_EQ(*v.prismRotationDeg, 30.0f);
  EXPECT_FLOAT_EQ((*v.blades)[2].y, 0.25f);
  EXPECT_FLOAT_EQ((*v.blades)[3].y, 1.0f);
  EXPECT_FLOAT_EQ(*v.bladeRotationDeg, -10.0f);
  EXPECT_EQ(*v.shutter, (Shutter{ShutterMode::Random, 12.5f, 0.3f}));
  const std::string text = showToText(p.show);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty()) << q.problems[0].str();
  EXPECT_EQ(q.show.cueLists[0].cues[0].values.at(101), v);
  EXPECT_EQ(showToText(q.show), text);
  // "open" and "closed" as strings, a strobe without mode or duty as strobe at 0.5.
  ShowParse s = parseShowText(withValues(R"({"shutter": {"strobe_hz": 10}})"), test::validShowPath());
  ASSERT_TRUE(s.problems.empty());
  EXPECT_EQ(*s.show.cueLists[0].cues[0].values.at(101).shutter, (Shutter{ShutterMode::Strobe, 10.0f, 0.5f}));
  ShowParse c = parseShowText(withValues(R"({"shutter": "closed"})"), test::validShowPath());
  ASSERT_TRUE(c.problems.empty());
  EXPECT_EQ(c.show.cueLists[0].cues[0].values.at(101).shutter->mode, ShutterMode::Closed);
  EXPECT_NE(showToText(c.show).find("\"shutter\": \"closed\""), std::string::npos);
}

// The second gobo wheel and the spins: read, written back byte-stable, absent when not given.
TEST(OpticsValues, SecondGoboAndSpinsReadAndWriteBack) {
  ShowParse p = parseShowText(withValues(R"({"gobo2": "Leaves", "gobo2_rotation": -20, "gobo_spin": 30,
      "gobo2_spin": -45.5, "prism_spin": 90})"), test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  const CueValues& v = p.show.cueLists[0].cues[0].values.at(101);
  EXPECT_EQ(*v.gobo2, "Leaves");
  EXPECT_FLOAT_EQ(*v.gobo2RotationDeg, -20.0f);
  EXPECT_FLOAT_EQ(*v.goboSpinDegS, 30.0f);
  EXPECT_FLOAT_EQ(*v.gobo2SpinDegS, -45.5f);
  EXPECT_FLOAT_EQ(*v.prismSpinDegS, 90.0f);
  const std::string text = showToText(p.show);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty()) << q.problems[0].str();
  EXPECT_EQ(q.show.cueLists[0].cues[0].values.at(101), v);
  EXPECT_EQ(showToText(q.show), text);
  // A cue without them writes none of their keys.
  ShowParse plain = parseShowText(withValues(R"({"intensity": 1, "gobo_rotation": 5})"), test::validShowPath());
  ASSERT_TRUE(plain.problems.empty());
  const std::string plainText = showToText(plain.show);
  for (const char* key : {"gobo2", "_spin"}) EXPECT_EQ(plainText.find(key), std::string::npos) << key;
  // A spin past 100 turns a second is a slip.
  ShowParse fast = parseShowText(withValues(R"({"gobo_spin": 40000})"), test::validShowPath());
  ASSERT_FALSE(fast.problems.empty());
  EXPECT_EQ(fast.problems[0].place, "/cue_lists/0/cues/0/values/101/gobo_spin");
}

TEST(OpticsValues, SecondGoboSwitchesItsRotationAndSpinsFade) {
  Attributes from, to;
  to.gobo2 = "Leaves";
  to.gobo2RotationDeg = 90.0f;
  to.goboSpinDegS = 40.0f;
  to.gobo2SpinDegS = -20.0f;
  to.prismSpinDegS = 10.0f;
  const Attributes half = blendAttributes(from, to, 0.5, std::nullopt);
  EXPECT_EQ(half.gobo2, "Leaves");  // switched when the fade started, as gobo does
  EXPECT_FLOAT_EQ(half.gobo2RotationDeg, 45.0f);
  EXPECT_FLOAT_EQ(half.goboSpinDegS, 20.0f);
  EXPECT_FLOAT_EQ(half.gobo2SpinDegS, -10.0f);
  EXPECT_FLOAT_EQ(half.prismSpinDegS, 5.0f);
  EXPECT_EQ(blendAttributes(from, to, -1.0, std::nullopt).gobo2, "Open");
  Attributes a;
  CueValues v;
  v.gobo2 = "Leaves";
  v.gobo2SpinDegS = 12.0f;
  overlayValues(a, v);
  EXPECT_EQ(a.gobo2, "Leaves");
  EXPECT_FLOAT_EQ(a.gobo2SpinDegS, 12.0f);
  EXPECT_EQ(a.gobo, "Open");
  // A look recorded from the stage carries them only where they are in.
  EXPECT_FALSE(cueValuesOf(Attributes{}).gobo2.has_value());
  EXPECT_FALSE(cueValuesOf(Attributes{}).goboSpinDegS.has_value());
  EXPECT_EQ(*cueValuesOf(a).gobo2, "Leaves");
  EXPECT_FLOAT_EQ(*cueValuesOf(a).gobo2SpinDegS, 12.0f);
}

// The animation wheel's slot, angle and spin: read and written back byte-stable, the slot
// switching when the beam's fade starts and the angle and spin fading.
TEST(OpticsValues, AnimationWheelReadsWritesSwitchesAndFades) {
  ShowParse p = parseShowText(withValues(R"({"animation": "Flames", "animation_rotation": 12.5, "animation_spin": -8})"),
                              test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  const CueValues& v = p.show.cueLists[0].cues[0].values.at(101);
  EXPECT_EQ(*v.animation, "Flames");
  EXPECT_FLOAT_EQ(*v.animationRotationDeg, 12.5f);
  EXPECT_FLOAT_EQ(*v.animationSpinDegS, -8.0f);
  const std::string text = showToText(p.show);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty()) << q.problems[0].str();
  EXPECT_EQ(q.show.cueLists[0].cues[0].values.at(101), v);
  EXPECT_EQ(showToText(q.show), text);
  ShowParse fast = parseShowText(withValues(R"({"animation_spin": 40000})"), test::validShowPath());
  ASSERT_FALSE(fast.problems.empty());
  EXPECT_EQ(fast.problems[0].place, "/cue_lists/0/cues/0/values/101/animation_spin");
  ShowParse bad = parseShowText(withValues(R"({"animation": 3})"), test::validShowPath());
  ASSERT_FALSE(bad.problems.empty());
  EXPECT_EQ(bad.problems[0].place, "/cue_lists/0/cues/0/values/101/animation");

  Attributes from, to;
  to.animation = "Flames";
  to.animationRotationDeg = 40.0f;
  to.animationSpinDegS = 20.0f;
  const Attributes half = blendAttributes(from, to, 0.5, std::nullopt);
  EXPECT_EQ(half.animation, "Flames");
  EXPECT_FLOAT_EQ(half.animationRotationDeg, 20.0f);
  EXPECT_FLOAT_EQ(half.animationSpinDegS, 10.0f);
  EXPECT_EQ(blendAttributes(from, to, -1.0, std::nullopt).animation, "Open");
  EXPECT_FALSE(cueValuesOf(Attributes{}).animation.has_value());
  EXPECT_EQ(*cueValuesOf(to).animation, "Flames");
}

// The lens's focus (docs/physics.md, "Focus"): read and written back byte-stable as "focus",
// refused outside 0..1 at its place, fading linearly, recorded only away from its default, and
// laid over by palettes of the beam kind.
TEST(OpticsValues, FocusReadsWritesFadesAndIsRefusedOutsideItsRange) {
  ShowParse p = parseShowText(withValues(R"({"focus": 0.25})"), test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  const CueValues& v = p.show.cueLists[0].cues[0].values.at(101);
  EXPECT_FLOAT_EQ(*v.gateFocus, 0.25f);
  const std::string text = showToText(p.show);
  EXPECT_NE(text.find("\"focus\": 0.25"), std::string::npos);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty()) << q.problems[0].str();
  EXPECT_EQ(q.show.cueLists[0].cues[0].values.at(101), v);
  EXPECT_EQ(showToText(q.show), text);
  for (const char* value : {R"({"focus": 1.5})", R"({"focus": -0.1})", R"({"focus": "sharp"})"}) {
    ShowParse bad = parseShowText(withValues(value), test::validShowPath());
    ASSERT_FALSE(bad.problems.empty()) << value;
    EXPECT_EQ(bad.problems[0].place, "/cue_lists/0/cues/0/values/101/focus") << value;
  }
  Attributes from, to;
  from.gateFocus = 0.2f;
  to.gateFocus = 1.0f;
  EXPECT_FLOAT_EQ(blendAttributes(from, to, 0.25, std::nullopt).gateFocus, 0.4f);
  EXPECT_FALSE(cueValuesOf(Attributes{}).gateFocus.has_value());
  EXPECT_FLOAT_EQ(*cueValuesOf(to).gateFocus, 1.0f);
}

TEST(OpticsValues, RefusedAtTheirPlace) {
  const std::pair<const char*, const char*> bad[] = {
      {R"({"frost": 1.5})", "/frost"},
      {R"({"blades": [[0, 0], [0, 0], [0, 0]]})", "/blades"},
      {R"({"blades": [[0, 0], [0, 2], [0, 0], [0, 0]]})", "/blades/1/1"},
      {R"({"blades": [[0, 0], [0], [0, 0], [0, 0]]})", "/blades/1"},
      {R"({"shutter": "strobe"})", "/shutter"},
      {R"({"shutter": {"duty": 0.5}})", "/shutter/strobe_hz"},
      {R"({"shutter": {"strobe_hz": 500}})", "/shutter/strobe_hz"},
      {R"({"shutter": {"strobe_hz": 5, "duty": 0}})", "/shutter/duty"},
      {R"({"shutter": {"strobe_hz": 5, "mode": "open"}})", "/shutter/mode"},
      {R"({"shutter": {"strobe_hz": 5, "rate": 3}})", "/shutter/rate"},
      {R"({"prism": ""})", "/prism"},
  };
  for (const auto& [values, where] : bad) {
    ShowParse p = parseShowText(withValues(values), test::validShowPath());
    ASSERT_FALSE(p.problems.empty()) << values;
    EXPECT_EQ(p.problems[0].place, std::string("/cue_lists/0/cues/0/values/101") + where) << values << ": " << p.problems[0].str();
  }
}

TEST(OpticsValues, FadeOrSwitchLikeTheOthers) {
  Attributes from, to;
  to.frost = 1.0f;
  to.prism = "3-facet";
  to.prismRotationDeg = 90.0f;
  to.blades[1] = {0.5f, 1.0f};
  to.bladeRotationDeg = 20.0f;
  to.shutter = Shutter{ShutterMode::Strobe, 10.0f, 0.5f};
  const Attributes half = blendAttributes(from, to, 0.5, std::nullopt);
  EXPECT_FLOAT_EQ(half.frost, 0.5f);
  EXPECT_FLOAT_EQ(half.prismRotationDeg, 45.0f);
  EXPECT_FLOAT_EQ(half.blades[1].x, 0.25f);
  EXPECT_FLOAT_EQ(half.blades[1].y, 0.5f);
  EXPECT_FLOAT_EQ(half.bladeRotationDeg, 10.0f);
  EXPECT_EQ(half.prism, "3-facet");  // switched when the fade started
  EXPECT_EQ(half.shutter, to.shutter);
  const Attributes before = blendAttributes(from, to, -1.0, std::nullopt);
  EXPECT_EQ(before.prism, "Open");
  EXPECT_EQ(before.shutter.mode, ShutterMode::Open);
  // Tracking lays a cue's optics over the state.
  Attributes a;
  CueValues v;
  v.shutter = Shutter{ShutterMode::Closed, 0.0f, 0.5f};
  v.frost = 0.25f;
  overlayValues(a, v);
  EXPECT_EQ(a.shutter.mode, ShutterMode::Closed);
  EXPECT_FLOAT_EQ(a.frost, 0.25f);
  EXPECT_EQ(a.prism, "Open");
}

}  // namespace
}  // namespace haze
