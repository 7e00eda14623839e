// The console command line (docs/gui.md, "Console commands"): every line of the doc's three
// tables is read from docs/gui.md itself and run through runCommandLine on
// tests/data/shows/console.haze.json; each example must do what this file checks for it (and
// every example needs a check here, and every check an example there, so the doc and the test
// cannot drift), each error line must give the doc's message and change nothing, and each
// completion line must offer exactly the doc's words.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <glm/glm.hpp>

#include "shows/edit/command_run.h"
#include "shows/edit/command_syntax.h"
#include "shows/palettes.h"
#include "shows/playback.h"
#include "shows/show_json.h"

namespace haze {
namespace {

namespace fs = std::filesystem;

const fs::path kShow = fs::path(HAZE_SOURCE_DIR) / "tests/data/shows/console.haze.json";

struct DocRow {
  std::string typed;
  std::vector<std::string> said;  // the second column's `quoted` parts
};

// The rows of the table under "### <title>" in the "## Console commands" section.
std::vector<DocRow> docTable(const std::string& title) {
  std::ifstream in(fs::path(HAZE_SOURCE_DIR) / "docs/gui.md");
  std::string line;
  bool inSection = false, inTable = false;
  std::vector<DocRow> rows;
  const std::regex code("`([^`]*)`");
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) inSection = line == "## Console commands";
    if (!inSection) continue;
    if (line.rfind("### ", 0) == 0) inTable = line == "### " + title;
    if (!inTable || line.rfind("| `", 0) != 0) continue;
    const size_t split = line.find("` | ");
    if (split == std::string::npos) continue;
    DocRow r;
    r.typed = line.substr(3, split - 3);
    const std::string rest = line.substr(split + 4);
    for (std::sregex_iterator m(rest.begin(), rest.end(), code), e; m != e; ++m) r.said.push_back((*m)[1]);
    rows.push_back(r);
  }
  return rows;
}

std::unique_ptr<ShowDocument> openShow() {
  auto d = ShowDocument::open(kShow);
  EXPECT_TRUE(d.ok()) << (d ? "" : d.error().str());
  return d ? std::move(*d) : nullptr;
}

// What the programmer gives a fixture: its values with its palette references resolved.
std::optional<float> programmed(const ShowDocument& d, int id, std::optional<float> CueValues::*member) {
  auto it = d.programmer().values.find(id);
  return it == d.programmer().values.end() ? std::nullopt : resolveValues(d.show(), id, it->second).*member;
}

const PaletteRefs& refsOf(const ShowDocument& d, int id) {
  static const PaletteRefs none;
  auto it = d.programmer().values.find(id);
  return it == d.programmer().values.end() ? none : it->second.palettes;
}

const PaletteDef* paletteOf(const ShowDocument& d, const std::string& name) { return d.show().findPalette(name); }

std::vector<int> range(int a, int b) {
  std::vector<int> v;
  for (int i = a; i <= b; ++i) v.push_back(i);
  return v;
}

// Every fixture in `ids` holds `value` for `member` in the programmer, and no other fixture is there.
void expectProgrammer(const ShowDocument& d, const std::vector<int>& ids, std::optional<float> CueValues::*member,
                      float value) {
  EXPECT_EQ(d.programmer().values.size(), ids.size());
  for (int id : ids) {
    auto v = programmed(d, id, member);
    ASSERT_TRUE(v.has_value()) << "fixture " << id;
    EXPECT_FLOAT_EQ(*v, value) << "fixture " << id;
  }
}

struct Example {
  std::string setup;  // run first (context the line needs; lines separated by "; ")
  bool undoStep;      // the line is one undo step
  std::function<void(ShowDocument&)> check;
};

