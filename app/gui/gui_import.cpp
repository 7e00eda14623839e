// The window that lists an MVR import's warnings (what haze left out or read differently, each
// with its place in the XML), folded so a rig with a hundred stub GDTF channels reads as one
// line; `haze import-mvr --verbose` prints them all.
#include "app/gui/gui.h"

namespace haze {

void drawImportWarnings(Gui& gui) {
  if (!gui.showImportWarnings) return;
  const Rect& v = gui.layout.viewport;
  ImGui::SetNextWindowPos(ImVec2(v.x + 10, v.y + 10), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(std::max(v.w - 20, 300.0f), std::max(v.h * 0.5f, 160.0f)), ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);
  const std::string title = "Imported " + gui.importedFrom + ": " + std::to_string(gui.importWarnings.size()) +
                            " kinds of warning###import_warnings";
  if (ImGui::Begin(title.c_str(), &gui.showImportWarnings)) {
    for (const std::string& line : gui.importWarnings) {
      ImGui::Bullet();
      ImGui::SameLine();
      ImGui::TextWrapped("%s", line.c_str());
    }
    if (ImGui::Button("Close")) gui.showImportWarnings = false;
  }
  ImGui::End();
}

}  // namespace haze
