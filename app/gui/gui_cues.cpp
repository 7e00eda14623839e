// The cue list tab: transport (GO, BACK, GOTO and the running fade's progress), the cues (click
// picks one for editing, double-click GOTOs it), Record / Update / Delete, and the picked cue's
// number, label, fade, delay and follow. Every change is a command (undo).
#include <cstdio>
#include <map>
#include <set>

#include "app/gui/gui.h"
#include "shows/frame/live_session.h"

namespace haze {

namespace {

std::string listName(const Gui& gui) { return gui.doc->cueList() ? gui.doc->cueList()->name : ""; }

}  // namespace

void recordCueFromProgrammer(Gui& gui) {
  if (gui.doc->programmer().values.empty()) {
    gui.say("the programmer is empty: set attributes (or focus fixtures) before recording", true);
    return;
  }
  auto number = gui.doc->recordCue();
  if (!number) {
    gui.say(number.error().str(), true);
    return;
  }
  if (auto at = findCue(*gui.doc->cueList(), *number)) gui.cueCursor = *at;
  gui.say("recorded cue " + *number + " (only what changed); C clears the programmer");
}

void recordDmxLook(Gui& gui) {
  if (!gui.live) {
    gui.say("Record DMX records what a console sends: open the show with --sacn or --artnet", true);
    return;
  }
  // As `haze live --record-cue`: only fixtures DMX drove, so a universe the console does not
  // send cannot wipe the tracked look; the commanded state, not where the heads have got to.
  const std::set<int> fixtures = gui.live->receiver().input().dmxFixtures();
  if (fixtures.empty()) {
    gui.say("no fixture has received DMX yet: nothing recorded", true);
    return;
  }
  const StageState& stage = gui.live->pass(0);
  std::map<int, CueValues> look;
  for (int id : fixtures)
    if (auto it = stage.find(id); it != stage.end()) look[id] = cueValuesOf(it->second);
  auto number = gui.doc->recordLook(std::move(look), "from DMX");
  if (!number) {
    gui.say(number.error().str(), true);
    return;
  }
  if (auto at = findCue(*gui.doc->cueList(), *number)) gui.cueCursor = *at;
  gui.say("recorded cue " + *number + " from the DMX of " + std::to_string(fixtures.size()) +
          " fixtures (only what changed)");
}

void updateCursorCue(Gui& gui) {
  const CueList* list = gui.doc->cueList();
  if (!list || !gui.cueCursor || *gui.cueCursor >= list->cues.size()) {
    gui.say("pick a cue in the list to update", true);
    return;
  }
  const std::string number = list->cues[*gui.cueCursor].number;
  gui.report(gui.doc->run(updateCue(listName(gui), number)), "updated cue " + number);
}

void drawCuesTab(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  const CueList* list = doc.cueList();
  const double now = gui.nowS;

  if (ImGui::Button("GO")) doc.go(now);
  ImGui::SameLine();
  if (ImGui::Button("BACK")) doc.back(now);
  ImGui::SameLine();
  if (ImGui::Button("GOTO") && gui.cueCursor) doc.gotoCue(*gui.cueCursor, now);
  // The show's default fade (the command line's `default fade S`): what Record gives a new cue.
  ImGui::SameLine();
  ImGui::TextDisabled("new cues: fade %.1f s", doc.show().defaultFadeS);
  // Progress of the fade into the cue on stage: the delay shows as 0.
  const auto current = doc.currentCue();
  const double p = doc.fadeProgress(now);
  char overlay[160] = "no cue on stage";
  if (list && current && *current < list->cues.size()) {
    const Cue& c = list->cues[*current];
    if (p < 0.0) std::snprintf(overlay, sizeof(overlay), "%s %s: delay", c.number.c_str(), c.label.c_str());
    else if (p < 1.0) std::snprintf(overlay, sizeof(overlay), "%s %s: %.0f %%", c.number.c_str(), c.label.c_str(), p * 100.0);
    else std::snprintf(overlay, sizeof(overlay), "%s %s", c.number.c_str(), c.label.c_str());
  }
  ImGui::ProgressBar(static_cast<float>(p < 0.0 ? 0.0 : p), ImVec2(-1.0f, 0.0f), overlay);

  const float editH = ImGui::GetFrameHeightWithSpacing() * 6.5f;
  ImGui::BeginChild("cuelist", ImVec2(0, std::max(ImGui::GetContentRegionAvail().y - editH, 60.0f)), true);
  if (!list || list->cues.empty()) ImGui::TextWrapped("No cues yet. Set fixtures in the inspector, then Record (Ctrl+R).");
  if (list) {
    for (size_t i = 0; i < list->cues.size(); ++i) {
      const Cue& c = list->cues[i];
      char row[160];
      std::snprintf(row, sizeof(row), "%s %-5s %s##cue%zu", current && *current == i ? ">" : " ", c.number.c_str(),
                    c.label.c_str(), i);
      if (ImGui::Selectable(row, gui.cueCursor && *gui.cueCursor == i, ImGuiSelectableFlags_AllowDoubleClick)) {
        gui.cueCursor = i;
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) doc.gotoCue(i, now);
      }
    }
  }
  ImGui::EndChild();