std::map<std::string, Example> examples() {
  using V = CueValues;
  std::map<std::string, Example> e;
  e["1 thru 12 @ 50"] = {"", true, [](ShowDocument& d) {
                           EXPECT_EQ(d.selection, range(1, 12));
                           expectProgrammer(d, range(1, 12), &V::intensity, 0.5f);
                         }};
  e["1 + 3 + 5 @ full"] = {"", true, [](ShowDocument& d) { expectProgrammer(d, {1, 3, 5}, &V::intensity, 1.0f); }};
  e["1 thru 12 - 4 @ out"] = {"", true, [](ShowDocument& d) {
                                expectProgrammer(d, {1, 2, 3, 5, 6, 7, 8, 9, 10, 11, 12}, &V::intensity, 0.0f);
                              }};
  e["1 thru 6 - 2 thru 3"] = {"", false, [](ShowDocument& d) {
                                EXPECT_EQ(d.selection, (std::vector<int>{1, 4, 5, 6}));
                                EXPECT_TRUE(d.programmer().values.empty());
                              }};
  e["12-4"] = {"", false, [](ShowDocument& d) { EXPECT_EQ(d.selection, std::vector<int>{12}); }};
  e["group Front @ 80"] = {"", true, [](ShowDocument& d) { expectProgrammer(d, range(1, 6), &V::intensity, 0.8f); }};
  e["group spots sr pan 45 tilt -30"] = {"", true, [](ShowDocument& d) {
                                           expectProgrammer(d, range(7, 12), &V::panDeg, 45.0f);
                                           expectProgrammer(d, range(7, 12), &V::tiltDeg, -30.0f);
                                           EXPECT_FALSE(programmed(d, 7, &V::intensity));
                                         }};
  e["group 2 zoom 20"] = {"", true, [](ShowDocument& d) { expectProgrammer(d, range(7, 12), &V::zoomDeg, 20.0f); }};
  e["group front + 9 @ 40"] = {"", true, [](ShowDocument& d) {
                                 expectProgrammer(d, {1, 2, 3, 4, 5, 6, 9}, &V::intensity, 0.4f);
                               }};
  e["@ 75"] = {"2 + 4", true, [](ShowDocument& d) { expectProgrammer(d, {2, 4}, &V::intensity, 0.75f); }};
  e["1 thru 3 palette Centre"] = {"", true, [](ShowDocument& d) {
                                    expectProgrammer(d, {1, 2, 3}, &V::panDeg, 10.0f);
                                    expectProgrammer(d, {1, 2, 3}, &V::tiltDeg, 20.0f);
                                    for (int id : {1, 2, 3}) {
                                      EXPECT_EQ(refsOf(d, id).position, "Centre") << id;
                                      EXPECT_FALSE(d.programmer().values.at(id).panDeg) << id;  // a reference, not a copy
                                    }
                                  }};
  e["group 2 palette 2 @ 60"] = {"", true, [](ShowDocument& d) {
                                   expectProgrammer(d, range(7, 12), &V::intensity, 0.6f);
                                   for (int id : range(7, 12)) {
                                     EXPECT_EQ(refsOf(d, id).color, "Warm");
                                     const CueValues v = resolveValues(d.show(), id, d.programmer().values.at(id));
                                     ASSERT_TRUE(v.color);
                                     EXPECT_FLOAT_EQ(v.color->y, 0.8f);
                                     EXPECT_FLOAT_EQ(v.color->z, 0.6f);
                                   }
                                 }};
  e["1 iris 50 frost 20"] = {"", true, [](ShowDocument& d) {
                               expectProgrammer(d, {1}, &V::iris, 0.5f);
                               expectProgrammer(d, {1}, &V::frost, 0.2f);
                             }};
  e["record cue 7"] = {"1 @ 30", true, [](ShowDocument& d) {
                         const CueList& l = *d.cueList();
                         ASSERT_EQ(l.cues.size(), 4u);
                         EXPECT_EQ(l.cues[2].number, "7");
                         ASSERT_EQ(l.cues[2].values.size(), 1u);
                         EXPECT_FLOAT_EQ(*l.cues[2].values.at(1).intensity, 0.3f);
                       }};
  e["update cue 5"] = {"7 @ 90", true, [](ShowDocument& d) {
                         const Cue& c = d.cueList()->cues[1];
                         EXPECT_EQ(c.number, "5");
                         EXPECT_FLOAT_EQ(*c.values.at(7).intensity, 0.9f);
                       }};
  e["record cue 2/5"] = {"12 @ 80", true, [](ShowDocument& d) {
                           const CueList& specials = d.show().cueLists.at(1);
                           ASSERT_EQ(specials.cues.size(), 2u);
                           EXPECT_EQ(specials.cues[1].number, "5");
                           EXPECT_FLOAT_EQ(*specials.cues[1].values.at(12).intensity, 0.8f);
                           EXPECT_EQ(d.cueList()->cues.size(), 3u);  // Main unchanged
                         }};
  e["update cue 2/1"] = {"12 @ 90", true, [](ShowDocument& d) {
                           EXPECT_FLOAT_EQ(*d.show().cueLists.at(1).cues[0].values.at(12).intensity, 0.9f);
                         }};
  e["cue 2/1"] = {"", false, [](ShowDocument& d) {
                    EXPECT_EQ(d.listCue(1), std::optional<size_t>(0));
                    EXPECT_EQ(d.currentCue(), std::nullopt);
                  }};
  e["record palette Left"] = {"1 thru 3 pan -40 tilt 15", true, [](ShowDocument& d) {
                                const PaletteDef* p = paletteOf(d, "Left");
                                ASSERT_TRUE(p);
                                EXPECT_EQ(p->kind, PaletteKind::Position);
                                ASSERT_EQ(p->fixtures.size(), 3u);
                                for (int id : {1, 2, 3}) {
                                  EXPECT_FLOAT_EQ(*p->fixtures.at(id).panDeg, -40.0f);
                                  EXPECT_FLOAT_EQ(*p->fixtures.at(id).tiltDeg, 15.0f);
                                  EXPECT_EQ(refsOf(d, id).position, "Left");
                                }
                                expectProgrammer(d, {1, 2, 3}, &V::panDeg, -40.0f);
                              }};
  e["record beam palette Wide"] = {"group Front zoom 40 @ 50", true, [](ShowDocument& d) {
                                     const PaletteDef* p = paletteOf(d, "Wide");
                                     ASSERT_TRUE(p);
                                     EXPECT_EQ(p->kind, PaletteKind::Beam);
                                     ASSERT_EQ(p->fixtures.size(), 6u);
                                     EXPECT_FLOAT_EQ(*p->fixtures.at(4).zoomDeg, 40.0f);
                                     EXPECT_FALSE(p->fixtures.at(4).intensity);
                                     expectProgrammer(d, range(1, 6), &V::intensity, 0.5f);  // still in the programmer
                                   }};
  e["update palette Centre"] = {"1 palette Centre pan 12", true, [](ShowDocument& d) {
                                  const PaletteDef* p = paletteOf(d, "Centre");
                                  ASSERT_TRUE(p);
                                  ASSERT_EQ(p->fixtures.size(), 1u);
                                  EXPECT_FLOAT_EQ(*p->fixtures.at(1).panDeg, 12.0f);
                                  EXPECT_FALSE(p->fixtures.at(1).tiltDeg);  // the group's 20 already
                                  EXPECT_FLOAT_EQ(*paletteValuesFor(d.show(), *p, 2)->panDeg, 10.0f);
                                  EXPECT_EQ(refsOf(d, 1).position, "Centre");
                                  EXPECT_FALSE(d.programmer().values.at(1).panDeg);
                                }};
  e["delete palette Narrow"] = {"", true, [](ShowDocument& d) {
                                  EXPECT_FALSE(paletteOf(d, "Narrow"));
                                  EXPECT_EQ(d.show().palettes.size(), 2u);
                                }};
  e["record group Odd"] = {"1 + 3 + 5", true, [](ShowDocument& d) {
                             const GroupDef* g = d.show().findGroup("Odd");
                             ASSERT_TRUE(g);
                             EXPECT_EQ(g->fixtures, (std::vector<int>{1, 3, 5}));
                           }};
  e["delete group Odd"] = {"1 + 3 + 5; record group Odd", true, [](ShowDocument& d) {
                             EXPECT_FALSE(d.show().findGroup("Odd"));
                             EXPECT_EQ(d.show().groups.size(), 2u);
                           }};
  e["cue 5"] = {"", false, [](ShowDocument& d) { EXPECT_EQ(d.currentCue(), std::optional<size_t>(1)); }};
  e["go"] = {"", false, [](ShowDocument& d) { EXPECT_EQ(d.currentCue(), std::optional<size_t>(0)); }};
  e["clear"] = {"1 @ 50", true, [](ShowDocument& d) {
                  EXPECT_TRUE(d.programmer().values.empty());
                  EXPECT_TRUE(d.selection.empty());
                }};
  return e;
}

