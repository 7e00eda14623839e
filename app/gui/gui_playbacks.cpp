// The playback tab: one row per cue list, all played at once (docs/gui.md, "Playback"): the
// list's name, its current cue and fade, GO, BACK and a master fader. The viewport shows the
// lists merged (intensity HTP with each master, the rest LTP; shows/playbacks.h).
#include <cstdio>

#include "app/gui/gui.h"

namespace haze {

void drawPlaybacksTab(Gui& gui) {
  ShowDocument& doc = *gui.doc;
  const Show& show = doc.show();
  const double now = gui.nowS;
  if (show.cueLists.empty()) {
    ImGui::TextWrapped("No cue lists yet. Record a cue (Ctrl+R) to make the first.");
    return;
  }
  for (size_t i = 0; i < show.cueLists.size(); ++i) {
    const CueList& list = show.cueLists[i];
    ImGui::PushID(static_cast<int>(i));
    if (i > 0) ImGui::Separator();
    ImGui::TextUnformatted(list.name.empty() ? "(unnamed)" : list.name.c_str());
    if (ImGui::Button("GO")) {
      if (!doc.listGo(i, now)) gui.say("cue list \"" + list.name + "\": no cue after the current one", true);
    }
    ImGui::SameLine();
    if (ImGui::Button("BACK")) {
      if (!doc.listBack(i, now)) gui.say("cue list \"" + list.name + "\": no cue before the current one", true);
    }
    ImGui::SameLine();
    float master = static_cast<float>(doc.listMaster(i));
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##master", &master, 0.0f, 1.0f, "master %.2f")) doc.setListMaster(i, master);
    const auto c = doc.listCue(i);
    const double p = doc.listFadeProgress(i, now);
    char overlay[160] = "no cue on stage";
    if (c && *c < list.cues.size()) {
      const Cue& cue = list.cues[*c];
      if (p < 0.0) std::snprintf(overlay, sizeof overlay, "%s %s: delay", cue.number.c_str(), cue.label.c_str());
      else if (p < 1.0) std::snprintf(overlay, sizeof overlay, "%s %s: %.0f %%", cue.number.c_str(), cue.label.c_str(), p * 100.0);
      else std::snprintf(overlay, sizeof overlay, "%s %s", cue.number.c_str(), cue.label.c_str());
    }
    ImGui::ProgressBar(static_cast<float>(p < 0.0 ? 0.0 : p), ImVec2(-1.0f, 0.0f), overlay);
    ImGui::PopID();
  }
}

}  // namespace haze
