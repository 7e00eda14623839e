// The patch table: every fixture by id (narrowed by the filter field the Fixtures tab shares),
// its name (its type on hover), its universe.address as a desk writes it, then universe, address, mode and footprint to edit;
// overlapping or out-of-range footprints are shown in red (patchConflicts, show_document.h). Universe 0
// unpatches. Typed numbers apply on Enter through patchFixture, which refuses a patch that would
// overlap (the status line says why).
#include <cstdio>

#include "app/gui/gui.h"

namespace haze {

void drawPatchTab(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  const std::set<int> conflicts = patchConflicts(doc.show(), doc.profiles());
  if (conflicts.empty()) ImGui::TextUnformatted("No conflicts.");
  else ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%zu fixture(s) overlap or run past 512", conflicts.size());
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit |
                                ImGuiTableFlags_BordersInnerV;
  // Copies: a command may change the fixture list while the table is drawn.
  std::vector<FixtureDef> fixtures;
  for (const FixtureDef* f : drawFixtureFilter(gui)) fixtures.push_back(*f);
  gui.patchRows.clear();
  if (!ImGui::BeginTable("patch", 7, flags, ImVec2(0, 0))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("Fixture");
  ImGui::TableSetupColumn("Name");
  ImGui::TableSetupColumn("U.Addr");
  ImGui::TableSetupColumn("Univ");
  ImGui::TableSetupColumn("Addr");
  ImGui::TableSetupColumn("Mode");
  ImGui::TableSetupColumn("Ch");
  ImGui::TableHeadersRow();
  for (const FixtureDef& f : fixtures) {
    gui.patchRows.push_back(f.id);
    ImGui::PushID(f.id);
    ImGui::TableNextRow();
    if (conflicts.count(f.id)) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(140, 30, 30, 255));
    ImGui::TableNextColumn();
    ImGui::Text("%d", f.id);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(f.name.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", fixtureTypeText(f, doc.profiles()).c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(patchText(f).c_str());
    int universe = f.patch ? f.patch->universe : 0, address = f.patch ? f.patch->address : 0;
    ImGui::TableNextColumn();
    // Enter applies a typed number (a half-typed address would collide on the way).
    ImGui::SetNextItemWidth(40);
    const bool u = ImGui::InputInt("##u", &universe, 0, 0, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(44);
    const bool a = ImGui::InputInt("##a", &address, 0, 0, ImGuiInputTextFlags_EnterReturnsTrue);
    if (u || a) {
      std::optional<Patch> patch;
      if (universe > 0) patch = Patch{universe, address};
      Status s = doc.run(patchFixture(f.id, patch));
      if (!s) gui.say(s.error().str(), true);
    }
    ImGui::TableNextColumn();
    const auto prof = doc.profiles().find(f.profile);
    ImGui::SetNextItemWidth(80);
    if (ImGui::BeginCombo("##mode", f.mode.c_str())) {
      if (prof != doc.profiles().end() && prof->second)
        for (const DmxMode& m : prof->second->modes)
          if (ImGui::Selectable(m.name.c_str(), m.name == f.mode) && m.name != f.mode)
            gui.report(doc.run(patchFixture(f.id, f.patch, m.name)), "fixture " + std::to_string(f.id) + " in mode " + m.name);
      ImGui::EndCombo();
    }
    ImGui::TableNextColumn();
    const auto fp = modeFootprint(doc.profiles(), f.profile, f.mode);
    ImGui::Text("%d", fp ? *fp : 0);
    ImGui::PopID();
  }
  ImGui::EndTable();
}

}  // namespace haze