TEST(CommandLine, EveryDocExampleDoesWhatItSays) {
  const std::vector<DocRow> rows = docTable("Examples");
  const auto checks = examples();
  std::set<std::string> inDoc;
  for (const DocRow& r : rows) inDoc.insert(r.typed);
  for (const auto& [line, ex] : checks) EXPECT_TRUE(inDoc.count(line)) << "not in docs/gui.md: " << line;
  for (const DocRow& r : rows) {
    SCOPED_TRACE(r.typed);
    auto it = checks.find(r.typed);
    ASSERT_NE(it, checks.end()) << "docs/gui.md example without a check here";
    auto d = openShow();
    ASSERT_TRUE(d);
    std::stringstream setup(it->second.setup);
    for (std::string part; std::getline(setup, part, ';');) {
      auto ran = runCommandLine(*d, part, 0.0);
      ASSERT_TRUE(ran.ok()) << part << ": " << ran.error().str();
    }
    const Programmer before = d->programmer();
    const std::string showBefore = showToText(d->show());
    const size_t steps = d->history().undoSteps();
    auto said = runCommandLine(*d, r.typed, 1.0);
    ASSERT_TRUE(said.ok()) << said.error().str();
    EXPECT_FALSE(said->empty());
    it->second.check(*d);
    EXPECT_EQ(d->history().undoSteps(), steps + (it->second.undoStep ? 1 : 0));
    if (it->second.undoStep) {
      EXPECT_EQ(d->history().undoLabel(), "Command \"" + r.typed + "\"");
      ASSERT_TRUE(d->undo());
      EXPECT_EQ(d->programmer(), before);
      EXPECT_EQ(showToText(d->show()), showBefore);
      ASSERT_TRUE(d->redo());
      it->second.check(*d);
    }
  }
  EXPECT_EQ(rows.size(), checks.size());
}

