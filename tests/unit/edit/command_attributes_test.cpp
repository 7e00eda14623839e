// The command line's attributes and times (docs/gui-commands.md, "Attributes and times on the
// command line"): colour by code, palette, name and wheel slot; CTO; gobo and prism by name or
// slot with rotation and spin; shutter and strobe; frost and focus; cue times, labels and the
// show's default fade. Every line of the doc's example table runs here and must do what this file
// checks (and every check needs its line in the doc); the errors are the doc's; and a cue recorded
// from the command line with a colour, a gobo and a 5 s fade is half-way at 2.5 s.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>

#include <glm/glm.hpp>

#include "shows/edit/command_run.h"
#include "shows/edit/command_syntax.h"
#include "shows/palettes.h"
#include "shows/playback.h"
#include "shows/show_json.h"

namespace haze {
namespace {

namespace fs = std::filesystem;

// The console test show (twelve test spots with gobos Open, Dots, Star; palettes Centre, Warm,
// Narrow) and one more fixture, 20, whose inline profile has a colour wheel and two prisms.
fs::path writeShow() {
  const fs::path dir = fs::temp_directory_path() / ("haze-command-attributes-" + std::to_string(::getpid()));
  fs::create_directories(dir / "profiles");
  const fs::path src = fs::path(HAZE_SOURCE_DIR) / "tests/data/shows";
  fs::copy_file(src / "profiles/test-spot.json", dir / "profiles/test-spot.json", fs::copy_options::overwrite_existing);
  nlohmann::json show = nlohmann::json::parse(std::ifstream(src / "console.haze.json"));
  show["profiles"]["wheels"] = nlohmann::json::parse(R"({
    "format": "haze-fixture", "version": 1, "name": "Wheel Spot",
    "photometry": { "beam_angle": 15, "field_angle": 25, "peak_candela": 20000 },
    "color_wheels": [ { "name": "Colour 1", "slots": [ { "name": "Open" }, { "name": "Red", "color": [1, 0, 0] },
                                                       { "name": "Deep Blue", "color": [0, 0.1, 1] } ] } ],
    "gobo_wheels": [ { "name": "Gobo 1", "slots": [ { "name": "Open" }, { "name": "Breakup" } ] } ],
    "prisms": [ { "name": "3-facet", "facets": 3, "deflection": 10 }, { "name": "5-linear", "facets": 5, "deflection": 4, "linear": true } ]
  })");
  show["fixtures"].push_back({{"id", 20}, {"name", "Wheel 20"}, {"profile", "wheels"}, {"position", {0, 6, 0}}});
  std::ofstream(dir / "attributes.haze.json") << show.dump(2);
  return dir / "attributes.haze.json";
}

std::unique_ptr<ShowDocument> openShow() {
  static const fs::path file = writeShow();
  auto d = ShowDocument::open(file);
  EXPECT_TRUE(d.ok()) << (d ? "" : d.error().str());
  return d ? std::move(*d) : nullptr;
}

// The fixture's programmer values with its palettes resolved.
CueValues programmed(const ShowDocument& d, int id) {
  auto it = d.programmer().values.find(id);
  return it == d.programmer().values.end() ? CueValues{} : resolveValues(d.show(), id, it->second);
}

void expectColor(const std::optional<glm::vec3>& got, glm::vec3 want) {
  ASSERT_TRUE(got.has_value());
  EXPECT_NEAR(got->r, want.r, 1e-4f);
  EXPECT_NEAR(got->g, want.g, 1e-4f);
  EXPECT_NEAR(got->b, want.b, 1e-4f);
}

// The rows "| `typed` | what |" of the table under `### title` in docs/gui-commands.md.
std::vector<std::pair<std::string, std::string>> docRows(const std::string& title) {
  std::ifstream in(fs::path(HAZE_SOURCE_DIR) / "docs/gui-commands.md");
  std::vector<std::pair<std::string, std::string>> rows;
  bool inTable = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("#", 0) == 0) inTable = line == "### " + title;
    if (!inTable || line.rfind("| `", 0) != 0) continue;
    const size_t split = line.find("` | ");
    if (split == std::string::npos) continue;
    rows.push_back({line.substr(3, split - 3), line.substr(split + 4)});
  }
  return rows;
}

struct Example {
  std::string setup;  // lines run first, separated by "; "
  std::function<void(ShowDocument&)> check;
};

