// The atmosphere tab: scattering, absorption, phase function (and g for Henyey-Greenstein),
// ambient light (docs/physics.md), each a setAtmosphere command (a drag is one undo step); and the
// view's render quality, exposure and bloom, which are not part of the show.
#include <cmath>
#include <string>

#include "app/gui/gui.h"
#include "shows/dmx/udp_receiver.h"

namespace haze {

void drawAtmosphereTab(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  AtmosphereDef a = doc.show().atmosphere;
  bool changed = false;
  ImGuiID item = 0;
  auto track = [&](bool c) {
    if (c) {
      changed = true;
      item = ImGui::GetItemID();
    }
  };
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
        changed = true;
        item = ImGui::GetItemID();
      }
    ImGui::EndCombo();
  }
  if (a.phase == "hg") {
    ImGui::SetNextItemWidth(110);
    track(ImGui::SliderFloat("g", &a.g, -0.95f, 0.95f, "%.2f"));
  }
  ImGui::SetNextItemWidth(160);
  track(ImGui::DragFloat3("Ambient", &a.ambient.x, 0.005f, 0.0f, 10.0f, "%.2f"));
  if (changed) {
    a.scattering = std::max(a.scattering, 0.0f);
    a.absorption = std::max(a.absorption, 0.0f);
    Status s = doc.run(setAtmosphere(a), gui.mergeFor(item));
    if (!s) gui.say(s.error().str(), true);
  }

  ImGui::Separator();
  ImGui::TextUnformatted("View (not saved in the show)");
  const char* names[] = {"Draft", "Default", "High"};
  int q = std::min(static_cast<int>(gui.quality), 2);
  ImGui::SetNextItemWidth(110);
  if (ImGui::Combo("Quality", &q, names, 3)) gui.quality = static_cast<Quality>(q);
  int mode = gui.exposureMode == ExposureMode::Auto ? 0 : 1;
  const char* modes[] = {"Auto", "Manual"};
  ImGui::SetNextItemWidth(110);
  if (ImGui::Combo("Exposure", &mode, modes, 2)) {
    // Switching keeps the picture: the EV on screen becomes the manual EV, or the offset from the meter.
    const bool toManual = mode == 1;
    if (toManual != (gui.exposureMode == ExposureMode::Manual)) {
      const float shown = std::isfinite(gui.shownEv) ? gui.shownEv : gui.exposureEv;
      gui.exposureEv = toManual ? shown : shown - gui.meteredEv;
      gui.exposureMode = toManual ? ExposureMode::Manual : ExposureMode::Auto;
    }
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Auto meters the image like a camera (docs/rendering.md); manual: EV 0 maps 50 cd/m^2 to 1");
  ImGui::SetNextItemWidth(110);
  const bool isAuto = gui.exposureMode == ExposureMode::Auto;
  ImGui::SliderFloat(isAuto ? "Offset EV" : "Exposure EV", &gui.exposureEv, isAuto ? -6.0f : -16.0f, 6.0f, "%.1f");
  if (isAuto) ImGui::Text("Metered %.1f EV, shown %.1f EV", gui.meteredEv, std::isfinite(gui.shownEv) ? gui.shownEv : 0.0f);
  ImGui::SetNextItemWidth(110);
  ImGui::SliderFloat("Bloom", &gui.bloom, 0.0f, 0.3f, "%.2f");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Lens glare around bright beams: display only, not in PFMs");
  ImGui::TextWrapped("While the view or the stage moves it draws at draft quality; when still it refines "
                     "(%d frames so far).", gui.stillFrames);

  if (gui.live) {
    ImGui::Separator();
    ImGui::Text("Live DMX on %s: %.0f packets/s", gui.liveBind.c_str(), gui.live->packetRate());
    const auto sources = gui.live->sources();
    if (sources.empty()) ImGui::TextUnformatted("no source: holding the last levels");
    for (const DmxSourceInfo& src : sources)
      ImGui::Text("%s %s  universe %d  priority %d%s", src.winning ? "*" : " ", src.name.c_str(), src.universe,
                  src.priority, src.perSlotPriority ? " (per slot)" : "");
    // Sources that announce themselves (sACN universe discovery), sending to haze or not.
    for (const DiscoveredSource& d : gui.live->input().discovered()) {
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
}

}  // namespace haze
