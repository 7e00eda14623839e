// The fixture list: every fixture of the show by id, with its name, universe.address, type
// (shows/edit/fixture_rows.h) and whether the programmer holds it, narrowed by the filter field; click selects, Ctrl toggles,
// Shift adds (the same rule as clicks in the viewport, shows/edit/picking.h).
#include <cstdio>

#include "app/gui/gui.h"

namespace haze {

std::vector<const FixtureDef*> drawFixtureFilter(Gui& gui) {
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##fixturefilter", "filter: id, name, type, 2.101", gui.fixtureFilter, sizeof gui.fixtureFilter);
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  gui.filterField = {a.x, a.y, b.x - a.x, b.y - a.y};
  return listedFixtures(gui.doc->show(), gui.fixtureFilter);
}

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
  const std::vector<const FixtureDef*> listed = drawFixtureFilter(gui);

  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit |
                                ImGuiTableFlags_BordersOuter;
  gui.fixtureRows.clear();
  if (!ImGui::BeginTable("fixturelist", 4, flags, ImVec2(0, 0))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("Id");
  ImGui::TableSetupColumn("Name", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("U.Addr");
  ImGui::TableSetupColumn("Type");
  ImGui::TableHeadersRow();
  const ImGuiIO& io = ImGui::GetIO();
  // Ids only: a click may change the selection while the rows are drawn, never the fixtures.
  for (const FixtureDef* fp : listed) {
    const FixtureDef& f = *fp;
    gui.fixtureRows.push_back(f.id);
    const bool selected = std::find(doc.selection.begin(), doc.selection.end(), f.id) != doc.selection.end();
    const bool programmed = doc.programmer().values.count(f.id) > 0;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    char id[32];
    std::snprintf(id, sizeof id, "%d##fx%d", f.id, f.id);
    if (ImGui::Selectable(id, selected, ImGuiSelectableFlags_SpanAllColumns))
      applyClickToSelection(doc.selection, f.id, io.KeyCtrl, io.KeyShift);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s, mode %s, %s", f.profile.c_str(), f.mode.c_str(), f.patch ? patchText(f).c_str() : "unpatched");
    ImGui::TableNextColumn();
    ImGui::Text("%s%s", f.name.c_str(), programmed ? "  (P)" : "");
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(patchText(f).c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(fixtureTypeText(f, doc.profiles()).c_str());
  }
  ImGui::EndTable();
}

}  // namespace haze