// sRGB #ff8800 in linear RGB: 0x88 = 136 -> ((136/255 + 0.055) / 1.055)^2.4.
constexpr float kLinear88 = 0.2462014f;

std::map<std::string, Example> examples() {
  std::map<std::string, Example> e;
  e["1 color #ff8800"] = {"", [](ShowDocument& d) { expectColor(programmed(d, 1).color, {1.0f, kLinear88, 0.0f}); }};
  e["1 thru 3 colour Warm"] = {"", [](ShowDocument& d) {
                                 for (int id : {1, 2, 3}) {
                                   EXPECT_EQ(d.programmer().values.at(id).palettes.color, "Warm");
                                   expectColor(programmed(d, id).color, {1.0f, 0.8f, 0.6f});
                                 }
                               }};
  e["1 color red"] = {"", [](ShowDocument& d) { expectColor(programmed(d, 1).color, {1.0f, 0.0f, 0.0f}); }};
  e["20 color \"Deep Blue\""] = {"", [](ShowDocument& d) { expectColor(programmed(d, 20).color, {0.0f, 0.1f, 1.0f}); }};
  e["20 color 2"] = {"", [](ShowDocument& d) { expectColor(programmed(d, 20).color, {1.0f, 0.0f, 0.0f}); }};
  e["1 cto 159"] = {"", [](ShowDocument& d) { EXPECT_FLOAT_EQ(*programmed(d, 1).ctoMired, 159.0f); }};
  e["1 thru 3 gobo star"] = {"", [](ShowDocument& d) {
                               for (int id : {1, 2, 3}) EXPECT_EQ(programmed(d, id).gobo, "Star");
                             }};
  e["1 gobo 2"] = {"", [](ShowDocument& d) { EXPECT_EQ(programmed(d, 1).gobo, "Dots"); }};
  e["1 gobo open"] = {"1 gobo Star", [](ShowDocument& d) { EXPECT_EQ(programmed(d, 1).gobo, "Open"); }};
  e["1 gobo rotation -45 gobo spin 30"] = {"", [](ShowDocument& d) {
                                             EXPECT_FLOAT_EQ(*programmed(d, 1).goboRotationDeg, -45.0f);
                                             EXPECT_FLOAT_EQ(*programmed(d, 1).goboSpinDegS, 30.0f);
                                           }};
  e["1 shutter closed"] = {"", [](ShowDocument& d) {
                             EXPECT_EQ(programmed(d, 1).shutter, Shutter{.mode = ShutterMode::Closed});
                           }};
  e["1 strobe 8"] = {"", [](ShowDocument& d) {
                       EXPECT_EQ(programmed(d, 1).shutter,
                                 (Shutter{.mode = ShutterMode::Strobe, .rateHz = 8.0f, .duty = 0.5f}));
                     }};
  e["1 strobe off"] = {"1 strobe 8", [](ShowDocument& d) { EXPECT_EQ(programmed(d, 1).shutter, Shutter{}); }};
  e["20 prism 3-facet prism rotation 30"] = {"", [](ShowDocument& d) {
                                               EXPECT_EQ(programmed(d, 20).prism, "3-facet");
                                               EXPECT_FLOAT_EQ(*programmed(d, 20).prismRotationDeg, 30.0f);
                                             }};
  e["20 prism 2 prism spin -20"] = {"", [](ShowDocument& d) {
                                      EXPECT_EQ(programmed(d, 20).prism, "5-linear");
                                      EXPECT_FLOAT_EQ(*programmed(d, 20).prismSpinDegS, -20.0f);
                                    }};
  e["1 frost 40 focus 70"] = {"", [](ShowDocument& d) {
                                EXPECT_FLOAT_EQ(*programmed(d, 1).frost, 0.4f);
                                EXPECT_FLOAT_EQ(*programmed(d, 1).gateFocus, 0.7f);
                              }};
  e["cue 5 time 5 delay 1"] = {"", [](ShowDocument& d) {
                                 const Cue& c = d.cueList()->cues[1];
                                 EXPECT_DOUBLE_EQ(c.fadeS, 5.0);
                                 EXPECT_DOUBLE_EQ(c.delayS, 1.0);
                                 EXPECT_FALSE(c.followS);
                               }};
  e["cue 5 follow 2"] = {"cue 5 time 3", [](ShowDocument& d) {
                           const Cue& c = d.cueList()->cues[1];
                           EXPECT_DOUBLE_EQ(c.fadeS, 3.0);  // kept
                           ASSERT_TRUE(c.followS);
                           EXPECT_DOUBLE_EQ(*c.followS, 2.0);
                         }};
  e["cue 2/1 time 4"] = {"", [](ShowDocument& d) { EXPECT_DOUBLE_EQ(d.show().cueLists[1].cues[0].fadeS, 4.0); }};
  e["label cue 5 \"Verse\""] = {"", [](ShowDocument& d) { EXPECT_EQ(d.cueList()->cues[1].label, "Verse"); }};
  e["label cue 10 Last song"] = {"", [](ShowDocument& d) { EXPECT_EQ(d.cueList()->cues[2].label, "Last song"); }};
  e["default fade 5"] = {"", [](ShowDocument& d) { EXPECT_DOUBLE_EQ(d.show().defaultFadeS, 5.0); }};
  e["record cue 20"] = {"default fade 3; 1 @ full", [](ShowDocument& d) {
                          const Cue& c = d.cueList()->cues.back();
                          EXPECT_EQ(c.number, "20");
                          EXPECT_DOUBLE_EQ(c.fadeS, 3.0);
                        }};
  return e;
}

