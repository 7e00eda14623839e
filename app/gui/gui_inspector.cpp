// The inspector for the selection (one or many fixtures): name, position and mounting rotation
// (one fixture), pan and tilt with focus to point, and the attributes: intensity, colour (picker
// and the profile's colour wheel, the second colour wheel, CTO), zoom, gobo, gobo rotation and
// spin (both gobo wheels), iris, shutter, and frost, focus (the lens), prism and blades where the
// profile has them.
// Shown values are the first selected fixture's on stage; a change sets that attribute of every
// selected fixture in the programmer (a drag is one undo step). "*" marks attributes the
// programmer holds.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include "app/gui/gui.h"
#include "fixtures/color.h"

namespace haze {

namespace {

const char* mark(const CueValues* p, bool held) { return p && held ? "*" : " "; }

// Beam optics beyond the gobo (docs/show-format.md): the shutter for every fixture, frost, prism
// and blades where the profile has them.
void inspectOptics(const Profile& p, const Attributes& a, const CueValues* prog, CueValues& set, ImGuiID& item) {
  char label[32];
  auto track = [&](bool changed) {
    if (changed) item = ImGui::GetItemID();
    return changed;
  };
  const char* kModes[] = {"open", "closed", "strobe", "pulse", "pulse_open", "pulse_close", "random"};
  int mode = static_cast<int>(a.shutter.mode);
  std::snprintf(label, sizeof(label), "Shutter%s", mark(prog, prog && prog->shutter));
  Shutter shutter = a.shutter;
  bool changed = track(ImGui::Combo(label, &mode, kModes, 7));
  if (changed) {
    shutter.mode = static_cast<ShutterMode>(mode);
    if (shutter.strobing() && shutter.rateHz <= 0.0f) shutter.rateHz = 5.0f;
  }
  if (shutter.strobing()) {
    changed |= track(ImGui::SliderFloat("Strobe", &shutter.rateHz, kMinStrobeHz, 30.0f, "%.2f Hz"));
    changed |= track(ImGui::SliderFloat("Duty", &shutter.duty, 0.01f, 1.0f, "%.2f"));
  }
  if (changed) set.shutter = shutter;
  if (p.hasFrost) {
    float frost = a.frost;
    std::snprintf(label, sizeof(label), "Frost%s", mark(prog, prog && prog->frost));
    if (track(ImGui::SliderFloat(label, &frost, 0.0f, 1.0f, "%.2f"))) set.frost = frost;
  }
  // The lens's focus (docs/physics.md, "Focus"); the F key's aiming is another thing.
  if (p.hasGateFocus) {
    float focus = a.gateFocus;
    std::snprintf(label, sizeof(label), "Focus%s", mark(prog, prog && prog->gateFocus));
    if (track(ImGui::SliderFloat(label, &focus, 0.0f, 1.0f, "%.2f"))) set.gateFocus = focus;
  }
  if (!p.prisms.empty()) {
    std::snprintf(label, sizeof(label), "Prism%s", mark(prog, prog && prog->prism));
    if (ImGui::BeginCombo(label, a.prism.c_str())) {
      if (ImGui::Selectable("Open", a.prism == "Open")) {
        set.prism = "Open";
        item = ImGui::GetItemID();
      }
      for (const PrismSpec& pr : p.prisms)
        if (ImGui::Selectable(pr.name.c_str(), pr.name == a.prism)) {
          set.prism = pr.name;
          item = ImGui::GetItemID();
        }
      ImGui::EndCombo();
    }
    float rotation = a.prismRotationDeg;
    std::snprintf(label, sizeof(label), "Prism rot%s", mark(prog, prog && prog->prismRotationDeg));
    if (track(ImGui::DragFloat(label, &rotation, 0.5f, -3600.0f, 3600.0f, "%.1f deg"))) set.prismRotationDeg = rotation;
    float spin = a.prismSpinDegS;
    std::snprintf(label, sizeof(label), "Prism spin%s", mark(prog, prog && prog->prismSpinDegS));
    if (track(ImGui::DragFloat(label, &spin, 0.5f, -720.0f, 720.0f, "%.1f deg/s"))) set.prismSpinDegS = spin;
  }
  if (p.hasBlades) {
    ImGui::Text("Blades%s", mark(prog, prog && (prog->blades || prog->bladeRotationDeg)));
    BladeInsertions blades = a.blades;
    bool moved = false;
    for (int k = 0; k < 4; ++k) {
      std::snprintf(label, sizeof(label), "Blade %d", k + 1);
      moved |= track(ImGui::SliderFloat2(label, &blades[static_cast<size_t>(k)].x, 0.0f, 1.0f, "%.2f"));
    }
    if (moved) set.blades = blades;
    float rotation = a.bladeRotationDeg;
    if (track(ImGui::DragFloat("Blade rot", &rotation, 0.25f, -45.0f, 45.0f, "%.1f deg"))) set.bladeRotationDeg = rotation;
  }
}

}  // namespace

void drawInspector(Gui& gui) {
  const Rect& r = gui.layout.right;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin("Inspector", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  ShowDocument& doc = *gui.doc;
  if (doc.selection.empty()) {
    ImGui::TextWrapped("Nothing selected. Click a fixture (or its beam) in the view, or pick fixtures in the "
                       "Fixtures tab; Ctrl toggles, Shift adds.");
    ImGui::Separator();
    ImGui::Text("Programmer: %zu fixture(s)", doc.programmer().values.size());
    ImGui::End();
    return;
  }
  const int id = doc.selection.front();
  const FixtureDef* f = doc.show().findFixture(id);
  const auto prof = f ? doc.profiles().find(f->profile) : doc.profiles().end();
  if (!f || prof == doc.profiles().end() || !prof->second) {
    ImGui::TextUnformatted("The selected fixture has no loaded profile.");
    ImGui::End();
    return;
  }
  const Profile& p = *prof->second;
  const bool single = doc.selection.size() == 1;
  if (single) ImGui::Text("%d  %s", f->id, f->name.c_str());
  else ImGui::Text("%zu fixtures (first: %d %s)", doc.selection.size(), f->id, f->name.c_str());
  ImGui::TextDisabled("%s", p.name.c_str());

  if (single) {
    static char nameField[128];
    static int nameFor = 0;
    if (nameFor != id || !ImGui::IsAnyItemActive()) {
      std::snprintf(nameField, sizeof(nameField), "%s", f->name.c_str());
      nameFor = id;
    }
    ImGui::InputText("Name", nameField, sizeof(nameField));
    if (ImGui::IsItemDeactivatedAfterEdit() && f->name != nameField)
      gui.report(doc.run(renameFixture(id, nameField)), "renamed fixture " + std::to_string(id));
    glm::vec3 pos = f->position, rot = f->rotationDeg;
    if (ImGui::DragFloat3("Pos m", &pos.x, 0.01f, -1000.0f, 1000.0f, "%.2f")) {
      Status s = doc.run(moveFixture(id, pos), gui.mergeFor(ImGui::GetItemID()));
      if (!s) gui.say(s.error().str(), true);
    }
    if (ImGui::DragFloat3("Rot deg", &rot.x, 0.5f, -360.0f, 360.0f, "%.1f")) {
      Status s = doc.run(rotateFixture(id, rot), gui.mergeFor(ImGui::GetItemID()));
      if (!s) gui.say(s.error().str(), true);
    }
    f = doc.show().findFixture(id);  // the commands above may have moved the vector
    if (!f) {
      ImGui::End();
      return;
    }
  }

  const auto st = gui.stage.find(id);
  Attributes a = st != gui.stage.end() ? st->second : Attributes{};
  const auto progIt = doc.programmer().values.find(id);
  const CueValues* prog = progIt != doc.programmer().values.end() ? &progIt->second : nullptr;
  CueValues set;
  ImGuiID item = 0;
  auto track = [&](bool changed) {
    if (changed) item = ImGui::GetItemID();
    return changed;
  };

  ImGui::Separator();
  ImGui::Text("Aim%s", mark(prog, prog && (prog->panDeg || prog->tiltDeg)));
  if (track(ImGui::DragFloat("Pan", &a.panDeg, 0.25f, p.panDeg.min, p.panDeg.max, "%.1f deg"))) set.panDeg = a.panDeg;
  if (track(ImGui::DragFloat("Tilt", &a.tiltDeg, 0.25f, p.tiltDeg.min, p.tiltDeg.max, "%.1f deg"))) set.tiltDeg = a.tiltDeg;
  if (ImGui::Button(gui.tool == Tool::Focus ? "Focus: click a point..." : "Focus to point (F)")) {
    gui.tool = Tool::Focus;
    gui.say("click the point the selected fixture(s) should aim at");
  }

  ImGui::Separator();
  float percent = a.intensity * 100.0f;
  char label[32];
  std::snprintf(label, sizeof(label), "Intensity%s", mark(prog, prog && prog->intensity));
  if (track(ImGui::SliderFloat(label, &percent, 0.0f, 100.0f, "%.0f %%"))) set.intensity = std::clamp(percent / 100.0f, 0.0f, 1.0f);
  glm::vec3 color = a.color;
  std::snprintf(label, sizeof(label), "Colour%s", mark(prog, prog && prog->color));
  if (track(ImGui::ColorEdit3(label, &color.x, ImGuiColorEditFlags_Float))) set.color = glm::clamp(color, 0.0f, 1.0f);
  if (!p.colorWheels.empty()) {
    for (const WheelSlot& slot : p.colorWheels.front().slots) {
      if (!slot.color) continue;
      const glm::vec3 c = *slot.color;
      if (ImGui::ColorButton(slot.name.c_str(), ImVec4(c.x, c.y, c.z, 1.0f))) {
        set.color = c;
        item = ImGui::GetItemID();
      }
      if (ImGui::GetContentRegionAvail().x > 30) ImGui::SameLine();
    }
    ImGui::NewLine();
  }
  if (p.colorWheels.size() > 1) {
    std::snprintf(label, sizeof(label), "Colour 2%s", mark(prog, prog && prog->color2));
    if (ImGui::BeginCombo(label, a.color2.c_str())) {
      if (ImGui::Selectable("Open", a.color2 == "Open")) {
        set.color2 = "Open";
        item = ImGui::GetItemID();
      }
      for (const WheelSlot& slot : p.colorWheels[1].slots)
        if (slot.name != "Open" && ImGui::Selectable(slot.name.c_str(), slot.name == a.color2)) {
          set.color2 = slot.name;
          item = ImGui::GetItemID();
        }
      ImGui::EndCombo();
    }
  }
  float cto = a.ctoMired;
  std::snprintf(label, sizeof(label), "CTO%s", mark(prog, prog && prog->ctoMired));
  if (track(ImGui::SliderFloat(label, &cto, -kMaxCtoMired, kMaxCtoMired, "%.0f mired"))) set.ctoMired = cto;
  if (p.zoomDeg.max > p.zoomDeg.min) {
    float zoom = a.zoomDeg.value_or(p.fieldAngleDeg);
    std::snprintf(label, sizeof(label), "Zoom%s", mark(prog, prog && prog->zoomDeg));
    if (track(ImGui::SliderFloat(label, &zoom, p.zoomDeg.min, p.zoomDeg.max, "%.1f deg"))) set.zoomDeg = zoom;
  }
  // One slot combo, rotation and spin per gobo wheel haze models (two).
  for (size_t w = 0; w < std::min<size_t>(p.goboWheels.size(), 2); ++w) {
    const bool first = w == 0;
    const std::string& slotNow = first ? a.gobo : a.gobo2;
    std::optional<std::string>& slotSet = first ? set.gobo : set.gobo2;
    std::snprintf(label, sizeof(label), "Gobo%s%s", first ? "" : " 2", mark(prog, prog && (first ? prog->gobo : prog->gobo2)));
    if (ImGui::BeginCombo(label, slotNow.c_str())) {
      for (const WheelSlot& slot : p.goboWheels[w].slots)
        if (ImGui::Selectable(slot.name.c_str(), slot.name == slotNow)) {
          slotSet = slot.name;
          item = ImGui::GetItemID();
        }
      ImGui::EndCombo();
    }
    float rotation = first ? a.goboRotationDeg : a.gobo2RotationDeg;
    std::snprintf(label, sizeof(label), "Gobo%s rot%s", first ? "" : " 2",
                  mark(prog, prog && (first ? prog->goboRotationDeg : prog->gobo2RotationDeg)));
    if (track(ImGui::DragFloat(label, &rotation, 0.5f, -3600.0f, 3600.0f, "%.1f deg")))
      (first ? set.goboRotationDeg : set.gobo2RotationDeg) = rotation;
    float spin = first ? a.goboSpinDegS : a.gobo2SpinDegS;
    std::snprintf(label, sizeof(label), "Gobo%s spin%s", first ? "" : " 2",
                  mark(prog, prog && (first ? prog->goboSpinDegS : prog->gobo2SpinDegS)));
    if (track(ImGui::DragFloat(label, &spin, 0.5f, -720.0f, 720.0f, "%.1f deg/s")))
      (first ? set.goboSpinDegS : set.gobo2SpinDegS) = spin;
  }
  // The animation wheel: its slot, the disc's angle and its spin (docs/physics.md, "Animation wheel").
  if (!p.animationWheels.empty()) {
    std::snprintf(label, sizeof(label), "Animation%s", mark(prog, prog && prog->animation));
    if (ImGui::BeginCombo(label, a.animation.c_str())) {
      for (const WheelSlot& slot : p.animationWheels[0].slots)
        if (ImGui::Selectable(slot.name.c_str(), slot.name == a.animation)) {
          set.animation = slot.name;
          item = ImGui::GetItemID();
        }
      ImGui::EndCombo();
    }
    float angle = a.animationRotationDeg;
    std::snprintf(label, sizeof(label), "Anim rot%s", mark(prog, prog && prog->animationRotationDeg));
    if (track(ImGui::DragFloat(label, &angle, 0.5f, -3600.0f, 3600.0f, "%.1f deg"))) set.animationRotationDeg = angle;
    float spin = a.animationSpinDegS;
    std::snprintf(label, sizeof(label), "Anim spin%s", mark(prog, prog && prog->animationSpinDegS));
    if (track(ImGui::DragFloat(label, &spin, 0.5f, -720.0f, 720.0f, "%.1f deg/s"))) set.animationSpinDegS = spin;
  }
  float iris = a.iris;
  std::snprintf(label, sizeof(label), "Iris%s", mark(prog, prog && prog->iris));
  if (track(ImGui::SliderFloat(label, &iris, 0.05f, 1.0f, "%.2f"))) set.iris = iris;
  inspectOptics(p, a, prog, set, item);

  if (set != CueValues{}) {
    Status s = doc.setSelectionValues(set, gui.mergeFor(item));
    if (!s) gui.say(s.error().str(), true);
  }
  ImGui::Separator();
  ImGui::Text("Programmer: %zu fixture(s)", doc.programmer().values.size());
  if (ImGui::Button("Record cue (Ctrl+R)")) recordCueFromProgrammer(gui);
  if (ImGui::Button("Clear programmer (C)") && !doc.programmer().values.empty())
    gui.report(doc.run(clearProgrammer()), "programmer cleared");
  ImGui::End();
}

}  // namespace haze
