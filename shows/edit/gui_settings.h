// The GUI's view settings that outlive a run (docs/gui.md, "Remembered between runs"), kept in
// gui-settings.json beside the recent files ($XDG_CONFIG_HOME/haze or ~/.config/haze): what a
// designer sets up once per machine and expects to find again, not part of any show. Pure read
// and write here so the file's rules are tested without a window; the GUI applies them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "fixtures/core/result.h"

namespace haze {

struct GuiSettings {
  // The show panel's width as the designer dragged it; none: the width that fits the tab names.
  std::optional<float> showPanelWidthPx;
  // Lock state only, not the EV: an EV suits one show, cue and rig, and last night's could be
  // black or blown out today; the GUI meters its first frame and locks there.
  bool exposureLocked = false;
  bool fixtureNumbers = true;
  std::string viewportQuality = "default";  // "draft", "default" or "high" (the View menu's)
  std::string cells = "auto";                // View > Cells: "auto", "separate" or "merged" (docs/cells.md)
  bool operator==(const GuiSettings&) const = default;
};

// The settings and, when the file was broken, its first problem (file, place, what was
// expected). A broken value leaves that one setting at its default; text that is not JSON
// leaves them all at theirs. Unknown keys are ignored (a newer haze may have written them).
struct GuiSettingsLoad {
  GuiSettings settings;
  std::optional<Error> problem;
};

// Beside recentFilesPath(); empty when neither XDG_CONFIG_HOME nor HOME is set.
std::filesystem::path guiSettingsPath();
GuiSettingsLoad parseGuiSettings(std::string_view text, const std::string& fileName);
// A missing file (or an empty path) is the defaults, with no problem.
GuiSettingsLoad loadGuiSettings(const std::filesystem::path& file);
std::string guiSettingsJson(const GuiSettings& s);
// Written atomically (writeFileAtomically), the folder created when missing.
Status saveGuiSettings(const std::filesystem::path& file, const GuiSettings& s);

// What to write after a run changed some settings: `saved` (the file's) with each setting that
// differs between `before` and `now` taken from `now`. A setting a command-line option chose for
// this run only (--quality, --exposure-mode) is in `before` already, so it is not written unless
// the designer then changes it in the GUI.
GuiSettings withChangedSettings(GuiSettings saved, const GuiSettings& before, const GuiSettings& now);

}  // namespace haze