TEST(CommandAttributes, EveryDocExampleDoesWhatItSaysAndIsOneUndoStep) {
  const auto rows = docRows("Examples of attributes and times");
  const auto checks = examples();
  std::set<std::string> inDoc;
  for (const auto& [typed, what] : rows) inDoc.insert(typed);
  for (const auto& [line, ex] : checks) EXPECT_TRUE(inDoc.count(line)) << "not in docs/gui-commands.md: " << line;
  EXPECT_EQ(rows.size(), checks.size());
  for (const auto& [typed, what] : rows) {
    SCOPED_TRACE(typed);
    auto it = checks.find(typed);
    ASSERT_NE(it, checks.end()) << "docs/gui-commands.md example without a check here";
    auto d = openShow();
    ASSERT_TRUE(d);
    std::stringstream setup(it->second.setup);
    for (std::string part; std::getline(setup, part, ';');) {
      auto ran = runCommandLine(*d, part, 0.0);
      ASSERT_TRUE(ran.ok()) << part << ": " << ran.error().str();
    }
    const std::string showBefore = showToText(d->show());
    const Programmer before = d->programmer();
    const size_t steps = d->history().undoSteps();
    auto said = runCommandLine(*d, typed, 1.0);
    ASSERT_TRUE(said.ok()) << said.error().str();
    EXPECT_FALSE(said->empty());
    it->second.check(*d);
    EXPECT_EQ(d->history().undoSteps(), steps + 1);
    ASSERT_TRUE(d->undo());
    EXPECT_EQ(showToText(d->show()), showBefore);
    EXPECT_EQ(d->programmer(), before);
    ASSERT_TRUE(d->redo());
    it->second.check(*d);
  }
}

TEST(CommandAttributes, EveryDocErrorSaysWhatWasExpectedAndChangesNothing) {
  const auto rows = docRows("Errors of attributes and times");
  ASSERT_GE(rows.size(), 8u);
  const std::regex code("`([^`]*)`");
  for (const auto& [typed, said] : rows) {
    SCOPED_TRACE(typed);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(said, m, code));
    auto d = openShow();
    ASSERT_TRUE(d);
    ASSERT_TRUE(runCommandLine(*d, "5 @ 20", 0.0).ok());
    const std::string showBefore = showToText(d->show());
    const Programmer before = d->programmer();
    const size_t steps = d->history().undoSteps();
    auto ran = runCommandLine(*d, typed, 1.0);
    ASSERT_FALSE(ran.ok());
    EXPECT_EQ(ran.error().str(), m[1].str());
    EXPECT_EQ(showToText(d->show()), showBefore);
    EXPECT_EQ(d->programmer(), before);
    EXPECT_EQ(d->history().undoSteps(), steps);
  }
}