TEST(CommandLine, EveryDocErrorSaysWhatWasExpectedAndChangesNothing) {
  const std::vector<DocRow> rows = docTable("Errors");
  ASSERT_GE(rows.size(), 10u);
  for (const DocRow& r : rows) {
    SCOPED_TRACE(r.typed);
    ASSERT_EQ(r.said.size(), 1u);
    auto d = openShow();
    ASSERT_TRUE(d);
    // Something selected and programmed first, so "nothing changed" covers both.
    ASSERT_TRUE(runCommandLine(*d, "5 + 6 @ 20", 0.0).ok());
    const Programmer before = d->programmer();
    const std::vector<int> selected = d->selection;
    const std::string showBefore = showToText(d->show());
    const size_t steps = d->history().undoSteps();
    const auto cue = d->currentCue();
    auto said = runCommandLine(*d, r.typed, 1.0);
    ASSERT_FALSE(said.ok());
    EXPECT_EQ(said.error().str(), r.said[0]);
    EXPECT_EQ(d->programmer(), before);
    EXPECT_EQ(d->selection, selected);
    EXPECT_EQ(showToText(d->show()), showBefore);
    EXPECT_EQ(d->history().undoSteps(), steps);
    EXPECT_EQ(d->currentCue(), cue);
  }
}

TEST(CommandLine, EveryDocCompletionOffersExactlyItsWords) {
  const std::vector<DocRow> rows = docTable("Completion");
  ASSERT_GE(rows.size(), 6u);
  auto d = openShow();
  ASSERT_TRUE(d);
  for (const DocRow& r : rows) {
    SCOPED_TRACE("'" + r.typed + "'");
    EXPECT_EQ(completeCommand(r.typed, d->show()).words, r.said);
  }
}

