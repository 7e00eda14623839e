// The console command line under the show panel (docs/gui.md, "Console commands"): the field,
// Tab completion and Up/Down history through ImGui's text callbacks, and the last line's result.
// Parsing and running are shows/edit/command_syntax.h and command_run.h, tested without a window.
#include <cfloat>
#include <cstring>

#include "app/gui/gui.h"
#include "shows/edit/command_run.h"
#include "shows/edit/command_syntax.h"

namespace haze {

namespace {

void replaceText(ImGuiInputTextCallbackData* data, const std::string& text) {
  data->DeleteChars(0, data->BufTextLen);
  data->InsertChars(0, text.c_str());
}

int commandCallback(ImGuiInputTextCallbackData* data) {
  Gui& gui = *static_cast<Gui*>(data->UserData);
  if (data->EventFlag == ImGuiInputTextFlags_CallbackCompletion) {
    // Completes the text before the cursor; what follows the cursor stays.
    const std::string typed(data->Buf, static_cast<size_t>(data->CursorPos));
    const Completion c = completeCommand(typed, gui.doc->show());
    const std::string done = applyCompletion(typed, c);
    if (done != typed) {
      data->DeleteChars(0, data->CursorPos);
      data->InsertChars(0, done.c_str());
    }
    std::string offered;
    if (c.words.size() > 1)
      for (const std::string& w : c.words) offered += (offered.empty() ? "" : "  ") + w;
    else if (c.words.empty() && !c.hint.empty())
      offered = "next: " + c.hint;
    gui.commandOffered = offered;
  } else if (data->EventFlag == ImGuiInputTextFlags_CallbackHistory && !gui.commandHistory.empty()) {
    const int n = static_cast<int>(gui.commandHistory.size());
    int& at = gui.commandBrowse;  // -1: the line being typed
    if (data->EventKey == ImGuiKey_UpArrow) at = at < 0 ? n - 1 : std::max(at - 1, 0);
    else if (data->EventKey == ImGuiKey_DownArrow && at >= 0) at = at + 1 >= n ? -1 : at + 1;
    replaceText(data, at < 0 ? std::string() : gui.commandHistory[static_cast<size_t>(at)]);
  }
  return 0;
}

void runLine(Gui& gui) {
  const std::string line = gui.commandField;
  if (line.find_first_not_of(" \t") == std::string::npos) return;
  if (gui.commandHistory.empty() || gui.commandHistory.back() != line) gui.commandHistory.push_back(line);
  if (gui.commandHistory.size() > 100) gui.commandHistory.erase(gui.commandHistory.begin());
  gui.commandBrowse = -1;
  gui.commandOffered.clear();
  auto said = runCommandLine(*gui.doc, line, gui.nowS);
  if (said) {
    gui.commandResult = *said;
    gui.commandError = false;
    gui.commandField[0] = '\0';
  } else {
    // The line stays in the field, to be corrected.
    gui.commandResult = said.error().str();
    gui.commandError = true;
  }
}

}  // namespace

void drawCommandLine(Gui& gui) {
  const Rect& r = gui.layout.command;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin("Command line", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::TextUnformatted(">");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (gui.focusCommand) {
    ImGui::SetKeyboardFocusHere();
    gui.focusCommand = false;
  }
  const ImGuiInputTextFlags flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackCompletion |
                                    ImGuiInputTextFlags_CallbackHistory;
  if (ImGui::InputText("##command", gui.commandField, sizeof(gui.commandField), flags, commandCallback, &gui)) {
    runLine(gui);
    gui.focusCommand = true;  // Enter leaves the field in ImGui; a console's command line stays
  }
  const std::string& below = gui.commandOffered.empty() ? gui.commandResult : gui.commandOffered;
  if (!below.empty()) {
    const bool error = gui.commandOffered.empty() && gui.commandError;
    ImGui::PushStyleColor(ImGuiCol_Text, error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.7f, 0.9f, 0.7f, 1.0f));
    ImGui::TextWrapped("%s", below.c_str());
    ImGui::PopStyleColor();
  } else {
    ImGui::TextDisabled("L: type a command (1 thru 4 @ 50)");
  }
  ImGui::End();
}

}  // namespace haze
