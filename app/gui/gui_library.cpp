// The fixture library: the show's profiles (with what haze read from each: beam, zoom, wheels,
// modes), adding a profile file from disk (native .json, .ies, .ldt, .gdtf), and placing the
// picked profile by clicking a surface in the viewport (P).
#include <cstdio>

#include "app/gui/gui.h"

namespace haze {

void drawLibraryTab(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  if (ImGui::Button("Add file...")) requestFileAction(gui, FileAction::AddProfile);
  ImGui::SameLine();
  const bool canPlace = !gui.placeProfile.empty() && doc.profiles().count(gui.placeProfile);
  if (!canPlace) ImGui::BeginDisabled();
  if (ImGui::Button(gui.tool == Tool::Place ? "Placing: click a surface" : "Place (P)")) {
    gui.tool = Tool::Place;
    gui.say("click a truss, a ceiling, a floor or a wall to place a " + gui.placeProfile);
  }
  if (!canPlace) ImGui::EndDisabled();

  ImGui::BeginChild("profiles", ImVec2(0, ImGui::GetContentRegionAvail().y * 0.55f), true);
  for (const auto& [key, profile] : doc.profiles()) {
    if (!profile) continue;
    const std::string row = key + "  (" + profile->name + ")";
    if (ImGui::Selectable(row.c_str(), gui.placeProfile == key)) gui.placeProfile = key;
  }
  if (doc.profiles().empty()) ImGui::TextWrapped("No profiles: Add file... takes a native profile, .ies, .ldt or .gdtf.");
  ImGui::EndChild();

  const auto it = doc.profiles().find(gui.placeProfile);
  if (it == doc.profiles().end() || !it->second) return;
  const Profile& p = *it->second;
  ImGui::TextWrapped("%s %s", p.manufacturer.c_str(), p.name.c_str());
  const auto ref = doc.show().profiles.find(gui.placeProfile);
  if (ref != doc.show().profiles.end() && !ref->second.path.empty()) ImGui::TextWrapped("file: %s", ref->second.path.c_str());
  ImGui::Text("field %.1f deg, zoom %.0f..%.0f", p.fieldAngleDeg, p.zoomDeg.min, p.zoomDeg.max);
  ImGui::Text("pan %.0f..%.0f, tilt %.0f..%.0f", p.panDeg.min, p.panDeg.max, p.tiltDeg.min, p.tiltDeg.max);
  ImGui::Text("%zu gobo wheel(s), %zu colour wheel(s)", p.goboWheels.size(), p.colorWheels.size());
  for (const DmxMode& m : p.modes) ImGui::BulletText("mode %s: %d channels", m.name.c_str(), m.footprint());
}

}  // namespace haze