TEST(CommandAttributes, ParsesEachAttributeWithoutRunning) {
  auto d = openShow();
  ASSERT_TRUE(d);
  const Show& s = d->show();
  auto parsed = parseCommand("3 color #00FF00 cto -131 gobo Dots gobo rotation 10 prism open shutter open frost 5 focus 0",
                             s);
  ASSERT_TRUE(parsed.ok()) << parsed.error().str();
  EXPECT_EQ(parsed->action, ParsedCommand::Action::Set);
  expectColor(parsed->values.color, {0.0f, 1.0f, 0.0f});
  EXPECT_FLOAT_EQ(*parsed->values.ctoMired, -131.0f);
  EXPECT_EQ(parsed->goboSlot, "Dots");
  EXPECT_FLOAT_EQ(*parsed->values.goboRotationDeg, 10.0f);
  EXPECT_EQ(parsed->prismSlot, "open");
  EXPECT_EQ(parsed->values.shutter, Shutter{});
  EXPECT_FLOAT_EQ(*parsed->values.frost, 0.05f);
  EXPECT_FLOAT_EQ(*parsed->values.gateFocus, 0.0f);
  auto times = parseCommand("cue 10 delay 2 follow off", s);
  ASSERT_TRUE(times.ok());
  EXPECT_EQ(times->action, ParsedCommand::Action::CueTimes);
  EXPECT_FALSE(times->fadeS);
  EXPECT_DOUBLE_EQ(*times->delayS, 2.0);
  ASSERT_TRUE(times->followS);
  EXPECT_FALSE(*times->followS);
  // A plain `cue N` is still a GOTO.
  EXPECT_EQ(parseCommand("cue 10", s)->action, ParsedCommand::Action::GotoCue);
  // Completion offers the new words where they fit.
  EXPECT_EQ(completeCommand("1 gobo ", s).words, (std::vector<std::string>{"rotation", "spin", "open"}));
  EXPECT_EQ(completeCommand("1 shutter ", s).words, (std::vector<std::string>{"open", "closed"}));
  EXPECT_EQ(completeCommand("cue 5 ", s).words, (std::vector<std::string>{"time", "delay", "follow"}));
  const auto colours = completeCommand("1 color W", s).words;
  EXPECT_EQ(colours, (std::vector<std::string>{"Warm", "white"}));
}

// Recorded from the command line with a colour, a gobo and the show's 5 s default fade, the cue
// plays back half-way at 2.5 s: the intensity and the colour between the cue before and the new
// one, the gobo already in (a wheel switches at the start of the fade, docs/show-format.md).
TEST(CommandAttributes, ACueRecordedWithColourGoboAndFiveSecondFadeIsHalfWayAtTwoAndAHalf) {
  auto d = openShow();
  ASSERT_TRUE(d);
  for (const char* line : {"default fade 5", "1 @ full color red gobo Star", "record cue 20"})
    ASSERT_TRUE(runCommandLine(*d, line, 0.0).ok()) << line;
  const CueList& list = *d->cueList();
  const size_t at = list.cues.size() - 1;
  ASSERT_EQ(list.cues[at].number, "20");
  EXPECT_DOUBLE_EQ(list.cues[at].fadeS, 5.0);
  const StageState before = trackedState(d->show(), d->profiles(), list, at - 1);
  EXPECT_FLOAT_EQ(before.at(1).intensity, 0.0f);  // cue 10 took it out
  EXPECT_EQ(before.at(1).color, glm::vec3(1.0f));
  const StageState half = stateAt(d->show(), d->profiles(), list, at, 2.5);
  EXPECT_NEAR(half.at(1).intensity, 0.5f, 1e-5f);
  EXPECT_NEAR(half.at(1).color.r, 1.0f, 1e-5f);
  EXPECT_NEAR(half.at(1).color.g, 0.5f, 1e-5f);
  EXPECT_NEAR(half.at(1).color.b, 0.5f, 1e-5f);
  EXPECT_EQ(half.at(1).gobo, "Star");
  const StageState done = stateAt(d->show(), d->profiles(), list, at, 5.0);
  EXPECT_FLOAT_EQ(done.at(1).intensity, 1.0f);
  EXPECT_EQ(done.at(1).color, glm::vec3(1.0f, 0.0f, 0.0f));
  // The same with the time set on the cue afterwards, and the default fade saved with the show.
  ASSERT_TRUE(runCommandLine(*d, "cue 20 time 4", 0.0).ok());
  EXPECT_NEAR(stateAt(d->show(), d->profiles(), *d->cueList(), at, 2.0).at(1).intensity, 0.5f, 1e-5f);
  const std::string text = showToText(d->show());
  EXPECT_NE(text.find("\"default_fade\": 5"), std::string::npos);
}

}  // namespace
}  // namespace haze
