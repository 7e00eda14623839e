// The GUI's command layer: every command does what it says, refuses bad input without changing
// anything, and undo then redo give back exactly the show before and after (compared as the text a
// save writes, plus the programmer).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "shows/edit/edit_commands.h"
#include "shows/playback.h"
#include "shows/palettes.h"
#include "shows/show_json.h"
#include "unit/shows/show_test_data.h"

namespace haze {
namespace {

std::shared_ptr<Profile> makeProfile(const std::string& name, std::vector<std::pair<std::string, int>> modes) {
  auto p = std::make_shared<Profile>();
  p->name = name;
  for (auto& [modeName, footprint] : modes) {
    DmxMode m;
    m.name = modeName;
    m.channels.resize(static_cast<size_t>(footprint));
    p->modes.push_back(m);
  }
  return p;
}

std::string valuesText(const CueValues& v) {
  std::ostringstream o;
  auto f = [&](const char* n, const std::optional<float>& x) { if (x) o << n << "=" << *x << " "; };
  f("i", v.intensity); f("p", v.panDeg); f("t", v.tiltDeg); f("z", v.zoomDeg); f("gr", v.goboRotationDeg); f("ir", v.iris);
  if (v.color) o << "c=" << v.color->x << "," << v.color->y << "," << v.color->z << " ";
  if (v.gobo) o << "g=" << *v.gobo << " ";
  return o.str();
}

// A built show: two profiles, three fixtures, one cue list with cues 1 and 2.
struct Bench {
  Show show;
  Programmer programmer;
  ProfileSet profiles;
  EditHistory history;
  EditTarget target{show, programmer, profiles};

  Bench() {
    profiles["spot"] = makeProfile("Spot", {{"Standard", 10}, {"Basic", 4}});
    profiles["par"] = makeProfile("Par", {{"RGB", 4}});
    show.profiles["spot"] = ProfileRef{"profiles/spot.json", std::nullopt, false};
    show.profiles["par"] = ProfileRef{"profiles/par.json", std::nullopt, false};
    show.fixtures.push_back(FixtureDef{1, "Spot 1", "spot", "Standard", {-2, 6, 0}, {0, 0, 0}, Patch{1, 1}});
    show.fixtures.push_back(FixtureDef{2, "Spot 2", "spot", "Standard", {2, 6, 0}, {0, 90, 0}, Patch{1, 21}});
    show.fixtures.push_back(FixtureDef{5, "Par 5", "par", "RGB", {0, 5, 3}, {0, 0, 0}, std::nullopt});
    CueList main;
    main.name = "Main";
    Cue c1;
    c1.number = "1";
    c1.label = "Preset";
    c1.fadeS = 3;
    c1.values[1] = CueValues{.intensity = 1.0f, .panDeg = 30.0f};
    c1.values[5] = CueValues{.intensity = 0.5f};
    Cue c2;
    c2.number = "2";
    c2.values[1] = CueValues{.panDeg = 45.0f};
    c2.values[2] = CueValues{.intensity = 1.0f, .tiltDeg = 20.0f};
    main.cues = {c1, c2};
    show.cueLists.push_back(main);
  }

