// The fixture list: every fixture of the show with its profile and patch; click selects, Ctrl
// toggles, Shift adds (the same rule as clicks in the viewport, shows/edit/picking.h).
#include <cstdio>

#include "app/gui/gui.h"

namespace haze {

void drawFixturesTab(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  ImGui::Text("%zu fixtures, %zu selected", doc.show().fixtures.size(), doc.selection.size());
  if (ImGui::Button("All")) {
    doc.selection.clear();
    for (const FixtureDef& f : doc.show().fixtures) doc.selection.push_back(f.id);
    std::sort(doc.selection.begin(), doc.selection.end());
  }
  ImGui::SameLine();
  if (ImGui::Button("None")) doc.selection.clear();
  ImGui::SameLine();
  if (doc.selection.empty()) ImGui::BeginDisabled();
  if (ImGui::Button("Delete")) {
    const size_t n = doc.selection.size();
    gui.report(doc.run(deleteFixtures(doc.selection)), "deleted " + std::to_string(n) + " fixture(s)");
  }
  if (doc.selection.empty()) ImGui::EndDisabled();

  ImGui::BeginChild("fixturelist", ImVec2(0, 0), true);
  const ImGuiIO& io = ImGui::GetIO();
  for (const FixtureDef& f : doc.show().fixtures) {
    const bool selected = std::find(doc.selection.begin(), doc.selection.end(), f.id) != doc.selection.end();
    const bool programmed = doc.programmer().values.count(f.id) > 0;
    char row[200];
    std::snprintf(row, sizeof(row), "%4d %s%s##fx%d", f.id, f.name.c_str(), programmed ? "  (P)" : "", f.id);
    if (ImGui::Selectable(row, selected)) applyClickToSelection(doc.selection, f.id, io.KeyCtrl, io.KeyShift);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s, mode %s, %s", f.profile.c_str(), f.mode.c_str(),
                        f.patch ? (std::to_string(f.patch->universe) + "." + std::to_string(f.patch->address)).c_str()
                                : "unpatched");
  }
  ImGui::EndChild();
}

}  // namespace haze
