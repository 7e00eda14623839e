// Files: new, open (by path, or from the recent list), import and export MVR, save, save as, adding profile
// files to the library, and the unsaved-changes guard in front of everything that would drop
// the open show (new, open, quit, closing the window). Open, Import MVR and Add profile use the
// desktop's file dialog (desktop_dialog.h) when there is one; Save as, and everything when there
// is none, takes a typed path in a popup that starts in the show's folder.
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstring>

#include "app/gui/gui.h"
#include "shows/edit/recent_files.h"
#include "shows/frame/live_session.h"
#include "shows/import/mvr_export.h"
#include "shows/import/mvr_import.h"

namespace haze {

namespace fs = std::filesystem;

void Gui::adopt(std::unique_ptr<ShowDocument> next) {
  doc = std::move(next);
  live.reset();  // live input was bound to the old show's patch
  camera = doc->show().cameras.empty() ? -1 : 0;
  orbit = doc->show().cameras.empty() ? Orbit{} : Orbit::from(doc->show().cameras.front());
  fovYDeg = doc->show().cameras.empty() ? 40.0f : doc->show().cameras.front().fovYDeg;
  tool = Tool::Select;
  cueCursor.reset();
  placeProfile = doc->profiles().empty() ? "" : doc->profiles().begin()->first;
  if (doc->cueList() && !doc->cueList()->cues.empty()) doc->jumpTo(0, nowS);
}

namespace {

void remember(Gui& gui, const fs::path& file) {
  gui.recent = withRecentFile(gui.recent, file);
  if (Status s = saveRecentFiles(recentFilesPath(), gui.recent); !s)
    gui.say("recent files not kept: " + s.error().str(), true);
}

void openPath(Gui& gui, const std::string& path) {
  auto next = ShowDocument::open(path);
  if (!next) {
    gui.say(next.error().str(), true);
    return;
  }
  gui.adopt(std::move(*next));
  gui.say("opened " + path);
  remember(gui, path);
}

std::string folderOf(const Gui& gui) {
  if (gui.doc->untitled()) return fs::current_path().string() + "/";
  return gui.doc->show().file.parent_path().string() + "/";
}

void askPath(Gui& gui, FileAction action) {
  gui.pathAction = action;
  gui.openPathPopup = true;
  std::string start = folderOf(gui);
  if (action == FileAction::SaveAs && !gui.doc->untitled()) start = gui.doc->show().file.string();
  if (action == FileAction::ExportMvr && !gui.doc->untitled()) {
    fs::path stem = gui.doc->show().file;
    while (stem.has_extension()) stem.replace_extension();  // "demo.haze.json" -> "demo"
    start = stem.string() + ".mvr";
  }
  std::snprintf(gui.pathField, sizeof(gui.pathField), "%s", start.c_str());
}

// The desktop's dialog for choosing an existing file; false when there is none (type the path).
bool startDesktopDialog(Gui& gui, FileAction action) {
  if (gui.dialog.running()) {
    gui.say("a file dialog is already open", true);
    return true;
  }
  std::string folder = folderOf(gui);
  if (folder.size() > 1 && folder.back() == '/') folder.pop_back();
  bool started = false;
  switch (action) {
    case FileAction::Open: started = gui.dialog.start("Open show", folder, "Shows", {"*.haze.json"}); break;
    case FileAction::ImportMvr: started = gui.dialog.start("Import MVR", folder, "MVR files", {"*.mvr"}); break;
    case FileAction::AddProfile:
      started = gui.dialog.start("Add profile", folder, "Profiles", {"*.json", "*.ies", "*.ldt", "*.gdtf"});
      break;
    default: break;
  }
  if (started) {
    gui.dialogAction = action;
    gui.say("choose the file in the dialog");
  }
  return started;
}

// Does what was asked, the guard having been passed.
void perform(Gui& gui, FileAction action, const std::string& path) {
  switch (action) {
    case FileAction::New: {
      auto next = ShowDocument::blank(gui.doc.get());
      if (!next) {
        gui.say(next.error().str(), true);
        return;
      }
      gui.adopt(std::move(*next));
      gui.say("new show on the same venue: add profiles in the Library tab, then place fixtures");
      return;
    }
    case FileAction::OpenPath: openPath(gui, path); return;
    case FileAction::Quit:
      gui.quitConfirmed = true;
      glfwSetWindowShouldClose(gui.window, GLFW_TRUE);
      return;
    case FileAction::Open:
    case FileAction::ImportMvr:
    case FileAction::AddProfile:
      if (!startDesktopDialog(gui, action)) askPath(gui, action);
      return;
    case FileAction::SaveAs: askPath(gui, action); return;
    case FileAction::ExportMvr:
      // The export reads the saved show and keeps the fixtures' new MVR uuids in it, as
      // `haze export-mvr` does, so the show on disk must be the one on screen.
      if (gui.doc->untitled() || gui.doc->modified()) {
        gui.say("save the show first: Export MVR writes the saved show (and keeps its fixtures' MVR uuids in it)", true);
        return;
      }
      askPath(gui, action);
      return;
    case FileAction::None: return;
  }
}

bool dropsTheShow(FileAction a) {
  return a == FileAction::New || a == FileAction::Open || a == FileAction::OpenPath || a == FileAction::ImportMvr ||
         a == FileAction::Quit;
}

// The path popup's OK.
void finishPath(Gui& gui, const std::string& path) {
  switch (gui.pathAction) {
    case FileAction::Open: openPath(gui, path); break;
    case FileAction::SaveAs: {
      Status s = gui.doc->save(path);
      gui.report(s, "saved " + path);
      if (s) remember(gui, path);
      break;
    }
    case FileAction::AddProfile: {
      auto key = gui.doc->addProfileFile(path);
      if (!key) {
        gui.say(key.error().str(), true);
        break;
      }
      gui.placeProfile = *key;
      gui.say("added profile '" + *key + "': press P (or Place) and click a surface");
      break;
    }
    case FileAction::ImportMvr: {
      const fs::path showFile = fs::path(path).replace_extension(".haze.json");
      auto imported = importMvr(path, showFile);
      if (!imported) {
        gui.say(imported.error().str(), true);
        break;
      }
      openPath(gui, showFile.string());
      gui.importWarnings = groupMvrWarnings(imported->warnings);
      gui.importedFrom = fs::path(path).filename().string();
      gui.showImportWarnings = !gui.importWarnings.empty();
      // Also on stderr, as `haze import-mvr` prints them, for logs and for tests.
      std::fprintf(stderr, "haze: imported %s: %d fixtures, %zu warnings\n", gui.importedFrom.c_str(),
                   imported->fixtureCount, imported->warnings.size());
      for (const std::string& w : gui.importWarnings) std::fprintf(stderr, "haze: warning: %s\n", w.c_str());
      if (gui.showImportWarnings)
        gui.say(std::to_string(imported->warnings.size()) + " import warnings: see the window", false);
      break;
    }
    case FileAction::ExportMvr: {
      const fs::path showFile = gui.doc->show().file;
      auto exported = exportMvrFromShowFile(showFile, path);
      if (!exported) {
        gui.say(exported.error().str(), true);
        break;
      }
      // New uuids were saved in the show: open it again so the window has them (and its stamp).
      if (exported->uuidsMade > 0) openPath(gui, showFile.string());
      std::fprintf(stderr, "haze: exported %s: MVR %s, %d fixtures, %zu warnings\n", path.c_str(), exported->version.c_str(),
                   exported->fixtureCount, exported->warnings.size());
      for (const std::string& w : exported->warnings) std::fprintf(stderr, "haze: warning: %s\n", w.c_str());
      gui.say("exported " + path + ": " + std::to_string(exported->fixtureCount) + " fixtures" +
                  (exported->warnings.empty() ? "" : ", " + std::to_string(exported->warnings.size()) + " warnings (on stderr)"),
              false);
      break;
    }
    default: break;
  }
}

}  // namespace

void requestFileAction(Gui& gui, FileAction action, std::string path) {
  if (dropsTheShow(action) && gui.doc->modified()) {
    gui.guarded = action;
    gui.guardedPath = std::move(path);
    gui.openGuardPopup = true;
    return;
  }
  perform(gui, action, path);
}

void saveCurrent(Gui& gui) {
  if (gui.doc->untitled()) {
    askPath(gui, FileAction::SaveAs);
    return;
  }
  const std::string file = gui.doc->show().file.string();
  Status s = gui.doc->save();
  gui.report(s, "saved " + file);
  if (s) remember(gui, file);
}

void drawFileDialogs(Gui& gui) {
  if (gui.dialog.running()) {
    std::string chosen;
    switch (gui.dialog.poll(chosen)) {
      case DesktopDialog::Outcome::Running: break;
      case DesktopDialog::Outcome::Chosen:
        gui.pathAction = gui.dialogAction;
        finishPath(gui, chosen);
        break;
      case DesktopDialog::Outcome::Cancelled: gui.say("cancelled"); break;
      case DesktopDialog::Outcome::Failed:
        gui.say("the desktop's file dialog gave no answer: type the path");
        askPath(gui, gui.dialogAction);
        break;
    }
  }
  // The window's close button goes through the guard like Quit does.
  if (glfwWindowShouldClose(gui.window) && !gui.quitConfirmed && gui.doc->modified()) {
    glfwSetWindowShouldClose(gui.window, GLFW_FALSE);
    requestFileAction(gui, FileAction::Quit);
  }
  if (gui.openGuardPopup) {
    ImGui::OpenPopup("Unsaved changes");
    gui.openGuardPopup = false;
  }
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has unsaved changes.", gui.doc->untitled() ? "The new show" : gui.doc->show().file.filename().c_str());
    if (ImGui::Button("Save")) {
      ImGui::CloseCurrentPopup();
      if (gui.doc->untitled()) {
        askPath(gui, FileAction::SaveAs);
        gui.say("save the new show first, then do it again");
      } else {
        saveCurrent(gui);
        if (!gui.doc->modified()) perform(gui, gui.guarded, gui.guardedPath);
      }
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard changes")) {
      ImGui::CloseCurrentPopup();
      perform(gui, gui.guarded, gui.guardedPath);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }

  if (gui.openPathPopup) {
    ImGui::OpenPopup("Path");
    gui.openPathPopup = false;
  }
  if (ImGui::BeginPopupModal("Path", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    const char* ask = gui.pathAction == FileAction::Open        ? "Open show (.haze.json):"
                      : gui.pathAction == FileAction::SaveAs     ? "Save show as (.haze.json):"
                      : gui.pathAction == FileAction::AddProfile ? "Add a profile file (.json, .ies, .ldt, .gdtf):"
                      : gui.pathAction == FileAction::ExportMvr  ? "Export the rig as MVR (.mvr):"
                                                                 : "Import MVR (.mvr); the show is written beside it:";
    ImGui::TextUnformatted(ask);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(std::max(gui.layout.viewport.w, 420.0f));
    const bool enter = ImGui::InputText("##path", gui.pathField, sizeof(gui.pathField), ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::Button("OK") || enter) {
      ImGui::CloseCurrentPopup();
      finishPath(gui, gui.pathField);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

}  // namespace haze
