// The fixture library: the show's profiles (with what haze read from each: beam, zoom, wheels,
// modes), adding a profile file from disk (native .json, .ies, .ldt, .gdtf, .qxf), placing the
// picked profile by clicking a surface in the viewport (P), and searching the installed fixture
// library to change the selected fixtures' type (docs/fixtures.md, "Changing a fixture's type").
#include <cmath>
#include <cstdio>
#include <optional>

#include <glm/trigonometric.hpp>

#include "app/gui/gui.h"
#include "fixtures/facts.h"
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
  std::string factsFor;  // the file `facts` were read from: a hit's profile loads once per pick
  PickFacts facts;
};

// The beam's shape as a cone seen from the side: the intensity over the peak at each angle off
// the axis is the distance from the lens (the apex, top middle) drawn in that direction.
void drawBeamShape(const std::vector<float>& shape) {
  const float size = 48.0f;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 apex(at.x + size, at.y + 4.0f);
  std::vector<ImVec2> outline;
  for (int g = -90; g <= 90; ++g) {
    const float r = size * shape[static_cast<size_t>(std::abs(g))];
    const float a = glm::radians(static_cast<float>(g));
    outline.emplace_back(apex.x + r * std::sin(a), apex.y + r * std::cos(a));
  }
  draw->AddLine(apex, ImVec2(apex.x, apex.y + size), IM_COL32(90, 90, 90, 255));
  for (size_t k = 1; k < outline.size(); ++k) draw->AddTriangleFilled(apex, outline[k - 1], outline[k], IM_COL32(255, 225, 150, 110));
  draw->AddPolyline(outline.data(), static_cast<int>(outline.size()), IM_COL32(255, 225, 150, 255), 0, 1.5f);
  ImGui::Dummy(ImVec2(2.0f * size, size + 8.0f));
}

// The picked hit's facts (fixtures/facts.h pickFacts), read from its file the first time it is
// picked.
void readPickedFacts(LibrarySearch& s, const LibraryEntry& e) {
  if (s.factsFor != e.file) {
    auto profile = loadProfile(e.file);
    s.facts = pickFacts(e, profile.ok() ? profile->get() : nullptr);
    if (!profile.ok()) s.facts.lines.push_back("does not load: " + profile.error().message);
    s.factsFor = e.file;
  }
}

void drawPickedFacts(const LibrarySearch& s) {
  for (const std::string& line : s.facts.lines) ImGui::BulletText("%s", line.c_str());
}

void drawChangeType(Gui& gui, LibrarySearch& s) {
  ShowDocument& doc = *gui.doc;
  ImGui::Separator();
  ImGui::TextUnformatted("Library: change type");
  ImGui::SetNextItemWidth(-1);
  gui.libraryProbe = {};
  ImGui::InputTextWithHint("##librarysearch", "search: robin 600, alphaspot...", s.text, sizeof s.text);
  {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    gui.libraryProbe.search = {a.x, a.y, b.x - a.x, b.y - a.y};
  }
  if (s.shownFor != s.text) {
    if (!s.index) s.index = indexLibrary(libraryFolders({}), defaultLibraryCache());
    s.hits = s.text[0] ? searchLibrary(*s.index, s.text) : std::vector<const LibraryEntry*>{};
    if (s.hits.size() > 200) s.hits.resize(200);
    s.shownFor = s.text;
    s.picked = -1;
    s.mode = 0;
  }
  // Five rows at most: the picked hit's facts need the room below.
  const float hitsH = std::min(ImGui::GetContentRegionAvail().y * 0.35f, 5.5f * ImGui::GetTextLineHeightWithSpacing());
  ImGui::BeginChild("library hits", ImVec2(0, hitsH), true);
  for (size_t k = 0; k < s.hits.size(); ++k) {
    const LibraryEntry& e = *s.hits[k];
    const std::string row = e.title() + "  (" + e.type + ")##" + e.file;
    if (ImGui::Selectable(row.c_str(), s.picked == static_cast<int>(k))) {
      s.picked = static_cast<int>(k);
      s.mode = 0;
    }
    if (k == 0) {
      const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
      gui.libraryProbe.firstHit = {a.x, a.y, b.x - a.x, b.y - a.y};
    }
  }
  ImGui::EndChild();
  gui.libraryProbe.hits = static_cast<int>(s.hits.size());
  if (s.picked < 0 || static_cast<size_t>(s.picked) >= s.hits.size()) return;
  const LibraryEntry& e = *s.hits[static_cast<size_t>(s.picked)];
  readPickedFacts(s, e);
  if (e.modes.empty()) {
    drawPickedFacts(s);
    return;
  }
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
  const bool change = ImGui::Button(button.c_str());
  {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    gui.libraryProbe.change = {a.x, a.y, b.x - a.x, b.y - a.y};
  }
  if (change) {
    auto report = doc.changeFixtureType(doc.selection, e.file, e.modes[static_cast<size_t>(s.mode)].name);
    if (!report)
      gui.say(report.error().str(), true);
    else
      gui.say("Changed " + std::to_string(doc.selection.size()) + " fixtures to " + e.title() + "; " +
              std::to_string(report->lines.size()) + " values not carried over as they were" +
              (report->lines.empty() ? "" : " (" + report->lines.front() + (report->lines.size() > 1 ? "; ..." : "") + ")"));
  }
  if (doc.selection.empty()) ImGui::EndDisabled();
  // The beam's shape beside the button, the facts below: both fit the panel without scrolling.
  if (!s.facts.beamShape.empty()) {
    ImGui::SameLine(0.0f, 24.0f);
    drawBeamShape(s.facts.beamShape);
  }
  drawPickedFacts(s);
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

  // A third of the panel: the library search and the picked hit's facts below need the rest.
  ImGui::BeginChild("profiles", ImVec2(0, ImGui::GetContentRegionAvail().y * 0.3f), true);
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