  // Everything an edit may change, as text.
  std::string snapshot() const {
    std::string s = showToText(show) + "\nprogrammer:";
    for (const auto& [id, v] : programmer.values) s += " " + std::to_string(id) + "{" + valuesText(v) + "}";
    return s;
  }
  Status run(std::unique_ptr<EditCommand> c, bool merge = false) { return history.run(target, std::move(c), merge); }
  const CueList& main() const { return show.cueLists.front(); }
  const Cue& cue(const std::string& n) const { return main().cues[findCue(main(), n).value()]; }
};

// Runs a command that must succeed, then checks undo gives `before` back and redo `after`.
void expectRoundTrip(Bench& b, std::unique_ptr<EditCommand> c) {
  std::string before = b.snapshot();
  Status s = b.run(std::move(c));
  ASSERT_TRUE(s.ok()) << s.error().str();
  std::string after = b.snapshot();
  EXPECT_NE(before, after) << "the command changed nothing";
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_EQ(b.snapshot(), before);
  ASSERT_TRUE(b.history.redo(b.target));
  EXPECT_EQ(b.snapshot(), after);
}

// A command that must fail and leave everything as it was.
void expectRefused(Bench& b, std::unique_ptr<EditCommand> c, const std::string& messagePart) {
  std::string before = b.snapshot();
  size_t steps = b.history.undoSteps();
  Status s = b.run(std::move(c));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().str().find(messagePart), std::string::npos) << s.error().str();
  EXPECT_EQ(b.snapshot(), before);
  EXPECT_EQ(b.history.undoSteps(), steps);
}

TEST(EditFixtures, PlaceTakesTheNextIdAndTheFirstGapThatFitsTheFootprint) {
  Bench b;
  // Universe 1 holds 1..10 and 21..30: a 10-slot mode fits at 11, the next one at 31.
  EXPECT_EQ(nextFreeAddress(b.show, b.profiles, 1, 10).value(), 11);
  EXPECT_EQ(nextFreeAddress(b.show, b.profiles, 1, 11).value(), 31);
  EXPECT_EQ(nextFreeAddress(b.show, b.profiles, 2, 10).value(), 1);
  EXPECT_EQ(nextFreeAddress(b.show, b.profiles, 1, 10, /*ignoreId=*/1).value(), 1);
  expectRoundTrip(b, placeFixture({"spot", "", {1, 7, 2}, {0, 45, 0}, "", 1}));
  const FixtureDef& f = b.show.fixtures.back();
  EXPECT_EQ(f.id, 6);
  EXPECT_EQ(f.name, "Spot 6");
  EXPECT_EQ(f.mode, "Standard");
  EXPECT_EQ(f.position, glm::vec3(1, 7, 2));
  EXPECT_EQ(f.rotationDeg, glm::vec3(0, 45, 0));
  ASSERT_TRUE(f.patch);
  EXPECT_EQ(f.patch->universe, 1);
  EXPECT_EQ(f.patch->address, 11);
  ASSERT_TRUE(b.run(placeFixture({"spot", "Basic", {}, {}, "Side", 1})).ok());
  EXPECT_EQ(b.show.fixtures.back().patch->address, 31);  // 1..30 are all taken now
  EXPECT_EQ(b.show.fixtures.back().name, "Side");
  ASSERT_TRUE(b.run(placeFixture({"par", "", {}, {}, "", std::nullopt})).ok());
  EXPECT_FALSE(b.show.fixtures.back().patch);
}

TEST(EditFixtures, PlaceRefusesUnknownProfilesModesAndFullUniverses) {
  Bench b;
  expectRefused(b, placeFixture({"moving head", "", {}, {}, "", 1}), "moving head");
  expectRefused(b, placeFixture({"spot", "Extended", {}, {}, "", 1}), "Extended");
  expectRefused(b, placeFixture({"spot", "", {NAN, 0, 0}, {}, "", 1}), "finite");
  // Fill universe 3 with 4-slot fixtures: 128 fit, the 129th does not.
  for (int i = 0; i < 128; ++i) ASSERT_TRUE(b.run(placeFixture({"par", "", {}, {}, "", 3})).ok()) << i;
  EXPECT_EQ(b.show.fixtures.back().patch->address, 509);
  expectRefused(b, placeFixture({"par", "", {}, {}, "", 3}), "universe 3");
}

TEST(EditFixtures, DeleteTakesTheirCueAndProgrammerValuesAndUndoPutsThemBackInPlace) {
  Bench b;
  ASSERT_TRUE(b.run(setProgrammer({{2, CueValues{.panDeg = 10.0f}}, {5, CueValues{.iris = 0.5f}}})).ok());
  expectRoundTrip(b, deleteFixtures({2}));
  ASSERT_EQ(b.show.fixtures.size(), 2u);
  EXPECT_FALSE(b.show.findFixture(2));
  EXPECT_FALSE(b.cue("2").values.count(2));
  EXPECT_FALSE(b.programmer.values.count(2));
  EXPECT_TRUE(b.programmer.values.count(5));
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_EQ(b.show.fixtures[1].id, 2);  // back in the middle, not at the end
  expectRoundTrip(b, deleteFixtures({5, 1}));
  EXPECT_EQ(b.show.fixtures.size(), 1u);
  expectRefused(b, deleteFixtures({2, 99}), "99");
  expectRefused(b, deleteFixtures({}), "at least one");
}

TEST(EditFixtures, DeleteTakesTheFixtureOutOfGroupsAndPalettesAndUndoPutsItBack) {
  Bench b;
  b.show.groups.push_back(GroupDef{"Spots", {1, 2}});
  PaletteDef centre{"Centre", PaletteKind::Position, {{"Spots", CueValues{.panDeg = 5.0f}}},
                    {{2, CueValues{.panDeg = 7.0f}}}};
  b.show.palettes.push_back(centre);
  b.show.cueLists[0].cues[0].values[1].palettes.position = "Centre";
  expectRoundTrip(b, deleteFixtures({2}));
  EXPECT_EQ(b.show.groups[0].fixtures, std::vector<int>{1});
  EXPECT_FALSE(b.show.palettes[0].fixtures.count(2));
  EXPECT_TRUE(checkGroupsAndPalettes(b.show).empty());  // the show still loads after a save
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_EQ(b.show.groups[0].fixtures, (std::vector<int>{1, 2}));
  EXPECT_TRUE(b.show.palettes[0].fixtures.count(2));
}

TEST(EditFixtures, MoveAndRotateAndAFoldedDragUndoInOneStep) {
  Bench b;
  expectRoundTrip(b, moveFixture(2, {3, 6.5f, -1}));
  EXPECT_EQ(b.show.findFixture(2)->position, glm::vec3(3, 6.5f, -1));
  expectRoundTrip(b, rotateFixture(2, {180, 0, 0}));
  EXPECT_EQ(b.show.findFixture(2)->rotationDeg, glm::vec3(180, 0, 0));
  expectRoundTrip(b, renameFixture(2, "Stage left"));
  EXPECT_EQ(b.show.findFixture(2)->name, "Stage left");
  expectRefused(b, moveFixture(42, {}), "42");

  std::string before = b.snapshot();
  size_t steps = b.history.undoSteps();
  for (int i = 1; i <= 20; ++i) ASSERT_TRUE(b.run(moveFixture(1, {0.1f * i, 6, 0}), /*merge=*/true).ok());
  EXPECT_EQ(b.history.undoSteps(), steps + 1);
  EXPECT_EQ(b.history.undoLabel(), "Move fixture 1");
  std::string after = b.snapshot();
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_EQ(b.snapshot(), before);
  ASSERT_TRUE(b.history.redo(b.target));
  EXPECT_EQ(b.snapshot(), after);
  EXPECT_EQ(b.show.findFixture(1)->position, glm::vec3(0.1f * 20, 6, 0));
  // A move of another fixture is a new step even when merging.
  ASSERT_TRUE(b.run(moveFixture(2, {0, 0, 0}), true).ok());
  EXPECT_EQ(b.history.undoSteps(), steps + 2);
}

TEST(EditFixtures, PatchChecksFootprintRangeAndOverlaps) {
  Bench b;
  expectRoundTrip(b, patchFixture(5, Patch{1, 11}));
  EXPECT_EQ(b.show.findFixture(5)->patch->address, 11);
  // Spot 1 (10 slots at 1) overlaps the par at 11..14 when moved to 5..14.
  expectRefused(b, patchFixture(1, Patch{1, 5}), "overlap fixture 5");
  // The Basic mode is 4 slots: 5..8 is free.
  expectRoundTrip(b, patchFixture(1, Patch{1, 5}, "Basic"));
  EXPECT_EQ(b.show.findFixture(1)->mode, "Basic");
  expectRefused(b, patchFixture(2, Patch{1, 504}), "does not fit");  // 504..513
  expectRoundTrip(b, patchFixture(2, Patch{1, 503}));                 // 503..512
  expectRefused(b, patchFixture(2, Patch{0, 1}), "universe 0");
  expectRefused(b, patchFixture(2, Patch{2, 1}, "Huge"), "Huge");
  expectRoundTrip(b, patchFixture(2, std::nullopt));
  EXPECT_FALSE(b.show.findFixture(2)->patch);
}

TEST(EditProgrammer, SetLaysValuesOverAndClearTakesThemOut) {
  Bench b;
  expectRoundTrip(b, setProgrammer({{1, CueValues{.panDeg = 10.0f}}}));
  expectRoundTrip(b, setProgrammer({{1, CueValues{.tiltDeg = -20.0f, .gobo = std::string("Stars")}}}));
  EXPECT_EQ(b.programmer.values.at(1), (CueValues{.panDeg = 10.0f, .tiltDeg = -20.0f, .gobo = std::string("Stars")}));
  expectRefused(b, setProgrammer({{3, CueValues{.panDeg = 1.0f}}}), "3");
  expectRefused(b, setProgrammer({{1, CueValues{.panDeg = INFINITY}}}), "finite");
  // On stage the programmer wins over playback.
  StageState stage = withProgrammer(trackedState(b.show, b.profiles, b.main(), 1), b.programmer, b.show);
  EXPECT_EQ(stage.at(1).panDeg, 10.0f);
  EXPECT_EQ(stage.at(1).intensity, 1.0f);  // from cue 1, tracked
  EXPECT_EQ(stage.at(1).gobo, "Stars");
  expectRoundTrip(b, clearProgrammer());
  EXPECT_TRUE(b.programmer.values.empty());
}

TEST(EditProgrammer, AFoldedFaderDragRedoesToItsLastValue) {
  Bench b;
  std::string before = b.snapshot();
  for (int i = 0; i <= 10; ++i)
    ASSERT_TRUE(b.run(setProgrammer({{1, CueValues{.intensity = 0.1f * i}}, {2, CueValues{.intensity = 0.1f * i}}}), true).ok());
  EXPECT_EQ(b.history.undoSteps(), 1u);
  std::string after = b.snapshot();
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_EQ(b.snapshot(), before);
  ASSERT_TRUE(b.history.redo(b.target));
  EXPECT_EQ(b.snapshot(), after);
  EXPECT_EQ(b.programmer.values.at(2).intensity, 0.1f * 10);
}

TEST(EditCues, RecordStoresOnlyWhatDiffersFromTheTrackedStateBefore) {
  Bench b;
  // Against the state of cue 2 (fixture 1: intensity 1 tracked from cue 1, pan 45, tilt 0 by
  // default; fixture 2: intensity 1, tilt 20; par: intensity 0.5) only fixture 1's pan and the
  // par's colour are new.
  ASSERT_TRUE(b.run(setProgrammer({{1, CueValues{.intensity = 1.0f, .panDeg = 60.0f, .tiltDeg = 0.0f}},
                                   {2, CueValues{.intensity = 1.0f, .tiltDeg = 20.0f}},
                                   {5, CueValues{.intensity = 0.5f, .color = glm::vec3(1, 0, 0)}}}))
                  .ok());
  expectRoundTrip(b, recordCue({"Main", "2", "", "Look 3"}));
  ASSERT_EQ(b.main().cues.size(), 3u);
  const Cue& c = b.main().cues[2];
  EXPECT_EQ(c.number, "3");
  EXPECT_EQ(c.label, "Look 3");
  ASSERT_EQ(c.values.size(), 2u);
  EXPECT_EQ(c.values.at(1), CueValues{.panDeg = 60.0f});
  EXPECT_EQ(c.values.at(5), CueValues{.color = glm::vec3(1, 0, 0)});
  // Playing the new cue gives exactly the programmer's look.
  StageState played = trackedState(b.show, b.profiles, b.main(), 2);
  StageState wanted = withProgrammer(trackedState(b.show, b.profiles, b.main(), 1), b.programmer, b.show);
  EXPECT_EQ(played, wanted);
  EXPECT_EQ(b.history.undoLabel(), "Record cue 3");
}

TEST(EditCues, RecordCarriesTheShutterAndBladesOfTheProgrammer) {
  Bench b;
  CueValues v;
  v.shutter = Shutter{ShutterMode::Strobe, 12.0f, 0.4f};
  v.blades = BladeInsertions{};
  (*v.blades)[2] = {0.3f, 0.1f};
  v.frost = 0.0f;  // what fixture 1 has already: not recorded
  ASSERT_TRUE(b.run(setProgrammer({{1, v}})).ok());
  expectRoundTrip(b, recordCue({"Main", "2", "", "Strobe"}));
  const Cue& c = b.main().cues[2];
  ASSERT_EQ(c.values.size(), 1u);
  CueValues want;
  want.shutter = v.shutter;
  want.blades = v.blades;
  EXPECT_EQ(c.values.at(1), want);
  StageState played = trackedState(b.show, b.profiles, b.main(), 2);
  EXPECT_EQ(played.at(1).shutter, *v.shutter);
  EXPECT_FLOAT_EQ(played.at(1).blades[2].x, 0.3f);
  CueValues bad;
  bad.shutter = Shutter{ShutterMode::Strobe, NAN, 0.5f};
  expectRefused(b, setProgrammer({{1, bad}}), "finite");
}

TEST(EditCues, RecordNumbersBetweenNeighboursAndAtTheStart) {
  Bench b;
  ASSERT_TRUE(b.run(setProgrammer({{2, CueValues{.intensity = 0.25f}}})).ok());
  expectRoundTrip(b, recordCue({"Main", "1", "", ""}));
  EXPECT_EQ(b.main().cues[1].number, "1.5");
  // After cue 1 and at the start, fixture 2 is at intensity 0 (untouched by cue 1).
  EXPECT_EQ(b.main().cues[1].values.at(2), CueValues{.intensity = 0.25f});
  ASSERT_TRUE(b.run(recordCue({"", "1", "", ""})).ok());
  EXPECT_EQ(b.main().cues[1].number, "1.2");
  expectRoundTrip(b, recordCue({"Main", "", "", "Pre"}));
  EXPECT_EQ(b.main().cues.front().number, "0.5");
  EXPECT_EQ(b.main().cues.front().values.at(2), CueValues{.intensity = 0.25f});
  expectRoundTrip(b, recordCue({"Main", "2", "7", ""}));
  EXPECT_EQ(b.main().cues.back().number, "7");
  expectRefused(b, recordCue({"Main", "1", "2.5", ""}), "between its neighbours");
  expectRefused(b, recordCue({"Main", "1", "1.5", ""}), "between its neighbours");
  expectRefused(b, recordCue({"Main", "1", "one", ""}), "not a cue number");
  expectRefused(b, recordCue({"Main", "9", "", ""}), "9");
}

TEST(EditCues, RecordIntoAShowWithoutListsCreatesOne) {
  Bench b;
  b.show.cueLists.clear();
  ASSERT_TRUE(b.run(setProgrammer({{1, CueValues{.intensity = 1.0f}}})).ok());
  expectRoundTrip(b, recordCue({"", "", "", ""}));
  ASSERT_EQ(b.show.cueLists.size(), 1u);
  EXPECT_EQ(b.show.cueLists[0].name, "Main");
  EXPECT_EQ(b.show.cueLists[0].cues.at(0).number, "1");
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_TRUE(b.show.cueLists.empty());
}

TEST(EditCues, UpdateSetsChangesAndDropsValuesThatNowTrack) {
  Bench b;
  // Cue 2 sets fixture 1's pan to 45; pan 30 is what cue 1 gives, so cue 2 should just track it.
  ASSERT_TRUE(b.run(setProgrammer({{1, CueValues{.panDeg = 30.0f}}, {5, CueValues{.iris = 0.3f}}})).ok());
  expectRoundTrip(b, updateCue("Main", "2"));
  EXPECT_FALSE(b.cue("2").values.count(1));
  EXPECT_EQ(b.cue("2").values.at(5), CueValues{.iris = 0.3f});
  EXPECT_EQ(b.cue("2").values.at(2), (CueValues{.intensity = 1.0f, .tiltDeg = 20.0f}));
  EXPECT_EQ(trackedState(b.show, b.profiles, b.main(), 1).at(1).panDeg, 30.0f);
  expectRefused(b, updateCue("Main", "4"), "4");
  expectRefused(b, updateCue("Other", "1"), "Other");
}

TEST(EditCues, DeleteRenumberLabelAndTimes) {
  Bench b;
  expectRoundTrip(b, deleteCue("Main", "1"));
  EXPECT_EQ(b.main().cues.size(), 1u);
  ASSERT_TRUE(b.history.undo(b.target));

  // Renumbering 1 to 3 moves it after cue 2.
  expectRoundTrip(b, renumberCue("Main", "1", "3"));
  EXPECT_EQ(b.main().cues[0].number, "2");
  EXPECT_EQ(b.main().cues[1].number, "3");
  EXPECT_EQ(b.main().cues[1].label, "Preset");
  expectRefused(b, renumberCue("Main", "3", "2.0"), "already exists");
  expectRefused(b, renumberCue("Main", "3", "x"), "not a cue number");

  expectRoundTrip(b, labelCue("Main", "2", "Blackout"));
  EXPECT_EQ(b.cue("2").label, "Blackout");
  expectRoundTrip(b, setCueTimes("Main", "2", CueTimes{2.5, 1.0, 4.0}));
  EXPECT_EQ(b.cue("2").fadeS, 2.5);
  EXPECT_EQ(b.cue("2").delayS, 1.0);
  EXPECT_EQ(b.cue("2").followS, 4.0);
  expectRoundTrip(b, setCueTimes("Main", "2", CueTimes{2.5, 1.0, std::nullopt}));
  EXPECT_FALSE(b.cue("2").followS);
  expectRefused(b, setCueTimes("Main", "2", CueTimes{-1.0, 0.0, std::nullopt}), "seconds");
  expectRefused(b, setCueTimes("Main", "2", CueTimes{NAN, 0.0, std::nullopt}), "seconds");
}

TEST(EditShow, AtmosphereIsCheckedAndUndone) {
  Bench b;
  AtmosphereDef a;
  a.scattering = 0.05f;
  a.phase = "hg";
  a.g = 0.6f;
  a.ambient = glm::vec3(0.02f);
  expectRoundTrip(b, setAtmosphere(a));
  EXPECT_EQ(b.show.atmosphere.phase, "hg");
  a.phase = "foggy";
  expectRefused(b, setAtmosphere(a), "foggy");
  a.phase = "hg";
  a.g = 1.0f;
  expectRefused(b, setAtmosphere(a), "-0.99..0.99");
  a.g = 0.0f;
  a.absorption = -0.1f;
  expectRefused(b, setAtmosphere(a), ">= 0");
}

TEST(EditHistoryTest, RedoIsDroppedByANewEditAndModifiedFollowsTheSavedState) {
  Bench b;
  EXPECT_FALSE(b.history.canUndo());
  EXPECT_FALSE(b.history.undo(b.target));
  EXPECT_FALSE(b.history.modified());
  ASSERT_TRUE(b.run(moveFixture(1, {0, 0, 0})).ok());
  EXPECT_TRUE(b.history.modified());
  b.history.markSaved();
  EXPECT_FALSE(b.history.modified());
  ASSERT_TRUE(b.run(moveFixture(1, {1, 0, 0}), true).ok());  // not folded into the saved step
  EXPECT_TRUE(b.history.modified());
  EXPECT_EQ(b.history.undoSteps(), 2u);
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_FALSE(b.history.modified());
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_TRUE(b.history.modified());
  EXPECT_TRUE(b.history.canRedo());
  EXPECT_EQ(b.history.redoLabel(), "Move fixture 1");
  ASSERT_TRUE(b.run(renameFixture(1, "A")).ok());
  EXPECT_FALSE(b.history.canRedo());
  EXPECT_TRUE(b.history.modified());  // the saved state is gone for good
  ASSERT_TRUE(b.history.undo(b.target));
  EXPECT_TRUE(b.history.modified());
}

TEST(EditHistoryTest, KeepsAtMostMaxSteps) {
  Bench b;
  b.history = EditHistory(3);
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(b.run(moveFixture(1, {static_cast<float>(i), 0, 0})).ok());
  EXPECT_EQ(b.history.undoSteps(), 3u);
  while (b.history.undo(b.target)) {
  }
  EXPECT_EQ(b.show.findFixture(1)->position, glm::vec3(1, 0, 0));  // moves 0 and 1 stay applied
  EXPECT_TRUE(b.history.modified());
}

// Many random edits, then undo all of them: the show comes back byte for byte; redo all: the end
// state comes back.
TEST(EditHistoryTest, RandomEditSequencesUndoAndRedoExactly) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Bench b;
    std::mt19937 rng(seed);
    auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    auto anyFixture = [&]() { return b.show.fixtures.empty() ? 1 : b.show.fixtures[pick(static_cast<int>(b.show.fixtures.size()))].id; };
    auto anyCue = [&]() { return b.main().cues.empty() ? std::string("1") : b.main().cues[pick(static_cast<int>(b.main().cues.size()))].number; };
    std::vector<std::string> states{b.snapshot()};
    for (int step = 0; step < 60; ++step) {
      std::unique_ptr<EditCommand> c;
      switch (pick(12)) {
        case 0: c = placeFixture({pick(2) ? "spot" : "par", "", {float(pick(9)), 6, 0}, {}, "", 1 + pick(2)}); break;
        case 1: c = deleteFixtures({anyFixture()}); break;
        case 2: c = moveFixture(anyFixture(), {float(pick(9)), float(pick(9)), 0}); break;
        case 3: c = rotateFixture(anyFixture(), {0, float(pick(360)), 0}); break;
        case 4: c = setProgrammer({{anyFixture(), CueValues{.intensity = pick(5) / 4.0f, .panDeg = float(pick(3) * 30)}}}); break;
        case 5: c = recordCue({"Main", pick(3) ? anyCue() : "", "", ""}); break;
        case 6: c = updateCue("Main", anyCue()); break;
        case 7: c = deleteCue("Main", anyCue()); break;
        case 8: c = renumberCue("Main", anyCue(), std::to_string(pick(20)) + (pick(2) ? ".5" : "")); break;
        case 9: c = patchFixture(anyFixture(), Patch{1, 1 + pick(500)}); break;
        case 10: c = clearProgrammer(); break;
        default: c = setCueTimes("Main", anyCue(), CueTimes{double(pick(5)), 0.0, std::nullopt}); break;
      }
      if (b.run(std::move(c)).ok()) states.push_back(b.snapshot());
      else EXPECT_EQ(b.snapshot(), states.back());
    }
    ASSERT_GT(states.size(), 20u) << "seed " << seed;
    for (size_t i = states.size() - 1; i > 0; --i) {
      ASSERT_TRUE(b.history.undo(b.target));
      ASSERT_EQ(b.snapshot(), states[i - 1]) << "seed " << seed << " undo to state " << i - 1;
    }
    EXPECT_FALSE(b.history.undo(b.target));
    for (size_t i = 1; i < states.size(); ++i) {
      ASSERT_TRUE(b.history.redo(b.target));
      ASSERT_EQ(b.snapshot(), states[i]) << "seed " << seed << " redo to state " << i;
    }
  }
}

