// File > MVR-xchange: haze as an MVR-xchange station for the saved show (the same station as
// `haze live --mvr-xchange`, app/xchange_station.h): the stations seen, "Commit" to send the
// show as saved to them, "Request" to fetch a station's latest file, imported as a new show
// beside the open one (never into it). The station stops when the window's Stop is pressed or
// another show is opened.
#include "app/gui/gui.h"

namespace haze {
namespace {

void startStation(Gui& gui) {
  if (gui.doc->untitled()) return gui.say("save the show first: MVR-xchange offers the saved show file", true);
  XchangeOptions o;
  o.enabled = true;
  o.group = gui.xchangeGroup;
  o.acceptDir = gui.doc->show().file.parent_path().string();
  if (o.acceptDir.empty()) o.acceptDir = ".";
  o.requestCommits = false;  // the window's Request fetches; a commit is listed
  auto s = XchangeService::start(gui.doc->show().file, gui.xchangeBind, o);
  if (!s) return gui.say("MVR-xchange: " + s.error().str(), true);
  gui.xchange = std::move(*s);
  gui.xchangeShow = gui.doc->show().file.string();
  gui.say("MVR-xchange: haze is a station of group " + o.group + " on port " + std::to_string(gui.xchange->port()));
}

void drawStations(Gui& gui) {
  const std::vector<XchangeService::StationSeen> seen = gui.xchange->stations();
  if (seen.empty()) ImGui::TextDisabled("no station has joined or been found yet");
  if (!seen.empty() && ImGui::BeginTable("stations", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("Station");
    ImGui::TableSetupColumn("Provider");
    ImGui::TableSetupColumn("Files");
    ImGui::TableSetupColumn("");
    ImGui::TableHeadersRow();
    for (const XchangeService::StationSeen& s : seen) {
      ImGui::PushID(s.uuid.c_str());
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%s%s", s.name.empty() ? s.uuid.c_str() : s.name.c_str(), s.left ? " (left)" : "");
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(s.provider.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%zu", s.files);
      ImGui::TableNextColumn();
      ImGui::BeginDisabled(!s.connected);
      if (ImGui::SmallButton("Request")) gui.xchange->request(s.uuid);
      ImGui::EndDisabled();
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
}

}  // namespace

void drawXchangeWindow(Gui& gui) {
  // The station serves one show file: another show opened stops it.
  if (gui.xchange && (gui.doc->untitled() || gui.doc->show().file.string() != gui.xchangeShow)) gui.xchange.reset();
  if (!gui.showXchange) return;
  ImGui::SetNextWindowSize(ImVec2(460, 300), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("MVR-xchange", &gui.showXchange)) {
    if (!gui.xchange) {
      ImGui::InputText("Group", gui.xchangeGroup, sizeof gui.xchangeGroup);
      ImGui::InputText("Bind", gui.xchangeBind, sizeof gui.xchangeBind);
      ImGui::SameLine();
      ImGui::TextDisabled("0.0.0.0: the network");
      if (ImGui::Button("Start")) startStation(gui);
      ImGui::TextWrapped("Announces haze over mDNS (when avahi-daemon runs) and offers the saved show as MVR; "
                         "files other stations send are imported as new shows beside this one (docs/mvr.md).");
    } else {
      ImGui::Text("Group %s, %s:%d", gui.xchangeGroup, gui.xchangeBind, gui.xchange->port());
      ImGui::SameLine();
      if (ImGui::Button("Commit")) gui.xchange->commitNow();
      ImGui::SameLine();
      if (ImGui::Button("Stop")) gui.xchange.reset();
    }
    if (gui.xchange) {
      drawStations(gui);
      ImGui::Separator();
      for (const std::string& line : gui.xchange->recentLines()) ImGui::TextWrapped("%s", line.c_str());
    }
  }
  ImGui::End();
}

}  // namespace haze
