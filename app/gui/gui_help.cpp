// The help window (F1): the keyboard shortcuts and mouse gestures, as lighting people expect
// them (GO on Space or Enter, as on a console's big button).
#include "app/gui/gui.h"

namespace haze {

namespace {

constexpr const char* kShortcuts[][2] = {
    {"Space, Enter", "GO: the next cue"},
    {"Backspace", "BACK: the previous cue"},
    {"G", "GOTO the cue picked in the cue list"},
    {"Ctrl+R", "Record the programmer into a new cue at the end"},
    {"Ctrl+Shift+R", "Live: record what DMX puts on stage into a new cue at the end"},
    {"Ctrl+U", "Update the picked cue with the programmer"},
    {"C", "Clear the programmer"},
    {"P", "Place a fixture of the library's profile: click a surface"},
    {"F", "Focus to point: click where the selection should aim"},
    {"L", "Command line (1 thru 4 @ 50): Enter runs, Tab completes, Up/Down recall"},
    {"E", "Lock the exposure at the EV on screen (fades keep it), or back to auto"},
    {"Esc", "Back to selecting (or clear the selection)"},
    {"Ctrl+A", "Select every fixture"},
    {"Delete", "Delete the selected fixtures"},
    {"Ctrl+Z", "Undo"},
    {"Ctrl+Shift+Z, Ctrl+Y", "Redo"},
    {"Ctrl+N / Ctrl+O", "New show / open a show"},
    {"Ctrl+I", "Import an MVR rig (the show is written beside it)"},
    {"Ctrl+E", "Export the saved show's rig as MVR"},
    {"Ctrl+S / Ctrl+Shift+S", "Save / save as"},
    {"Ctrl+Q", "Quit (asks about unsaved changes)"},
    {"F1", "This window"},
};

constexpr const char* kMouse[][2] = {
    {"Click", "Select a fixture (its marker or its beam); Ctrl toggles, Shift adds"},
    {"Drag a selected fixture", "Move it on its level; Ctrl+drag: up and down; Alt+drag: turn it"},
    {"Drag a selected beam's end ring", "Aim: the beam follows the point under the pointer"},
    {"Drag elsewhere", "Orbit the view"},
    {"Right or middle drag, Shift+drag", "Pan the view"},
    {"Wheel", "Zoom"},
};

void table(const char* id, const char* const (*rows)[2], size_t n) {
  if (ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
    for (size_t i = 0; i < n; ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(rows[i][0]);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", rows[i][1]);
    }
    ImGui::EndTable();
  }
}

}  // namespace

void drawHelp(Gui& gui) {
  if (!gui.showHelp) return;
  const Rect& v = gui.layout.viewport;
  ImGui::SetNextWindowPos(ImVec2(v.x + 10, v.y + 10), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(std::max(v.w - 20, 300.0f), std::max(v.h - 20, 200.0f)), ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);  // legible over a bright stage
  if (ImGui::Begin("Help: shortcuts", &gui.showHelp)) {
    ImGui::TextUnformatted("Keys (not while typing in a field)");
    table("keys", kShortcuts, std::size(kShortcuts));
    ImGui::Separator();
    ImGui::TextUnformatted("Mouse in the view");
    table("mouse", kMouse, std::size(kMouse));
  }
  ImGui::End();
}

}  // namespace haze
