// The atmosphere tab: scattering, absorption, phase function (and g for Henyey-Greenstein),
// ambient light, soft or hard shadows and the sun (docs/physics.md), each a setAtmosphere command (a drag is one
// undo step); the
// density field (docs/shows.md, "Density"): base, ground fog, air flow and hazers; and the
// ambient light (docs/physics.md), each a setAtmosphere command (a drag is one undo step); the
// density field (docs/shows.md, "Density"): base, ground fog, air flow and hazers; visible dust
// (docs/shows.md, "Particles"); and the
// view's render quality, exposure and bloom, which are not part of the show.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <glm/common.hpp>

#include "app/gui/gui.h"
#include "shows/frame/live_session.h"

namespace haze {

namespace {

// Whether any widget of a group changed this frame, and which changed last: Gui::mergeFor
// takes its id to make a drag one undo step.
struct EditTracker {
  bool changed = false;
  ImGuiID item = 0;
  void operator()(bool edited) {
    if (!edited) return;
    changed = true;
    item = ImGui::GetItemID();
  }
};

// Every change of the density re-runs its simulation over the warm-up, so its widgets edit a
// draft and the show takes the draft when the widget is let go: one undo step and one
// simulation per change, not one per frame of a drag. One window, so one draft.
void drawDensity(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  AtmosphereDef a = doc.show().atmosphere;
  static std::optional<DensitySpec> draft;
  static bool editing = false;
  auto commit = [&](const std::optional<DensitySpec>& spec) {
    a.density = spec;
    Status s = doc.run(setAtmosphere(a), false);
    if (!s) gui.say(s.error().str(), true);
    editing = false;
  };
  bool on = a.density.has_value();
  if (ImGui::Checkbox("Density field", &on)) {
    // A new field: even haze at the scattering above, which hazers and fog then add to.
    commit(on ? std::optional<DensitySpec>(DensitySpec{}) : std::nullopt);
    return;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Haze that varies in space: ground fog, hazers and a room air flow (docs/shows.md)");
  if (!a.density) return;
  if (!editing || !draft) draft = *a.density;
  DensitySpec& d = *draft;
  bool active = false, done = false;
  auto edited = [&](bool) {
    active = active || ImGui::IsItemActive();
    done = done || ImGui::IsItemDeactivatedAfterEdit();
  };
  ImGui::SetNextItemWidth(110);
  edited(ImGui::DragFloat("Base density", &d.base, 0.01f, 0.0f, 20.0f, "%.2f"));
  bool fog = d.fog.has_value();
  if (ImGui::Checkbox("Ground fog", &fog)) {
    d.fog = fog ? std::optional<FogLayerSpec>(FogLayerSpec{.density = 5.0f}) : std::nullopt;
    done = true;
  }
  if (d.fog) {
    ImGui::SetNextItemWidth(110);
    edited(ImGui::DragFloat("Fog density", &d.fog->density, 0.05f, 0.0f, 100.0f, "%.2f"));
    ImGui::SetNextItemWidth(110);
    edited(ImGui::DragFloat("Fog top m", &d.fog->heightM, 0.01f, 0.0f, 20.0f, "%.2f"));
    ImGui::SetNextItemWidth(110);
    edited(ImGui::DragFloat("Fog falloff m", &d.fog->falloffM, 0.01f, 0.01f, 10.0f, "%.2f"));
  }
  ImGui::SetNextItemWidth(160);
  edited(ImGui::DragFloat3("Air flow m/s", &d.airFlowMps.x, 0.01f, -5.0f, 5.0f, "%.2f"));
  ImGui::SetNextItemWidth(110);
  edited(ImGui::DragFloat("Mixing m2/s", &d.mixingM2ps, 0.005f, 0.0f, 5.0f, "%.3f"));
  float warmup = static_cast<float>(d.warmupS);
  ImGui::SetNextItemWidth(110);
  edited(ImGui::DragFloat("Warm-up s", &warmup, 1.0f, 0.0f, 600.0f, "%.0f"));
  d.warmupS = warmup;
  if (ImGui::Checkbox("Held still", &d.still)) done = true;
  ImGui::SetNextItemWidth(160);
  edited(ImGui::DragInt3("Grid cells", d.grid, 0.5f, 4, 128));
  for (size_t i = 0; i < d.hazers.size(); ++i) {
    HazerSpec& h = d.hazers[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::Text("Hazer %zu", i + 1);
    ImGui::SameLine();
    const bool remove = ImGui::SmallButton("Remove");
    ImGui::SetNextItemWidth(160);
    edited(ImGui::DragFloat3("Position m", &h.positionM.x, 0.02f, -1000.0f, 1000.0f, "%.2f"));
    ImGui::SetNextItemWidth(160);
    edited(ImGui::DragFloat3("Blows to", &h.direction.x, 0.01f, -1.0f, 1.0f, "%.2f"));
    ImGui::SetNextItemWidth(110);
    edited(ImGui::DragFloat("Output m3/s", &h.output, 0.05f, 0.0f, 100.0f, "%.2f"));
    ImGui::SetNextItemWidth(110);
    edited(ImGui::DragFloat("Spread deg", &h.spreadDeg, 0.5f, 1.0f, 120.0f, "%.0f"));
    ImGui::SetNextItemWidth(110);
    edited(ImGui::DragFloat("Fan m/s", &h.speedMps, 0.05f, 0.0f, 20.0f, "%.2f"));
    ImGui::PopID();
    if (remove) {
      d.hazers.erase(d.hazers.begin() + static_cast<std::ptrdiff_t>(i));
      done = true;
      break;
    }
  }
  if (ImGui::Button("Add hazer")) {
    // In the stage-left wing of the venue's box, a metre up, blowing across it.
    const Venue& v = doc.venue();
    HazerSpec h;
    h.positionM = {v.boundsMin.x + 0.1f * (v.boundsMax.x - v.boundsMin.x), v.boundsMin.y + 1.0f,
                   0.5f * (v.boundsMin.z + v.boundsMax.z)};
    h.direction = {1.0f, 0.0f, 0.0f};
    d.hazers.push_back(h);
    done = true;
  }
  ImGui::TextWrapped("The window shows the field after its warm-up (%s).",
                     d.still ? "held still" : "as at GO; renders and video let it drift");
  editing = active;
  if (done) {
    d.base = std::max(d.base, 0.0f);
    for (int& n : d.grid) n = std::clamp(n, 4, 128);
    for (HazerSpec& h : d.hazers)
      if (h.direction == glm::vec3(0.0f)) h.direction = {1.0f, 0.0f, 0.0f};
    commit(d);
  }
}

// The field the window shows, as a horizontal slice at a chosen height seen from above (+X to
// the right, +Z down), grey from 0 to the slice's own maximum. At the end of
// the tab, so that the rows above keep their places.
void drawFieldSlice(Gui& gui) {
  const std::shared_ptr<const DensityField>& field = gui.atmosphere.last();
  if (!gui.doc->show().atmosphere.density || !field || field->empty()) return;
  ImGui::Separator();
  static float heightM = 1.0f;
  heightM = std::clamp(heightM, field->minM.y, field->maxM.y);
  ImGui::SetNextItemWidth(110);
  ImGui::SliderFloat("Slice height", &heightM, field->minM.y, field->maxM.y, "%.2f m");
  const std::vector<float> slice = field->horizontalSlice(heightM);
  float top = 0.0f;
  for (float v : slice) top = std::max(top, v);
  ImGui::Text("D at %.2f m: up to %.2f (whole field %.2f)", heightM, top, field->maxValue());
  const float side = std::min(ImGui::GetContentRegionAvail().x, 256.0f);
  const float cell = side / static_cast<float>(std::max(field->nx, field->nz));
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (int z = 0; z < field->nz; ++z)
    for (int x = 0; x < field->nx; ++x) {
      const float v = top > 0.0f ? slice[static_cast<size_t>(z) * static_cast<size_t>(field->nx) + static_cast<size_t>(x)] / top : 0.0f;
      const int grey = static_cast<int>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
      const ImVec2 a(at.x + static_cast<float>(x) * cell, at.y + static_cast<float>(z) * cell);
      draw->AddRectFilled(a, ImVec2(a.x + cell + 0.5f, a.y + cell + 0.5f), IM_COL32(grey, grey, grey, 255));
    }
  ImGui::Dummy(ImVec2(cell * static_cast<float>(field->nx), cell * static_cast<float>(field->nz)));
}

// The sun (docs/shows.md, "The sun"), below the density field so that the rows above keep
// their places: switching it on for the first time adds the default sun.
void drawSun(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  AtmosphereDef a = doc.show().atmosphere;
  EditTracker track;
  bool sunOn = a.sun && a.sun->enabled;
  if (ImGui::Checkbox("Sun", &sunOn)) {
    if (!a.sun) a.sun = SunDef{};
    a.sun->enabled = sunOn;
    track(true);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Daylight: a directional light that enters the venue through its openings (docs/shows.md)");
  if (a.sun && a.sun->enabled) {
    ImGui::SetNextItemWidth(110);
    track(ImGui::DragFloat("Azimuth deg", &a.sun->azimuthDeg, 0.5f, -360.0f, 360.0f, "%.1f"));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("From north (-Z) towards east (+X), seen from above");
    ImGui::SetNextItemWidth(110);
    track(ImGui::DragFloat("Elevation deg", &a.sun->elevationDeg, 0.25f, -90.0f, 90.0f, "%.1f"));
    ImGui::SetNextItemWidth(110);
    track(ImGui::DragFloat("Sun lux", &a.sun->illuminanceLux, 100.0f, 0.0f, 1e6f, "%.0f"));
    ImGui::SetNextItemWidth(160);
    track(ImGui::ColorEdit3("Sun colour", &a.sun->color.x, ImGuiColorEditFlags_Float));
  }
  if (!track.changed) return;
  a.sun->azimuthDeg = std::clamp(a.sun->azimuthDeg, -360.0f, 360.0f);
  a.sun->elevationDeg = std::clamp(a.sun->elevationDeg, -90.0f, 90.0f);
  a.sun->illuminanceLux = std::clamp(a.sun->illuminanceLux, 0.0f, 1e6f);
  a.sun->color = glm::clamp(a.sun->color, glm::vec3(0.0f), glm::vec3(1.0f));
  Status s = doc.run(setAtmosphere(a), gui.mergeFor(track.item));
  if (!s) gui.say(s.error().str(), true);
}

// Visible dust in the beams (docs/shows.md, "Particles"): part of the show, a display option
// (PFMs have none unless asked). A drag is one undo step, as for the atmosphere above.
void drawParticles(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  AtmosphereDef a = doc.show().atmosphere;
  ParticleSettings ps = a.particles.value_or(ParticleSettings{});
  EditTracker track;
  track(ImGui::Checkbox("Particles", &ps.enabled));
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Visible dust where the beams light it, drifting with the air: display only (docs/rendering.md)");
  if (ps.enabled) {
    ImGui::SetNextItemWidth(110);
    track(ImGui::DragFloat("Dust per m^3", &ps.densityPerM3, 1.0f, 0.0f, kMaxParticleDensityPerM3, "%.0f"));
    ImGui::SetNextItemWidth(110);
    track(ImGui::DragFloat("Dust size um", &ps.sizeUm, 0.5f, 1.0f, 1000.0f, "%.0f"));
    ImGui::SetNextItemWidth(110);
    track(ImGui::DragFloat("Dust brightness", &ps.brightness, 50.0f, 0.0f, 1e7f, "%.0f"));
  }
  if (track.changed) {
    ps.densityPerM3 = std::clamp(ps.densityPerM3, 0.0f, kMaxParticleDensityPerM3);
    ps.sizeUm = std::clamp(ps.sizeUm, 1.0f, 1000.0f);
    ps.brightness = std::clamp(ps.brightness, 0.0f, 1e7f);
    a.particles = ps;
    Status s = doc.run(setAtmosphere(a), gui.mergeFor(track.item));
    if (!s) gui.say(s.error().str(), true);
  }
}

}  // namespace

void setExposureMode(Gui& gui, ExposureMode mode) {
  gui.lockExposureWhenMetered = false;  // the designer's choice overrides a lock remembered from the last run
  if (mode == gui.exposureMode) return;
  // Switching keeps the picture: the EV on screen becomes the manual (locked) EV, or the offset
  // from the meter, so locking in the middle of a look holds exactly that look.
  const float shown = std::isfinite(gui.shownEv) ? gui.shownEv : exposureEvFor({gui.exposureMode, gui.exposureEv}, gui.meteredEv);
  gui.exposureEv = mode == ExposureMode::Manual ? shown : shown - gui.meteredEv;
  gui.exposureMode = mode;
}

void drawAtmosphereTab(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  AtmosphereDef a = doc.show().atmosphere;
  EditTracker track;
  ImGui::TextUnformatted("Atmosphere");
  ImGui::SetNextItemWidth(110);
  track(ImGui::DragFloat("Scattering 1/m", &a.scattering, 0.0005f, 0.0f, 1.0f, "%.4f"));
  ImGui::SetNextItemWidth(110);
  track(ImGui::DragFloat("Absorption 1/m", &a.absorption, 0.0005f, 0.0f, 1.0f, "%.4f"));
  ImGui::SetNextItemWidth(110);
  if (ImGui::BeginCombo("Phase", a.phase.c_str())) {
    for (const char* p : {"hazy", "isotropic", "hg"})
      if (ImGui::Selectable(p, a.phase == p)) {
        a.phase = p;
        track(true);
      }
    ImGui::EndCombo();
  }
  if (a.phase == "hg") {
    ImGui::SetNextItemWidth(110);
    track(ImGui::SliderFloat("g", &a.g, -0.95f, 0.95f, "%.2f"));
  }
  ImGui::SetNextItemWidth(160);
  track(ImGui::DragFloat3("Ambient", &a.ambient.x, 0.005f, 0.0f, 10.0f, "%.2f"));
  if (track.changed) {
    a.scattering = std::max(a.scattering, 0.0f);
    a.absorption = std::max(a.absorption, 0.0f);
    Status s = doc.run(setAtmosphere(a), gui.mergeFor(track.item));
    if (!s) gui.say(s.error().str(), true);
  }
  drawDensity(gui);
  drawSun(gui);
  // Soft: shadows softened by each lens disc; hard: point lights (docs/physics.md, "Soft
  // shadows"). Below the density and the sun, so the rows above keep their places.
  AtmosphereDef withShadows = doc.show().atmosphere;
  int shadows = withShadows.softShadows ? 0 : 1;
  const char* shadowKinds[] = {"soft", "hard"};
  ImGui::SetNextItemWidth(110);
  if (ImGui::Combo("Shadows", &shadows, shadowKinds, 2)) {
    withShadows.softShadows = shadows == 0;
    Status s = doc.run(setAtmosphere(withShadows), false);
    if (!s) gui.say(s.error().str(), true);
  }
  drawParticles(gui);

  ImGui::Separator();
  ImGui::TextUnformatted("View (not saved in the show)");
  const char* names[] = {"Draft", "Default", "High"};
  int q = std::min(static_cast<int>(gui.quality), 2);
  ImGui::SetNextItemWidth(110);
  if (ImGui::Combo("Quality", &q, names, 3)) gui.quality = static_cast<Quality>(q);
  int mode = gui.exposureMode == ExposureMode::Auto ? 0 : 1;
  const char* modes[] = {"Auto", "Manual"};
  ImGui::SetNextItemWidth(110);
  if (ImGui::Combo("Exposure", &mode, modes, 2)) setExposureMode(gui, mode == 1 ? ExposureMode::Manual : ExposureMode::Auto);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Auto meters the image like a camera (docs/rendering.md); manual: EV 0 maps 50 cd/m^2 to 1");
  ImGui::SetNextItemWidth(110);
  const bool isAuto = gui.exposureMode == ExposureMode::Auto;
  ImGui::SliderFloat(isAuto ? "Offset EV" : "Exposure EV", &gui.exposureEv, isAuto ? -6.0f : -16.0f, 6.0f, "%.1f");
  if (isAuto) ImGui::Text("Metered %.1f EV, shown %.1f EV", gui.meteredEv, std::isfinite(gui.shownEv) ? gui.shownEv : 0.0f);
  else ImGui::TextUnformatted("Locked: fades and cues keep this EV (View > Lock exposure, E)");
  ImGui::SetNextItemWidth(110);
  ImGui::SliderFloat("Bloom", &gui.bloom, 0.0f, 0.3f, "%.2f");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Lens glare around bright beams: display only, not in PFMs");
  ImGui::TextWrapped("While the view or the stage moves it draws at draft quality; when still it refines "
                     "(%d frames so far).", gui.stillFrames);

  if (gui.live) {
    ImGui::Separator();
    ImGui::Text("Live DMX on %s: %.0f packets/s", gui.liveBind.c_str(), gui.live->receiver().packetRate());
    const auto sources = gui.live->receiver().sources();
    if (sources.empty()) ImGui::TextUnformatted("no source: holding the last levels");
    for (const DmxSourceInfo& src : sources)
      ImGui::Text("%s %s  universe %d  priority %d%s", src.winning ? "*" : " ", src.name.c_str(), src.universe,
                  src.priority, src.perSlotPriority ? " (per slot)" : "");
    // Sources that announce themselves (sACN universe discovery), sending to haze or not.
    for (const DiscoveredSource& d : gui.live->receiver().input().discovered()) {
      std::string list;
      int shown = 0;
      for (int u : d.universes) {
        if (shown++ == 32) {
          list += " ... (" + std::to_string(d.universes.size()) + ")";
          break;
        }
        list += (list.empty() ? "" : ",") + std::to_string(u);
      }
      ImGui::TextWrapped("discovered %s: universes %s", d.name.c_str(), list.empty() ? "none" : list.c_str());
    }
  }
  drawFieldSlice(gui);
}

}  // namespace haze