TEST(CommandLine, TabCompletesOneCandidateAndTheCommonPrefixOfSeveral) {
  auto d = openShow();
  ASSERT_TRUE(d);
  const Show& s = d->show();
  EXPECT_EQ(applyCompletion("gr", completeCommand("gr", s)), "group ");
  EXPECT_EQ(applyCompletion("group sp", completeCommand("group sp", s)), "group \"Spots SR\" ");
  EXPECT_EQ(applyCompletion("1@f", completeCommand("1@f", s)), "1@full ");
  EXPECT_EQ(applyCompletion("re", completeCommand("re", s)), "record ");
  // Several candidates: as far as they agree.
  EXPECT_EQ(completeCommand("1 t", s).words, (std::vector<std::string>{"thru", "tilt"}));
  EXPECT_EQ(applyCompletion("1 t", completeCommand("1 t", s)), "1 t");
  EXPECT_EQ(applyCompletion("1 thru 3 palette ", completeCommand("1 thru 3 palette ", s)), "1 thru 3 palette ");
  // A completed line parses.
  const std::string done = applyCompletion("group sp", completeCommand("group sp", s)) + "@ 50";
  EXPECT_TRUE(parseCommand(done, s).ok());
  // Nothing offered after a word that needs a number; the hint says what.
  const Completion afterThru = completeCommand("1 thru ", s);
  EXPECT_TRUE(afterThru.words.empty());
  EXPECT_EQ(afterThru.hint, "a fixture id");
  // After an error: nothing, and the error as the hint.
  const Completion bad = completeCommand("13 @ ", s);
  EXPECT_TRUE(bad.words.empty());
  EXPECT_EQ(bad.hint, "word 1: no fixture has id 13");
}

TEST(CommandLine, SplitsWordsAsDocumented) {
  auto words = [](const std::string& line) {
    std::vector<std::string> out;
    auto w = splitCommandWords(line);
    EXPECT_TRUE(w.ok());
    if (w)
      for (const CommandWord& x : *w) out.push_back(x.text);
    return out;
  };
  EXPECT_EQ(words("1+3@50"), (std::vector<std::string>{"1", "+", "3", "@", "50"}));
  EXPECT_EQ(words("1 thru 12 -4"), (std::vector<std::string>{"1", "thru", "12", "-", "4"}));
  EXPECT_EQ(words("1 tilt -30"), (std::vector<std::string>{"1", "tilt", "-30"}));
  EXPECT_EQ(words("group \"Spots SR\" @ 5"), (std::vector<std::string>{"group", "Spots SR", "@", "5"}));
}

// The demo's lines in docs/gui.md ("On the demo"), in their order, on the bundled demo show:
// its groups and palettes from the command line, recorded into a new cue.
TEST(CommandLine, TheDemoLinesInTheDocDoWhatTheySay) {
  const std::vector<DocRow> rows = docTable("On the demo");
  ASSERT_EQ(rows.size(), 3u);
  auto opened = ShowDocument::open(fs::path(HAZE_SOURCE_DIR) / "examples/demo/demo.haze.json");
  ASSERT_TRUE(opened.ok()) << opened.error().str();
  ShowDocument& d = **opened;
  for (const DocRow& r : rows) ASSERT_TRUE(runCommandLine(d, r.typed, 0.0).ok()) << r.typed;
  const CueList& list = *d.cueList();
  ASSERT_EQ(list.cues.back().number, "6");
  EXPECT_EQ(list.cues.back().values.size(), 8u);
  // Record keeps what differs from tracking; the look on stage at cue 6 is what the lines said.
  const StageState stage = trackedState(d.show(), d.profiles(), list, list.cues.size() - 1);
  auto near = [](const glm::vec3& a, const glm::vec3& b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(1e-6f))); };
  for (int id : {201, 202, 203, 204}) {
    EXPECT_FLOAT_EQ(stage.at(id).intensity, 0.5f) << id;
    EXPECT_TRUE(near(stage.at(id).color, glm::vec3(1.0f, 0.78f, 0.52f))) << id;
  }
  // The crossed-over aim of cue 4.5, beam by beam.
  const std::map<int, std::pair<float, float>> aim{{301, {-11.7f, 52.1f}}, {302, {15.2f, 59.8f}},
                                                   {303, {-15.2f, 59.8f}}, {304, {11.7f, 52.1f}}};
  for (const auto& [id, pt] : aim) {
    const Attributes& a = stage.at(id);
    EXPECT_FLOAT_EQ(a.intensity, 1.0f) << id;
    EXPECT_TRUE(near(a.color, glm::vec3(1.0f, 0.55f, 0.1f))) << id;
    EXPECT_FLOAT_EQ(a.panDeg, pt.first) << id;
    EXPECT_FLOAT_EQ(a.tiltDeg, pt.second) << id;
  }
  // The spots stay out, as at the bows.
  for (int id : {101, 102, 103, 104}) EXPECT_EQ(stage.at(id).intensity, 0.0f) << id;
}

