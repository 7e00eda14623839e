// The fixed layout: the show panel on the left with the command line under it, the inspector on the right, the viewport between
// them under the menu bar. Fixed, so that panels never cover the stage and tests can click at
// known places.
#include <algorithm>

#include "app/gui/gui.h"

namespace haze {

Layout layoutFor(float widthPx, float heightPx, float menuHeightPx) {
  Layout l;
  l.menuH = menuHeightPx;
  const float leftW = std::clamp(widthPx * 0.25f, 200.0f, 300.0f);
  const float rightW = std::clamp(widthPx * 0.22f, 190.0f, 280.0f);
  const float h = std::max(heightPx - menuHeightPx, 1.0f);
  // The field and two lines of its result (an error wraps) under the show panel.
  const float commandH = std::min(3.0f * menuHeightPx + 12.0f, h * 0.5f);
  l.left = {0.0f, menuHeightPx, leftW, h - commandH};
  l.command = {0.0f, menuHeightPx + h - commandH, leftW, commandH};
  l.right = {std::max(widthPx - rightW, leftW), menuHeightPx, rightW, h};
  l.viewport = {leftW, menuHeightPx, std::max(l.right.x - leftW, 1.0f), h};
  return l;
}

void drawShowPanel(Gui& gui) {
  const Rect& r = gui.layout.left;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin("Show", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoBringToFrontOnFocus);
  auto flag = [&](const char* tab) {
    return gui.openTab == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
  };
  if (ImGui::BeginTabBar("tabs")) {
    if (ImGui::BeginTabItem("Cues", nullptr, flag("Cues"))) {
      drawCuesTab(gui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Fixtures", nullptr, flag("Fixtures"))) {
      drawFixturesTab(gui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Library", nullptr, flag("Library"))) {
      drawLibraryTab(gui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Patch", nullptr, flag("Patch"))) {
      drawPatchTab(gui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Air", nullptr, flag("Air"))) {
      drawAtmosphereTab(gui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Playback", nullptr, flag("Playback"))) {
      drawPlaybacksTab(gui);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
    gui.openTab.clear();
  }
  ImGui::End();
}

}  // namespace haze
