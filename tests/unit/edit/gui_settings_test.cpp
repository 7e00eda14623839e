// The GUI's remembered view settings (shows/edit/gui_settings.h): defaults without a file, a
// round trip through the file, broken files named by file and place with the defaults used,
// unknown keys ignored, and which settings a run writes back.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include "shows/edit/gui_settings.h"

namespace haze {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("haze-gui-settings-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(GuiSettings, AMissingFileIsTheDefaults) {
  const fs::path dir = scratchDir("missing");
  const GuiSettingsLoad l = loadGuiSettings(dir / "haze/gui-settings.json");
  EXPECT_FALSE(l.problem);
  EXPECT_EQ(l.settings, GuiSettings{});
  EXPECT_FALSE(l.settings.showPanelWidthPx);  // the panel fits its tabs
  EXPECT_FALSE(l.settings.exposureLocked);
  EXPECT_TRUE(l.settings.fixtureNumbers);
  EXPECT_EQ(l.settings.viewportQuality, "default");
  EXPECT_EQ(l.settings.cells, "auto");
  EXPECT_FALSE(loadGuiSettings({}).problem);  // no HOME: nothing to read, nothing wrong
  fs::remove_all(dir);
}

TEST(GuiSettings, SavedAtomicallyIntoANewFolderAndReadBack) {
  const fs::path dir = scratchDir("roundtrip");
  const fs::path file = dir / "haze/gui-settings.json";
  const GuiSettings s{.showPanelWidthPx = 512.5f, .exposureLocked = true, .fixtureNumbers = false,
                      .viewportQuality = "high", .cells = "separate"};
  ASSERT_TRUE(saveGuiSettings(file, s));
  const GuiSettingsLoad l = loadGuiSettings(file);
  EXPECT_FALSE(l.problem);
  EXPECT_EQ(l.settings, s);
  // Nothing but the file is left in the folder (the atomic writer's temporary is renamed).
  EXPECT_EQ(std::distance(fs::directory_iterator(file.parent_path()), fs::directory_iterator{}), 1);
  // A default width is written as null and read back as none.
  ASSERT_TRUE(saveGuiSettings(file, GuiSettings{}));
  EXPECT_NE(readAll(file).find("\"show_panel_width_px\": null"), std::string::npos) << readAll(file);
  EXPECT_EQ(loadGuiSettings(file).settings, GuiSettings{});
  fs::remove_all(dir);
}

TEST(GuiSettings, TextThatIsNotJsonIsNamedByLineAndColumnAndGivesTheDefaults) {
  const GuiSettingsLoad l = parseGuiSettings("{\n  \"fixture_numbers\": false,\n  \"exposure_locked\": tru\n}\n", "g.json");
  ASSERT_TRUE(l.problem);
  EXPECT_EQ(l.problem->file, "g.json");
  EXPECT_EQ(l.problem->place.rfind("line 3, column", 0), 0u) << l.problem->place;
  EXPECT_NE(l.problem->message.find("not valid JSON"), std::string::npos) << l.problem->message;
  EXPECT_EQ(l.problem->str().find('\n'), std::string::npos) << "one line for the status line";
  EXPECT_EQ(l.settings, GuiSettings{});  // the numbers' false before the error is not taken
}

TEST(GuiSettings, ABadValueNamesItsKeyAndOnlyThatSettingIsTheDefault) {
  GuiSettingsLoad l = parseGuiSettings(R"({"fixture_numbers": false, "exposure_locked": "yes"})", "g.json");
  ASSERT_TRUE(l.problem);
  EXPECT_EQ(l.problem->str().rfind("g.json:/exposure_locked: expected true or false", 0), 0u) << l.problem->str();
  EXPECT_FALSE(l.settings.exposureLocked);
  EXPECT_FALSE(l.settings.fixtureNumbers);  // the good value is kept

  for (const char* width : {"-20", "0", "1e9", "\"wide\""}) {
    l = parseGuiSettings(std::string(R"({"show_panel_width_px": )") + width + "}", "g.json");
    ASSERT_TRUE(l.problem) << width;
    EXPECT_EQ(l.problem->place, "/show_panel_width_px");
    EXPECT_FALSE(l.settings.showPanelWidthPx) << width;
  }
  l = parseGuiSettings(R"({"viewport_quality": "reference"})", "g.json");
  ASSERT_TRUE(l.problem);
  EXPECT_EQ(l.problem->place, "/viewport_quality");
  EXPECT_EQ(l.settings.viewportQuality, "default");
  l = parseGuiSettings(R"({"cells": "one", "viewport_quality": "draft"})", "g.json");
  ASSERT_TRUE(l.problem);
  EXPECT_EQ(l.problem->str(), "g.json:/cells: expected \"auto\", \"separate\" or \"merged\"; the default is used");
  EXPECT_EQ(l.settings.cells, "auto");
  EXPECT_EQ(l.settings.viewportQuality, "draft");

  l = parseGuiSettings("[1, 2]", "g.json");
  ASSERT_TRUE(l.problem);
  EXPECT_EQ(l.settings, GuiSettings{});
}

TEST(GuiSettings, UnknownKeysAreIgnored) {
  const GuiSettingsLoad l =
      parseGuiSettings(R"({"from_a_newer_haze": {"x": 1}, "viewport_quality": "draft", "show_panel_width_px": 340})", "g.json");
  EXPECT_FALSE(l.problem) << l.problem->str();
  EXPECT_EQ(l.settings.viewportQuality, "draft");
  ASSERT_TRUE(l.settings.showPanelWidthPx);
  EXPECT_FLOAT_EQ(*l.settings.showPanelWidthPx, 340.0f);
}

TEST(GuiSettings, ARunWritesBackOnlyWhatTheDesignerChanged) {
  const GuiSettings saved{.showPanelWidthPx = 400.0f, .exposureLocked = true, .fixtureNumbers = true,
                          .viewportQuality = "high"};
  // This run started with --quality draft (the file keeps "high"); the designer then turned the
  // numbers off.
  GuiSettings before = saved;
  before.viewportQuality = "draft";
  GuiSettings now = before;
  now.fixtureNumbers = false;
  GuiSettings next = withChangedSettings(saved, before, now);
  EXPECT_EQ(next.viewportQuality, "high");
  EXPECT_FALSE(next.fixtureNumbers);
  EXPECT_EQ(next.showPanelWidthPx, saved.showPanelWidthPx);
  EXPECT_TRUE(next.exposureLocked);
  // A quality chosen in the GUI is a change, and is written; so is View > Cells.
  now.viewportQuality = "default";
  now.cells = "separate";
  next = withChangedSettings(next, before, now);
  EXPECT_EQ(next.viewportQuality, "default");
  EXPECT_EQ(next.cells, "separate");
  // Nothing changed: the file's settings unchanged (the GUI then writes nothing).
  EXPECT_EQ(withChangedSettings(saved, now, now), saved);
}

}  // namespace
}  // namespace haze