// On a show loaded from a file: edits then undo leave the text a save writes unchanged.
TEST(EditHistoryTest, UndoOnALoadedShowGivesBackItsSavedText) {
  test::LoadedShow loaded = test::loadValidShow();
  ASSERT_FALSE(loaded.show.fixtures.empty());
  Programmer programmer;
  EditTarget t{loaded.show, programmer, loaded.profiles};
  EditHistory h;
  std::string original = showToText(loaded.show);
  int id = loaded.show.fixtures.front().id;
  ASSERT_TRUE(h.run(t, moveFixture(id, {1, 2, 3})).ok());
  ASSERT_TRUE(h.run(t, setProgrammer({{id, CueValues{.intensity = 0.7f, .tiltDeg = 33.0f}}})).ok());
  ASSERT_TRUE(h.run(t, recordCue({"", loaded.show.cueLists.front().cues.front().number, "", "new"})).ok());
  ASSERT_TRUE(h.run(t, deleteFixtures({id})).ok());
  ASSERT_TRUE(h.run(t, placeFixture({loaded.show.profiles.begin()->first, "", {}, {}, "", 1})).ok());
  EXPECT_NE(showToText(loaded.show), original);
  while (h.undo(t)) {
  }
  EXPECT_EQ(showToText(loaded.show), original);
}

}  // namespace
}  // namespace haze