TEST(CommandLine, SelectionAloneAndSettingsOnTheCurrentSelection) {
  auto d = openShow();
  ASSERT_TRUE(d);
  ASSERT_TRUE(runCommandLine(*d, "3 thru 1", 0.0).ok());  // either order
  EXPECT_EQ(d->selection, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(d->history().undoSteps(), 0u);
  ASSERT_TRUE(runCommandLine(*d, "pan 45 @ 10", 0.0).ok());
  expectProgrammer(*d, {1, 2, 3}, &CueValues::panDeg, 45.0f);
  EXPECT_EQ(d->history().undoSteps(), 1u);
  // A later setting wins over a palette written before it.
  ASSERT_TRUE(runCommandLine(*d, "1 palette Centre pan 5", 0.0).ok());
  EXPECT_FLOAT_EQ(*programmed(*d, 1, &CueValues::panDeg), 5.0f);
  EXPECT_FLOAT_EQ(*programmed(*d, 1, &CueValues::tiltDeg), 20.0f);
  // Nothing selected: a setting says so.
  ASSERT_TRUE(runCommandLine(*d, "clear", 0.0).ok());
  auto none = runCommandLine(*d, "@ 50", 0.0);
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error().message.find("no fixture is selected"), std::string::npos);
  // Update with an empty programmer is refused rather than an empty undo step.
  auto empty = runCommandLine(*d, "update cue 5", 0.0);
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(describeIds({1, 2, 3, 5, 7, 8, 9}), "1-3, 5, 7-9");
}

// The point of palettes: a cue recorded from the programmer with a palette keeps the reference, so
// updating the palette (here from the command line too) reaches it; a cue recorded with the same
// values typed plainly does not follow.
TEST(CommandLine, ACueRecordedWithAPaletteFollowsTheUpdatedPalette) {
  auto d = openShow();
  ASSERT_TRUE(d);
  auto run = [&](const std::string& line) {
    auto r = runCommandLine(*d, line, 0.0);
    EXPECT_TRUE(r.ok()) << line << ": " << (r ? "" : r.error().str());
  };
  run("1 thru 3 palette Centre @ 50");
  run("record cue 7");
  run("clear");
  run("4 pan 10 tilt 20 @ 50");  // Centre's values for the Front group, typed
  run("record cue 8");
  run("clear");
  const CueList* main = d->cueList();
  ASSERT_EQ(main->cues.size(), 5u);
  const Cue& seven = main->cues[2];
  ASSERT_EQ(seven.number, "7");
  for (int id : {1, 2, 3}) {
    EXPECT_EQ(seven.values.at(id).palettes.position, "Centre") << id;
    EXPECT_FALSE(seven.values.at(id).panDeg) << id;
  }
  EXPECT_TRUE(main->cues[3].values.at(4).palettes.empty());
  // On stage at cue 7 before the update.
  ASSERT_TRUE(d->jumpTo(2, 0.0));
  EXPECT_FLOAT_EQ(d->stageState(0.0).at(2).panDeg, 10.0f);

  run("1 thru 4 pan 33");
  run("update palette Centre");
  run("clear");
  EXPECT_EQ(d->history().undoLabel(), "Command \"clear\"");
  const StageState at7 = trackedState(d->show(), d->profiles(), *d->cueList(), 2);
  const StageState at8 = trackedState(d->show(), d->profiles(), *d->cueList(), 3);
  for (int id : {1, 2, 3}) {
    EXPECT_FLOAT_EQ(at7.at(id).panDeg, 33.0f) << id;
    EXPECT_FLOAT_EQ(at7.at(id).tiltDeg, 20.0f) << id;
    EXPECT_FLOAT_EQ(at8.at(id).panDeg, 33.0f) << id;  // tracks into cue 8
  }
  EXPECT_FLOAT_EQ(at8.at(4).panDeg, 10.0f);  // recorded plainly: does not follow
  EXPECT_FLOAT_EQ(at7.at(5).panDeg, 0.0f);   // in no cue
  // The stage follows at once: the cue on stage shows the new palette without a new GO.
  EXPECT_FLOAT_EQ(d->stageState(1.0).at(2).panDeg, 33.0f);

  // The file keeps the reference, so the update reaches the cue after a save and reload too.
  const std::string text = showToText(d->show());
  ShowParse reread = parseShowText(text, kShow);
  ASSERT_TRUE(reread.problems.empty()) << reread.problems.front().str();
  EXPECT_EQ(reread.show.cueLists[0].cues[2].values.at(1).palettes.position, "Centre");
  EXPECT_FLOAT_EQ(*reread.show.findPalette("Centre")->fixtures.at(1).panDeg, 33.0f);

  // Undoing the palette update (past "clear") takes the cue back with it.
  ASSERT_TRUE(d->undo());
  ASSERT_TRUE(d->undo());
  EXPECT_FLOAT_EQ(trackedState(d->show(), d->profiles(), *d->cueList(), 2).at(1).panDeg, 10.0f);
}

