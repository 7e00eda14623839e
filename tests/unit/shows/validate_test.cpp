// Validation: each kind of broken show, made by one edit of the valid test show, must be
// reported at the JSON pointer of the edited value with a sentence saying what is wrong; and a
// show with many problems gets them all at once.
#include <fstream>
#include <functional>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "show_test_data.h"
#include "shows/show_validate.h"

namespace haze {
namespace {

using json = nlohmann::json;
using ptr = json::json_pointer;

json validJson() {
  std::ifstream in(test::validShowPath());
  return json::parse(in);
}

// Validated as if it sat beside the valid show, so its relative paths resolve the same way.
std::vector<Error> validate(const std::string& text) {
  return validateShowText(text, test::showsDir() / "edited.haze.json");
}

std::string listed(const std::vector<Error>& problems) {
  std::string s;
  for (const Error& e : problems) s += "  " + e.str() + "\n";
  return s.empty() ? "  (no problems)\n" : s;
}

struct Broken {
  const char* kind;
  std::function<void(json&)> edit;
  const char* pointer;  // where the problem must be reported
  const char* words;    // part of the sentence
};

void set(json& j, const char* p, json v) { j[ptr(p)] = std::move(v); }
void erase(json& j, const char* p) {
  ptr at(p);
  j[at.parent_pointer()].erase(at.back());
}

const std::vector<Broken>& brokenShows() {
  static const std::vector<Broken> all = {
      {"unknown profile", [](json& j) { set(j, "/fixtures/0/profile", "wash"); }, "/fixtures/0/profile",
       "unknown profile \"wash\""},
      {"duplicate fixture id", [](json& j) { set(j, "/fixtures/1/id", 101); }, "/fixtures/1/id",
       "fixture id 101 is already used by /fixtures/0"},
      {"overlapping DMX footprints", [](json& j) { set(j, "/fixtures/1/patch/address", 5); },
       "/fixtures/1/patch/address", "channels 5-14 of universe 1 overlap fixture 101"},
      {"overlap with a later address", [](json& j) { set(j, "/fixtures/0/patch/address", 15); },
       "/fixtures/1/patch/address", "overlap fixture 101"},
      {"footprint past channel 512", [](json& j) { set(j, "/fixtures/1/patch/address", 505); },
       "/fixtures/1/patch/address", "would run to channel 514, past 512"},
      {"address past 512", [](json& j) { set(j, "/fixtures/1/patch/address", 600); }, "/fixtures/1/patch/address",
       "from 1 to 512, got 600"},
      {"universe 0", [](json& j) { set(j, "/fixtures/0/patch/universe", 0); }, "/fixtures/0/patch/universe",
       "universe"},
      {"unknown DMX mode", [](json& j) { set(j, "/fixtures/0/mode", "Extended"); }, "/fixtures/0/mode",
       "no DMX mode \"Extended\""},
      {"pan outside the profile", [](json& j) { set(j, "/cue_lists/0/cues/0/values/101/pan", 300); },
       "/cue_lists/0/cues/0/values/101/pan", "pan 300 is outside the range of profile \"spot\"; expected -270 to 270"},
      {"tilt outside the profile", [](json& j) { set(j, "/cue_lists/0/cues/0/values/101/tilt", -200); },
       "/cue_lists/0/cues/0/values/101/tilt", "tilt -200 is outside"},
      {"zoom outside the profile", [](json& j) { set(j, "/cue_lists/0/cues/1/values/101/zoom", 45); },
       "/cue_lists/0/cues/1/values/101/zoom", "expected 8 to 40"},
      {"unknown gobo slot", [](json& j) { set(j, "/cue_lists/0/cues/0/values/101/gobo", "Moon"); },
       "/cue_lists/0/cues/0/values/101/gobo", "no gobo slot \"Moon\""},
      // The test spot has one gobo wheel and no prism.
      {"a second gobo wheel the profile lacks", [](json& j) { set(j, "/cue_lists/0/cues/0/values/101/gobo2", "Dots"); },
       "/cue_lists/0/cues/0/values/101/gobo2", "no gobo slot \"Dots\" on its second gobo wheel"},
      {"a second wheel's spin the profile lacks", [](json& j) { set(j, "/cue_lists/0/cues/0/values/101/gobo2_spin", 10); },
       "/cue_lists/0/cues/0/values/101/gobo2_spin", "has no second gobo wheel"},
      {"a prism spin without a prism", [](json& j) { set(j, "/cue_lists/0/cues/0/values/101/prism_spin", 10); },
       "/cue_lists/0/cues/0/values/101/prism_spin", "has no prism"},
      {"duplicate cue number", [](json& j) { set(j, "/cue_lists/0/cues/1/number", "1.0"); },
       "/cue_lists/0/cues/1/number", "repeats cue \"1\""},
      {"decreasing cue number", [](json& j) { set(j, "/cue_lists/0/cues/2/number", "1.5"); },
       "/cue_lists/0/cues/2/number", "comes after cue \"2\""},
      {"cue number that is not a number", [](json& j) { set(j, "/cue_lists/0/cues/0/number", "A"); },
       "/cue_lists/0/cues/0/number", "expected a cue number"},
      {"cue number written as a JSON number", [](json& j) { set(j, "/cue_lists/0/cues/0/number", 1); },
       "/cue_lists/0/cues/0/number", "(a string), got a number"},
      {"timecode beyond 24 h", [](json& j) { set(j, "/cue_lists/0/cues/0/timecode", "24:00:00:00"); },
       "/cue_lists/0/cues/0/timecode", "within a day"},
      {"timecode not hh:mm:ss:ff", [](json& j) { set(j, "/cue_lists/0/cues/0/timecode", "1:00"); },
       "/cue_lists/0/cues/0/timecode", "expected a timecode \"hh:mm:ss:ff\""},
      {"timecodes out of order", [](json& j) {
         set(j, "/cue_lists/0/cues/0/timecode", "00:01:00:00");
         set(j, "/cue_lists/0/cues/1/timecode", "00:00:30:00");
       }, "/cue_lists/0/cues/1/timecode", "expected timecodes that increase down the list"},
      {"negative fade", [](json& j) { set(j, "/cue_lists/0/cues/1/fade", -1); }, "/cue_lists/0/cues/1/fade",
       "not negative, got -1"},
      {"negative delay", [](json& j) { set(j, "/cue_lists/0/cues/1/delay", -0.5); }, "/cue_lists/0/cues/1/delay",
       "not negative"},
      {"negative follow", [](json& j) { set(j, "/cue_lists/0/cues/3/follow", -2); }, "/cue_lists/0/cues/3/follow",
       "not negative"},
      {"follow of the wrong type", [](json& j) { set(j, "/cue_lists/0/cues/3/follow", "soon"); },
       "/cue_lists/0/cues/3/follow", "or null, got a string"},
      {"missing profile file", [](json& j) { set(j, "/profiles/spot", "profiles/nope.json"); }, "/profiles/spot",
       "\"profiles/nope.json\" not found"},
      {"broken inline profile", [](json& j) { set(j, "/profiles/par/inline/format", "haze-show"); }, "/profiles/par",
       "cannot be loaded"},
      {"missing venue file", [](json& j) { set(j, "/venue/gltf", "venue/none.gltf"); }, "/venue/gltf",
       "\"venue/none.gltf\" not found"},
      {"fixture id of the wrong type", [](json& j) { set(j, "/fixtures/0/id", "101"); }, "/fixtures/0/id",
       "a whole number), got a string"},
      {"fixture id zero", [](json& j) { set(j, "/fixtures/2/id", 0); }, "/fixtures/2/id", "got 0"},
      {"fixture without a profile", [](json& j) { erase(j, "/fixtures/0/profile"); }, "/fixtures/0/profile",
       "missing required key \"profile\""},
      {"intensity of the wrong type", [](json& j) { set(j, "/cue_lists/0/cues/0/values/101/intensity", "full"); },
       "/cue_lists/0/cues/0/values/101/intensity", "(a number), got a string"},
      {"intensity above 1", [](json& j) { set(j, "/cue_lists/0/cues/0/values/102/intensity", 1.5); },
       "/cue_lists/0/cues/0/values/102/intensity", "from 0 to 1, got 1.5"},
      {"colour with two components", [](json& j) { set(j, "/cue_lists/0/cues/0/values/201/color", {1, 0}); },
       "/cue_lists/0/cues/0/values/201/color", "array of 3 numbers, got an array of 2"},
      {"colour component above 1", [](json& j) { set(j, "/cue_lists/0/cues/0/values/201/color/1", 2); },
       "/cue_lists/0/cues/0/values/201/color/1", "from 0 to 1"},
      {"misspelt attribute", [](json& j) { set(j, "/cue_lists/0/cues/0/values/102/intensty", 1); },
       "/cue_lists/0/cues/0/values/102/intensty", "unknown key \"intensty\""},
      {"values for a fixture that is not there", [](json& j) { set(j, "/cue_lists/0/cues/0/values/999/intensity", 1); },
       "/cue_lists/0/cues/0/values/999", "no fixture with id 999"},
      {"values keyed by a name", [](json& j) { set(j, "/cue_lists/0/cues/0/values/Spot 1/intensity", 1); },
       "/cue_lists/0/cues/0/values/Spot 1", "expected a fixture id"},
      {"newer format version", [](json& j) { set(j, "/version", 3); }, "/version",
       "format version 3, newer than this haze reads"},
      {"version zero", [](json& j) { set(j, "/version", 0); }, "/version", "format version"},
      {"a fixture profile instead of a show", [](json& j) { set(j, "/format", "haze-fixture"); }, "/format",
       "this is a fixture profile"},
      {"unknown phase function", [](json& j) { set(j, "/atmosphere/phase", "foggy"); }, "/atmosphere/phase",
       "expected hazy, isotropic or hg"},
      {"negative scattering", [](json& j) { set(j, "/atmosphere/scattering", -0.1); }, "/atmosphere/scattering",
       "not negative"},
      {"camera field of view 0", [](json& j) { set(j, "/cameras/0/fov_y", 0); }, "/cameras/0/fov_y", "from 1 to 179"},
      {"camera looking at itself", [](json& j) { set(j, "/cameras/0/target", {0, 4, 18}); }, "/cameras/0/target",
       "its own position"},
      {"duplicate cue list name", [](json& j) { set(j, "/cue_lists/1/name", "Main"); }, "/cue_lists/1/name",
       "already used by /cue_lists/0"},
      {"fixtures not an array", [](json& j) { set(j, "/fixtures", json::object()); }, "/fixtures",
       "(an array), got an object"},
  };
  return all;
}

TEST(Validate, TheValidShowHasNoProblems) {
  auto problems = validateShowFile(test::validShowPath());
  EXPECT_TRUE(problems.empty()) << listed(problems);
}

TEST(Validate, EachKindOfBrokenShowIsReportedAtItsPointer) {
  ASSERT_GE(brokenShows().size(), 20u);
  for (const Broken& b : brokenShows()) {
    json j = validJson();
    b.edit(j);
    auto problems = validate(j.dump(2));
    bool found = false;
    for (const Error& e : problems)
      found = found || (e.place == b.pointer && e.message.find(b.words) != std::string::npos);
    EXPECT_TRUE(found) << b.kind << ": expected a problem at " << b.pointer << " saying \"" << b.words
                       << "\"; got:\n"
                       << listed(problems);
    for (const Error& e : problems) EXPECT_NE(e.file.find("edited.haze.json"), std::string::npos) << e.str();
  }
}

TEST(Validate, ReportsEveryProblemAtOnce) {
  json j = validJson();
  set(j, "/fixtures/2/patch/address", 600);
  set(j, "/cue_lists/0/cues/1/fade", -1);
  set(j, "/cue_lists/0/cues/0/values/101/gobo", "Moon");
  set(j, "/cue_lists/0/cues/4/number", "3");
  set(j, "/atmosphere/phase", "foggy");
  auto problems = validate(j.dump());
  std::vector<std::string> places;
  for (const Error& e : problems) places.push_back(e.place);
  for (const char* p : {"/fixtures/2/patch/address", "/cue_lists/0/cues/1/fade", "/cue_lists/0/cues/0/values/101/gobo",
                        "/cue_lists/0/cues/4/number", "/atmosphere/phase"})
    EXPECT_NE(std::find(places.begin(), places.end(), p), places.end()) << p << "\n" << listed(problems);
  EXPECT_EQ(problems.size(), 5u) << listed(problems);
}

TEST(Validate, BrokenJsonNamesTheLineAndColumn) {
  auto problems = validate("{\n  \"format\": \"haze-show\",\n  \"version\": 1,,\n}\n");
  ASSERT_EQ(problems.size(), 1u) << listed(problems);
  EXPECT_EQ(problems[0].place, "line 3, column 16");
  EXPECT_NE(problems[0].message.find("not valid JSON"), std::string::npos) << problems[0].message;
}

TEST(Validate, HostileInputIsRefusedNotCrashedOn) {
  std::string deep(100000, '[');
  auto problems = validate(deep);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("deeper than"), std::string::npos) << problems[0].message;
  for (const char* text : {"", "null", "[]", "\"haze-show\"", "{\"format\": \"haze-show\", \"version\": 1e400}",
                           "{\"format\": \"haze-show\", \"version\": 18446744073709551615}"}) {
    auto p = validate(text);
    EXPECT_FALSE(p.empty()) << text;
  }
  json j = validJson();
  set(j, "/fixtures/0/position/0", 1e300);
  EXPECT_FALSE(validate(j.dump()).empty());
}

TEST(Validate, MissingFileIsOneClearProblem) {
  auto problems = validateShowFile(test::showsDir() / "no-such-show.haze.json");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace haze
