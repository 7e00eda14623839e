// Change fixture type: values mapped attribute by attribute, overlaps refused with the list, one
// undo step that gives the show back byte for byte, and the console's `type` line. The QLC+ cases
// need Debian's qlcplus-data (tools/install-deps.sh installs it).
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "shows/edit/command_run.h"
#include "shows/edit/command_syntax.h"
#include "shows/edit/edit_change_type.h"
#include "shows/edit/show_document.h"
#include "shows/show_json.h"

namespace haze {
namespace {

namespace fs = std::filesystem;

const fs::path kDemo = fs::path(HAZE_SOURCE_DIR) / "examples/demo/demo.haze.json";
const fs::path kSpot160 = "/usr/share/qlcplus/fixtures/Robe/Robe-Spot-160-XT.qxf";    // 8-channel, 16-Bit: 8 slots
const fs::path kRobin600 = "/usr/share/qlcplus/fixtures/Robe/Robe-Robin-600E-Spot.qxf";  // Mode 1: 32 slots
const std::vector<int> kTen = {101, 102, 103, 104, 201, 202, 203, 204, 301, 302};

#define REQUIRE_QLC()                                                                                          \
  if (!fs::exists(kSpot160) || !fs::exists(kRobin600)) GTEST_SKIP() << "qlcplus-data is not installed (" << kSpot160 \
                                                                    << "; tools/install-deps.sh installs it)"

std::unique_ptr<ShowDocument> openDemo() {
  auto d = ShowDocument::open(kDemo);
  EXPECT_TRUE(d.ok()) << (d.ok() ? "" : d.error().str());
  return d.ok() ? std::move(*d) : nullptr;
}

Profile wheelProfile() {
  Profile p;
  p.name = "Test spot";
  p.panDeg = {-200.0f, 200.0f};
  p.tiltDeg = {-100.0f, 100.0f};
  p.zoomDeg = {10.0f, 20.0f};
  p.colorWheels.push_back(Wheel{"Colours", {WheelSlot{"Red", glm::vec3(1, 0, 0), "", nullptr},
                                            WheelSlot{"Blue", glm::vec3(0, 0, 1), "", nullptr}}});
  p.goboWheels.push_back(Wheel{"Gobos", {WheelSlot{"Open", std::nullopt, "", nullptr}, WheelSlot{"Gobo 5", std::nullopt, "g5.png", nullptr}}});
  return p;
}

TEST(ChangeType, ValuesAreMappedAttributeByAttribute) {
  const Profile to = wheelProfile();
  CueValues v;
  v.intensity = 0.7f;
  v.panDeg = 250.0f;    // beyond 200
  v.tiltDeg = -50.0f;   // inside
  v.zoomDeg = 30.0f;    // beyond 20
  v.color = glm::vec3(0.9f, 0.1f, 0.2f);  // nearest: Red
  v.gobo = "gobo5";     // the same letters and digits as "Gobo 5"
  v.gobo2 = "Leaves";   // no second wheel
  v.frost = 0.5f;       // no frost
  v.prism = "3-facet";  // no prism
  std::vector<std::string> notes;
  const CueValues m = mapValuesToProfile(v, to, "cue 1 fixture 7", notes);
  EXPECT_EQ(m.intensity, 0.7f);
  EXPECT_EQ(m.panDeg, 200.0f);
  EXPECT_EQ(m.tiltDeg, -50.0f);
  EXPECT_EQ(m.zoomDeg, 20.0f);
  EXPECT_EQ(m.color, glm::vec3(1, 0, 0));
  EXPECT_EQ(m.gobo, "Gobo 5");
  EXPECT_EQ(m.gobo2.value_or("Open"), "Open");  // out of the beam, or unset: the type has one wheel
  EXPECT_FALSE(m.frost.has_value());
  EXPECT_EQ(m.prism, "Open");
  // pan, zoom, colour, gobo2, prism, frost: one line each, each naming where.
  ASSERT_EQ(notes.size(), 6u);
  for (const std::string& n : notes) EXPECT_EQ(n.rfind("cue 1 fixture 7: ", 0), 0u) << n;
  // A mixing fixture keeps the colour as it is.
  Profile rgb = to;
  rgb.colorMixing = ColorMixing::Rgb;
  notes.clear();
  EXPECT_EQ(mapValuesToProfile(v, rgb, "x", notes).color, v.color);
}

TEST(ChangeType, TenDemoFixturesBecomeAQlcSpotAndUndoGivesTheShowBack) {
  REQUIRE_QLC();
  auto d = openDemo();
  ASSERT_TRUE(d);
  const std::string before = showToText(d->show());
  const Show original = d->show();
  auto report = d->changeFixtureType(kTen, kSpot160, "8-channel, 16-Bit");
  ASSERT_TRUE(report.ok()) << report.error().str();
  EXPECT_GT(report->valuesMapped, 0);
  EXPECT_FALSE(report->lines.empty());  // the demo's gobos "Leaves" and "Dots" are not on this wheel
  bool goboSaid = false;
  for (const std::string& l : report->lines) goboSaid = goboSaid || l.find("gobo \"Leaves\"") != std::string::npos;
  EXPECT_TRUE(goboSaid);
  EXPECT_EQ(d->history().undoSteps(), 1u);
  const Profile& spot = *d->profiles().at(d->show().findFixture(101)->profile);
  for (int id : kTen) {
    const FixtureDef* now = d->show().findFixture(id);
    const FixtureDef* was = original.findFixture(id);
    ASSERT_NE(now, nullptr);
    EXPECT_EQ(now->name, was->name);
    EXPECT_EQ(now->position, was->position);
    EXPECT_EQ(now->rotationDeg, was->rotationDeg);
    EXPECT_EQ(now->patch->address, was->patch->address);
    EXPECT_EQ(now->mode, "8-channel, 16-Bit");
    EXPECT_EQ(d->profiles().at(now->profile)->name, "Spot 160 XT");
  }
  // Fixtures not named keep their type.
  EXPECT_EQ(d->show().findFixture(303)->profile, original.findFixture(303)->profile);
  // Pan and tilt: equal where the new range holds them; colours: a slot of the new wheel, the nearest.
  for (size_t c = 0; c < original.cueLists[0].cues.size(); ++c)
    for (const auto& [id, was] : original.cueLists[0].cues[c].values) {
      if (std::find(kTen.begin(), kTen.end(), id) == kTen.end()) continue;
      const CueValues& now = d->show().cueLists[0].cues[c].values.at(id);
      if (was.panDeg) {
        EXPECT_EQ(*now.panDeg, std::clamp(*was.panDeg, spot.panDeg.min, spot.panDeg.max));
      }
      if (was.tiltDeg) {
        EXPECT_EQ(*now.tiltDeg, std::clamp(*was.tiltDeg, spot.tiltDeg.min, spot.tiltDeg.max));
      }
      if (!was.color) continue;
      float best = 1e9f;
      for (const WheelSlot& s : spot.colorWheels.at(0).slots)
        if (s.color) best = std::min(best, glm::dot(*was.color - *s.color, *was.color - *s.color));
      best = std::min(best, glm::dot(*was.color - glm::vec3(1.0f), *was.color - glm::vec3(1.0f)));
      EXPECT_FLOAT_EQ(glm::dot(*was.color - *now.color, *was.color - *now.color), best);
    }
  const std::string changed = showToText(d->show());
  ASSERT_TRUE(d->undo());
  EXPECT_EQ(showToText(d->show()), before);
  ASSERT_TRUE(d->redo());
  EXPECT_EQ(showToText(d->show()), changed);
}

TEST(ChangeType, AnOverlappingFootprintIsRefusedWithTheList) {
  REQUIRE_QLC();
  auto d = openDemo();
  ASSERT_TRUE(d);
  const std::string before = showToText(d->show());
  auto report = d->changeFixtureType({101, 102, 103, 104}, kRobin600, "Mode 1");
  ASSERT_FALSE(report.ok());
  const std::string e = report.error().str();
  // The demo's spots start 12 channels apart: each 32-slot footprint overlaps the next.
  for (const char* said : {"fixture 102 (universe 1 13-44) overlaps fixture 101 (universe 1 1-32)",
                           "fixture 104 (universe 1 37-68) overlaps fixture 103 (universe 1 25-56)"})
    EXPECT_NE(e.find(said), std::string::npos) << e;
  EXPECT_EQ(showToText(d->show()), before);
  EXPECT_EQ(d->history().undoSteps(), 0u);
  EXPECT_FALSE(d->changeFixtureType({101}, kRobin600, "No such mode").ok());
}

TEST(ChangeType, TheConsoleLineNamesFixturesTypeAndMode) {
  auto d = openDemo();
  ASSERT_TRUE(d);
  auto c = parseCommand("101 thru 104 type \"Robe Spot 160 XT\" mode \"8-channel, 16-Bit\"", d->show());
  ASSERT_TRUE(c.ok()) << c.error().str();
  EXPECT_EQ(c->action, ParsedCommand::Action::ChangeType);
  EXPECT_EQ(*c->selection, (std::vector<int>{101, 102, 103, 104}));
  EXPECT_EQ(c->name, "Robe Spot 160 XT");
  EXPECT_EQ(c->mode, "8-channel, 16-Bit");
  auto bare = parseCommand("101 type", d->show());
  ASSERT_FALSE(bare.ok());
  EXPECT_NE(bare.error().message.find("expected a fixture type"), std::string::npos);
  if (!fs::exists(kSpot160)) GTEST_SKIP() << "qlcplus-data is not installed (" << kSpot160 << ")";
  const fs::path cache = fs::temp_directory_path() / ("haze-change-type-" + std::to_string(::getpid()));
  ::setenv("XDG_CACHE_HOME", cache.c_str(), 1);
  auto said = runCommandLine(*d, "101 thru 104 type \"Robe Spot 160 XT\" mode \"8-channel, 16-Bit\"", 0.0);
  ASSERT_TRUE(said.ok()) << said.error().str();
  EXPECT_NE(said->find("Changed"), std::string::npos) << *said;
  EXPECT_EQ(d->profiles().at(d->show().findFixture(104)->profile)->name, "Spot 160 XT");
  EXPECT_EQ(d->history().undoSteps(), 1u);
  fs::remove_all(cache);
}

}  // namespace
}  // namespace haze