TEST(CommandLine, PaletteAndGroupEditsRefuseWhatTheyCannotDo) {
  auto d = openShow();
  ASSERT_TRUE(d);
  const std::string before = showToText(d->show());
  auto refused = [&](const std::string& line, const std::string& says) {
    SCOPED_TRACE(line);
    const size_t steps = d->history().undoSteps();
    auto r = runCommandLine(*d, line, 0.0);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().str(), says);
    EXPECT_EQ(showToText(d->show()), before);
    EXPECT_EQ(d->history().undoSteps(), steps);
  };
  // An empty programmer records no palette.
  refused("record palette Blue",
          "palette Blue: the programmer is empty: nothing to put in the palette; set values first (\"1 thru 4 pan 30\")");
  refused("update palette Centre",
          "palette Centre: the programmer is empty: nothing to put in the palette; set values first (\"1 thru 4 pan 30\")");
  // Nothing selected: no group.
  refused("record group Odd",
          "group Odd: no fixture is selected; a group is recorded from the selection (\"1 thru 6\" first)");
  // A palette the programmer refers to stays.
  ASSERT_TRUE(runCommandLine(*d, "1 palette Narrow", 0.0).ok());
  const std::string withNarrow = showToText(d->show());
  auto r = runCommandLine(*d, "delete palette Narrow", 0.0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().str(), "palette Narrow: the programmer refers to the palette (fixture 1); clear it first (nothing was deleted)");
  EXPECT_EQ(showToText(d->show()), withNarrow);
  // A colour palette cannot take intensity alone.
  ASSERT_TRUE(runCommandLine(*d, "clear", 0.0).ok());
  ASSERT_TRUE(runCommandLine(*d, "2 @ 40", 0.0).ok());
  r = runCommandLine(*d, "record colour palette Dim", 0.0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().str(), "palette Dim: the programmer holds no color values (colour, cell colours); nothing was changed");
  // Without a kind, intensity alone makes an "all" palette; with a position it is left out, and said so.
  ASSERT_TRUE(runCommandLine(*d, "record palette Dim", 0.0).ok());
  EXPECT_EQ(d->show().findPalette("Dim")->kind, PaletteKind::All);
  ASSERT_TRUE(runCommandLine(*d, "clear", 0.0).ok());
  auto said = runCommandLine(*d, "3 @ 40 pan 5", 0.0);
  ASSERT_TRUE(said.ok());
  said = runCommandLine(*d, "record palette \"Low left\"", 0.0);
  ASSERT_TRUE(said.ok()) << said.error().str();
  EXPECT_EQ(*said, "Recorded position palette \"Low left\" (intensity left out: a position palette holds pan, tilt)");
  // The new palettes are names the rest of the line knows, in any case.
  ASSERT_TRUE(runCommandLine(*d, "clear", 0.0).ok());
  ASSERT_TRUE(runCommandLine(*d, "3 palette \"low left\"", 0.0).ok());
  EXPECT_FLOAT_EQ(*programmed(*d, 3, &CueValues::panDeg), 5.0f);
  EXPECT_EQ(refsOf(*d, 3).position, "Low left");
}
}  // namespace
}  // namespace haze