  if (ImGui::Button("Record")) recordCueFromProgrammer(gui);
  ImGui::SameLine();
  if (gui.live) {
    if (ImGui::Button("Rec DMX")) recordDmxLook(gui);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Record what the console sends as a new cue (Ctrl+Shift+R)");
    ImGui::SameLine();
  }
  const bool picked = list && gui.cueCursor && *gui.cueCursor < list->cues.size();
  if (!picked) ImGui::BeginDisabled();
  if (ImGui::Button("Update")) updateCursorCue(gui);
  ImGui::SameLine();
  if (ImGui::Button("Delete")) {
    const std::string number = list->cues[*gui.cueCursor].number;
    gui.report(doc.run(deleteCue(listName(gui), number)), "deleted cue " + number);
    gui.cueCursor.reset();
  }
  if (!picked) {
    ImGui::EndDisabled();
    ImGui::TextDisabled("Pick a cue to edit it.");
    return;
  }
  list = doc.cueList();
  if (!list || !gui.cueCursor || *gui.cueCursor >= list->cues.size()) return;
  const Cue& cue = list->cues[*gui.cueCursor];
  const std::string number = cue.number;

  // Text fields edit a copy and commit when the field is left (one undo step per change).
  static char numberField[32], labelField[128];
  static size_t fieldsFor = static_cast<size_t>(-1);
  static std::string fieldsNumber;
  if (fieldsFor != *gui.cueCursor || fieldsNumber != number || !ImGui::IsAnyItemActive()) {
    std::snprintf(numberField, sizeof(numberField), "%s", cue.number.c_str());
    std::snprintf(labelField, sizeof(labelField), "%s", cue.label.c_str());
    fieldsFor = *gui.cueCursor;
    fieldsNumber = number;
  }
  ImGui::SetNextItemWidth(70);
  ImGui::InputText("Number", numberField, sizeof(numberField), ImGuiInputTextFlags_CharsDecimal);
  if (ImGui::IsItemDeactivatedAfterEdit() && number != numberField) {
    Status s = doc.run(renumberCue(listName(gui), number, numberField));
    gui.report(s, "cue " + number + " is now cue " + numberField);
    if (s) {
      if (auto at = findCue(*doc.cueList(), numberField)) gui.cueCursor = *at;
    }
    return;
  }
  ImGui::InputText("Label", labelField, sizeof(labelField));
  if (ImGui::IsItemDeactivatedAfterEdit() && cue.label != labelField)
    gui.report(doc.run(labelCue(listName(gui), number, labelField)), "labelled cue " + number);

  CueTimes t{cue.fadeS, cue.delayS, cue.followS};
  float fade = static_cast<float>(t.fadeS), delay = static_cast<float>(t.delayS);
  float follow = static_cast<float>(t.followS.value_or(0.0));
  bool hasFollow = t.followS.has_value();
  bool changed = false;
  ImGui::SetNextItemWidth(90);
  changed |= ImGui::DragFloat("Fade s", &fade, 0.05f, 0.0f, 600.0f, "%.1f");
  ImGuiID item = ImGui::GetItemID();
  ImGui::SetNextItemWidth(90);
  if (ImGui::DragFloat("Delay s", &delay, 0.05f, 0.0f, 600.0f, "%.1f")) changed = true, item = ImGui::GetItemID();
  if (ImGui::Checkbox("Follow", &hasFollow)) changed = true, item = ImGui::GetItemID();
  if (hasFollow) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    if (ImGui::DragFloat("s##follow", &follow, 0.05f, 0.0f, 600.0f, "%.1f")) changed = true, item = ImGui::GetItemID();
  }
  if (changed) {
    t.fadeS = std::max(fade, 0.0f);
    t.delayS = std::max(delay, 0.0f);
    t.followS = hasFollow ? std::optional<double>(std::max(follow, 0.0f)) : std::nullopt;
    Status s = doc.run(setCueTimes(listName(gui), number, t), gui.mergeFor(item));
    if (!s) gui.say(s.error().str(), true);
  }
}

}  // namespace haze
