// The view settings the GUI remembers between runs (shows/edit/gui_settings.h, docs/gui.md): read
// once at start, where the command line leaves them free; written when the designer changes one,
// compared once a frame, so a drag or a menu click writes the file once, not every frame.
#include <cmath>
#include <cstdio>

#include "app/gui/gui.h"
#include "app/render_session.h"

namespace haze {

GuiSettings viewSettingsOf(const Gui& gui) {
  GuiSettings s;
  // Whole pixels: the file stays readable, and a drag moves by whole pixels anyway.
  if (gui.showPanelW > 0.0f) s.showPanelWidthPx = std::round(gui.showPanelW);
  // A lock remembered but not yet applied (no metered frame yet) is still on.
  s.exposureLocked = gui.exposureLocked() || gui.lockExposureWhenMetered;
  s.fixtureNumbers = gui.showNumbers;
  s.viewportQuality = qualityName(gui.quality);
  s.cells = cellBeamsName(gui.cells);
  return s;
}

void loadViewSettings(Gui& gui, bool qualityFromCommandLine, bool exposureFromCommandLine) {
  gui.settingsFile = guiSettingsPath();
  const GuiSettingsLoad l = loadGuiSettings(gui.settingsFile);
  if (l.problem) {
    // Said once, here; the file stays as it is until a setting changes (the designer may want
    // to mend it by hand).
    const std::string line = l.problem->str();
    std::fprintf(stderr, "haze: warning: %s\n", line.c_str());
    gui.say(line, true);
  }
  const GuiSettings& s = l.settings;
  if (s.showPanelWidthPx) gui.showPanelW = *s.showPanelWidthPx;  // showPanelWidth clamps it to the window
  gui.showNumbers = s.fixtureNumbers;
  gui.cells = cellBeamsNamed(s.cells);
  if (!qualityFromCommandLine)
    if (auto q = parseQuality(s.viewportQuality)) gui.quality = *q;
  // The lock, not last run's EV: the first frame whose maps are current is metered and locked
  // there (drawStage). --exposure-mode, or a show camera's manual exposure, decides instead.
  if (s.exposureLocked && !exposureFromCommandLine && !gui.exposureLocked()) gui.lockExposureWhenMetered = true;
  gui.settingsSaved = s;
  gui.settingsBefore = viewSettingsOf(gui);
}

void keepViewSettings(Gui& gui) {
  // Not while a button is held: a drag of the panel's edge is written once, when it ends.
  if (ImGui::IsAnyMouseDown()) return;
  const GuiSettings now = viewSettingsOf(gui);
  if (now == gui.settingsBefore) return;
  const GuiSettings next = withChangedSettings(gui.settingsSaved, gui.settingsBefore, now);
  gui.settingsBefore = now;
  if (next == gui.settingsSaved) return;
  // Kept as changed even when the write fails, so a full disk is said once, not every frame.
  gui.settingsSaved = next;
  if (Status s = saveGuiSettings(gui.settingsFile, next); !s) gui.say("view settings not kept: " + s.error().str(), true);
}

}  // namespace haze
