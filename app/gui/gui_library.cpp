// The fixture library: the show's profiles (with what haze read from each: beam, zoom, wheels,
// modes), adding a profile file from disk (native .json, .ies, .ldt, .gdtf, .qxf), placing the
// picked profile by clicking a surface in the viewport (P), and searching the installed fixture
// library to change the selected fixtures' type (docs/fixtures.md, "Changing a fixture's type").
#include <cstdio>
#include <optional>

#include "app/gui/gui.h"
#include "fixtures/fixture_library.h"

namespace haze {

namespace {

// The library search's state: one Library tab per window, so it lives here rather than in Gui.
struct LibrarySearch {
  std::optional<LibraryIndex> index;  // indexed (from the cache) the first time the tab searches
  char text[128] = "";
  std::string shownFor = "\x01";
  std::vector<const LibraryEntry*> hits;
  int picked = -1;
  int mode = 0;
};

void drawChangeType(Gui& gui, LibrarySearch& s) {
  ShowDocument& doc = *gui.doc;
  ImGui::Separator();
  ImGui::TextUnformatted("Library: change type");
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint("##librarysearch", "search: robin 600, alphaspot...", s.text, sizeof s.text);
  if (s.shownFor != s.text) {
    if (!s.index) s.index = indexLibrary(libraryFolders({}), defaultLibraryCache());
    s.hits = s.text[0] ? searchLibrary(*s.index, s.text) : std::vector<const LibraryEntry*>{};
    if (s.hits.size() > 200) s.hits.resize(200);
    s.shownFor = s.text;
    s.picked = -1;
    s.mode = 0;
  }
  ImGui::BeginChild("library hits", ImVec2(0, ImGui::GetContentRegionAvail().y * 0.5f), true);
  for (size_t k = 0; k < s.hits.size(); ++k) {
    const LibraryEntry& e = *s.hits[k];
    const std::string row = e.title() + "  (" + e.type + ")##" + e.file;
    if (ImGui::Selectable(row.c_str(), s.picked == static_cast<int>(k))) {
      s.picked = static_cast<int>(k);
      s.mode = 0;
    }
  }
  ImGui::EndChild();
  if (s.picked < 0 || static_cast<size_t>(s.picked) >= s.hits.size()) return;
  const LibraryEntry& e = *s.hits[static_cast<size_t>(s.picked)];
  if (e.modes.empty()) return;
  s.mode = std::clamp(s.mode, 0, static_cast<int>(e.modes.size()) - 1);
  const std::string current = e.modes[static_cast<size_t>(s.mode)].name + " (" + std::to_string(e.modes[static_cast<size_t>(s.mode)].channels) + " ch)";
  if (ImGui::BeginCombo("mode", current.c_str())) {
    for (size_t m = 0; m < e.modes.size(); ++m) {
      const std::string label = e.modes[m].name + " (" + std::to_string(e.modes[m].channels) + " ch)";
      if (ImGui::Selectable(label.c_str(), s.mode == static_cast<int>(m))) s.mode = static_cast<int>(m);
    }
    ImGui::EndCombo();
  }
  if (doc.selection.empty()) ImGui::BeginDisabled();
  const std::string button = "Change type of " + std::to_string(doc.selection.size()) + " selected";
  if (ImGui::Button(button.c_str())) {
    auto report = doc.changeFixtureType(doc.selection, e.file, e.modes[static_cast<size_t>(s.mode)].name);
    if (!report)
      gui.say(report.error().str(), true);
    else
      gui.say("Changed " + std::to_string(doc.selection.size()) + " fixtures to " + e.title() + "; " +
              std::to_string(report->lines.size()) + " values not carried over as they were" +
              (report->lines.empty() ? "" : " (" + report->lines.front() + (report->lines.size() > 1 ? "; ..." : "") + ")"));
  }
  if (doc.selection.empty()) ImGui::EndDisabled();
}

}  // namespace

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
  if (doc.profiles().empty()) ImGui::TextWrapped("No profiles: Add file... takes a native profile, .ies, .ldt, .gdtf or .qxf.");
  ImGui::EndChild();

  static LibrarySearch search;
  drawChangeType(gui, search);

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
