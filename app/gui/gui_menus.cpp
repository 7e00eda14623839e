// The menu bar (File, Edit, View, Help, the viewport's tools, frame time, status line) and the
// keyboard shortcuts. ImGui 1.86 takes the backend's key codes (GLFW_KEY_*) in IsKeyPressed.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/gui/gui.h"

namespace haze {

namespace {

void clearProgrammerNow(Gui& gui) {
  if (gui.doc->programmer().values.empty()) return;
  gui.report(gui.doc->run(clearProgrammer()), "programmer cleared");
}

void deleteSelection(Gui& gui) {
  if (gui.doc->selection.empty()) return;
  const size_t n = gui.doc->selection.size();
  gui.report(gui.doc->run(deleteFixtures(gui.doc->selection)), "deleted " + std::to_string(n) + " fixture(s)");
}

void selectAll(Gui& gui) {
  gui.doc->selection.clear();
  for (const FixtureDef& f : gui.doc->show().fixtures) gui.doc->selection.push_back(f.id);
  std::sort(gui.doc->selection.begin(), gui.doc->selection.end());
}

void undo(Gui& gui) {
  const std::string label = gui.doc->history().undoLabel();
  if (gui.doc->undo()) gui.say("undid: " + label);
}

void redo(Gui& gui) {
  const std::string label = gui.doc->history().redoLabel();
  if (gui.doc->redo()) gui.say("redid: " + label);
}

void startPlacing(Gui& gui) {
  if (gui.placeProfile.empty() || !gui.doc->profiles().count(gui.placeProfile)) {
    gui.say("pick a profile in the Library tab first, then click a surface to place it", true);
    return;
  }
  gui.tool = Tool::Place;
  gui.say("click a truss, a ceiling, a floor or a wall to place a " + gui.placeProfile);
}

void startFocus(Gui& gui) {
  if (gui.doc->selection.empty()) {
    gui.say("select a fixture first, then focus it on a point", true);
    return;
  }
  gui.tool = Tool::Focus;
  gui.say("click the point the selected fixture(s) should aim at");
}

// A fade judged under auto exposure is brightened by the meter as it falls; locked, every frame
// is shown at the EV on screen when the lock was taken (docs/rendering.md, "Exposure").
void toggleExposureLock(Gui& gui) {
  // A lock remembered from the last run but not yet taken (no metered frame yet) counts as on.
  const bool locked = gui.exposureLocked() || gui.lockExposureWhenMetered;
  setExposureMode(gui, locked ? ExposureMode::Auto : ExposureMode::Manual);
  char line[96];
  if (gui.exposureLocked()) std::snprintf(line, sizeof line, "exposure locked at EV %.1f", gui.exposureEv);
  else std::snprintf(line, sizeof line, "exposure follows the meter again");
  gui.say(line);
}

}  // namespace

void handleShortcuts(Gui& gui) {
  const std::vector<Gui::KeyPress> keys = std::move(gui.keys);
  gui.keys.clear();
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
  const double now = gui.nowS;
  for (const Gui::KeyPress& k : keys) {
    const bool ctrl = k.mods & GLFW_MOD_CONTROL, shift = k.mods & GLFW_MOD_SHIFT;
    if (ctrl) {
      switch (k.key) {
        case GLFW_KEY_Z: shift ? redo(gui) : undo(gui); break;
        case GLFW_KEY_Y: redo(gui); break;
        case GLFW_KEY_A: selectAll(gui); break;
        case GLFW_KEY_R: shift ? recordDmxLook(gui) : recordCueFromProgrammer(gui); break;
        case GLFW_KEY_U: updateCursorCue(gui); break;
        case GLFW_KEY_S: shift ? requestFileAction(gui, FileAction::SaveAs) : saveCurrent(gui); break;
        case GLFW_KEY_O: requestFileAction(gui, FileAction::Open); break;
        case GLFW_KEY_I: requestFileAction(gui, FileAction::ImportMvr); break;
        case GLFW_KEY_E: requestFileAction(gui, FileAction::ExportMvr); break;
        case GLFW_KEY_N: requestFileAction(gui, FileAction::New); break;
        case GLFW_KEY_Q: requestFileAction(gui, FileAction::Quit); break;
        default: break;
      }
      continue;
    }
    switch (k.key) {
      case GLFW_KEY_SPACE:
      case GLFW_KEY_ENTER:
      case GLFW_KEY_KP_ENTER:
        if (!gui.live && !gui.doc->go(now)) gui.say("GO: no next cue");
        break;
      case GLFW_KEY_BACKSPACE:
        if (!gui.live && !gui.doc->back(now)) gui.say("BACK: no previous cue");
        break;
      case GLFW_KEY_G:
        if (gui.cueCursor) gui.doc->gotoCue(*gui.cueCursor, now);
        break;
      case GLFW_KEY_C: clearProgrammerNow(gui); break;
      case GLFW_KEY_P: startPlacing(gui); break;
      case GLFW_KEY_F: startFocus(gui); break;
      case GLFW_KEY_DELETE: deleteSelection(gui); break;
      case GLFW_KEY_L: gui.focusCommand = true; break;
      case GLFW_KEY_E: toggleExposureLock(gui); break;
      case GLFW_KEY_F1: gui.showHelp = !gui.showHelp; break;
      case GLFW_KEY_ESCAPE:
        if (gui.tool != Tool::Select) gui.tool = Tool::Select;
        else gui.doc->selection.clear();
        break;
      default: break;
    }
  }
}

void drawMenuBar(Gui& gui) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New show", "Ctrl+N")) requestFileAction(gui, FileAction::New);
    if (ImGui::MenuItem("Open show...", "Ctrl+O")) requestFileAction(gui, FileAction::Open);
    if (ImGui::BeginMenu("Open recent", !gui.recent.empty())) {
      for (const std::string& r : gui.recent)
        if (ImGui::MenuItem(r.c_str())) requestFileAction(gui, FileAction::OpenPath, r);
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Import MVR...", "Ctrl+I")) requestFileAction(gui, FileAction::ImportMvr);
    if (ImGui::MenuItem("Export MVR...", "Ctrl+E")) requestFileAction(gui, FileAction::ExportMvr);
    if (ImGui::MenuItem("MVR-xchange...", nullptr, gui.showXchange)) gui.showXchange = !gui.showXchange;
    ImGui::Separator();
    if (ImGui::MenuItem("Save", "Ctrl+S")) saveCurrent(gui);
    if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S")) requestFileAction(gui, FileAction::SaveAs);
    // Save refuses to overwrite a show that changed on disk since it was loaded; this does.
    if (ImGui::MenuItem("Save over changes on disk", nullptr, false, !gui.doc->untitled())) {
      const std::string file = gui.doc->show().file.string();
      gui.report(gui.doc->save({}, /*force=*/true), "saved " + file + " (over the file on disk)");
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) requestFileAction(gui, FileAction::Quit);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const std::string u = "Undo " + gui.doc->history().undoLabel(), r = "Redo " + gui.doc->history().redoLabel();
    if (ImGui::MenuItem(u.c_str(), "Ctrl+Z", false, gui.doc->history().canUndo())) undo(gui);
    if (ImGui::MenuItem(r.c_str(), "Ctrl+Shift+Z", false, gui.doc->history().canRedo())) redo(gui);
    ImGui::Separator();
    if (ImGui::MenuItem("Select all fixtures", "Ctrl+A")) selectAll(gui);
    if (ImGui::MenuItem("Delete selected fixtures", "Del", false, !gui.doc->selection.empty())) deleteSelection(gui);
    if (ImGui::MenuItem("Clear programmer", "C", false, !gui.doc->programmer().values.empty())) clearProgrammerNow(gui);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    const auto& cams = gui.doc->show().cameras;
    for (size_t i = 0; i < cams.size(); ++i) {
      const std::string label = "Camera: " + cams[i].name;
      if (ImGui::MenuItem(label.c_str(), nullptr, gui.camera == static_cast<int>(i))) {
        gui.camera = static_cast<int>(i);
        gui.orbit = Orbit::from(cams[i]);
        gui.fovYDeg = cams[i].fovYDeg;
      }
    }
    ImGui::Separator();
    const char* names[] = {"Draft", "Default", "High"};
    for (int q = 0; q < 3; ++q)
      if (ImGui::MenuItem(names[q], nullptr, static_cast<int>(gui.quality) == q)) gui.quality = static_cast<Quality>(q);
    // While anything moves, frames are drawn smaller to keep about this time (0: full size).
    float budget = static_cast<float>(gui.draftBudgetMs);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    if (ImGui::SliderFloat("Draft budget", &budget, 0.0f, 200.0f, budget <= 0.0f ? "full size" : "%.0f ms"))
      gui.draftBudgetMs = std::max(0.0f, budget);
    ImGui::Separator();
    // docs/movement.md: off, heads jump to every value at once.
    ImGui::MenuItem("Real movement speeds", nullptr, &gui.realMovement);
    ImGui::MenuItem("Fixture bodies", nullptr, &gui.showBodies);
    ImGui::MenuItem("Fixture numbers", nullptr, &gui.showNumbers);
    ImGui::Separator();
    if (ImGui::MenuItem("Lock exposure", "E", gui.exposureLocked() || gui.lockExposureWhenMetered)) toggleExposureLock(gui);
    ImGui::Separator();
    // A multi-cell fixture as one beam where its cells act as one, or always one beam per cell
    // (docs/cells.md, "Cost"). Last in the menu: the GUI tests click the items above by place.
    if (ImGui::BeginMenu("Cells")) {
      const std::pair<CellBeams, const char*> choices[] = {{CellBeams::Auto, "One beam where driven alike"},
                                                           {CellBeams::Separate, "One beam per cell"},
                                                           {CellBeams::Merged, "One beam per fixture"}};
      for (const auto& [mode, label] : choices)
        if (ImGui::MenuItem(label, nullptr, gui.cells == mode)) gui.cells = mode;
      ImGui::EndMenu();
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Shortcuts", "F1", gui.showHelp)) gui.showHelp = !gui.showHelp;
    ImGui::EndMenu();
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Select", "Esc", gui.tool == Tool::Select)) gui.tool = Tool::Select;
  if (ImGui::MenuItem("Place", "P", gui.tool == Tool::Place)) startPlacing(gui);
  if (ImGui::MenuItem("Focus", "F", gui.tool == Tool::Focus)) startFocus(gui);
  ImGui::Separator();
  char timing[64];
  if (gui.mapsPending > 0) std::snprintf(timing, sizeof(timing), "%4.0f ms  catching up: %d maps", gui.frameMs, gui.mapsPending);
  else if (gui.stillFrames > 0) std::snprintf(timing, sizeof(timing), "%4.0f ms  refining %d", gui.frameMs, gui.stillFrames);
  else if (gui.draftScale < 1.0f)
    std::snprintf(timing, sizeof(timing), "%4.0f ms  draft at %.0f %%%s", gui.frameMs, 100.0f * gui.draftScale,
                  gui.draftLimited ? ", over budget" : "");
  else std::snprintf(timing, sizeof(timing), "%4.0f ms  draft", gui.frameMs);
  ImGui::TextUnformatted(timing);
  // The EV on screen, always in sight: a designer judging a fade must know whether the meter moves it.
  ImGui::Separator();
  char ev[48];
  std::snprintf(ev, sizeof ev, "EV %.1f %s", std::isfinite(gui.shownEv) ? gui.shownEv : 0.0f,
                gui.exposureLocked() ? "locked" : "auto");
  ImGui::TextUnformatted(ev);
  if (!gui.status.empty()) {
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, gui.statusError ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.7f, 0.9f, 0.7f, 1.0f));
    ImGui::TextUnformatted(gui.status.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::EndMainMenuBar();
}

}  // namespace haze
