// The layout: the show panel on the left with the command line under it, the inspector on the
// right, the viewport between them under the menu bar. Fixed but for the show panel's width,
// which fits its tab names by default and follows a drag of its right edge, so that panels never
// cover the stage and tests can click at known places.
#include <algorithm>
#include <cmath>
#include <iterator>

#include "app/gui/gui.h"

namespace haze {

Layout layoutFor(float widthPx, float heightPx, float menuHeightPx, float leftWidthPx) {
  Layout l;
  l.menuH = menuHeightPx;
  const float leftW = leftWidthPx;
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

// The narrowest show panel whose tab bar draws every tab name whole, as ImGui 1.86 lays it out
// (TabItemCalcSize: the label and the frame padding each side; ItemInnerSpacing between tabs),
// with room for a vertical scroll bar, which a long cue list brings.
static float tabsWidth() {
  const ImGuiStyle& style = ImGui::GetStyle();
  float w = 2.0f * style.WindowPadding.x + style.ScrollbarSize;
  for (const char* tab : kShowTabs) w += ImGui::CalcTextSize(tab).x + 2.0f * style.FramePadding.x;
  return w + style.ItemInnerSpacing.x * static_cast<float>(std::size(kShowTabs) - 1) + 2.0f;
}

float showPanelWidth(const Gui& gui, float windowWidthPx) {
  // Dragged: kept, but never so wide that the viewport and the inspector have no room.
  const float most = std::max(200.0f, windowWidthPx * 0.5f);
  if (gui.showPanelW > 0.0f) return std::clamp(gui.showPanelW, std::min(150.0f, most), most);
  // A quarter of the window (200..300 px) as before, widened to fit the tab names where a quarter
  // of the window allows it: at 1600x900 every name is whole; at 640x360 the viewport keeps its
  // size and the tabs shrink.
  const float quarter = std::clamp(windowWidthPx * 0.25f, 200.0f, 300.0f);
  return std::max(quarter, std::min(tabsWidth(), windowWidthPx * 0.25f));
}

void drawShowPanel(Gui& gui) {
  const Rect& r = gui.layout.left;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  // Resizable by its right edge: a drag changes the window's width this frame (after the size
  // set above), which becomes the layout's width from the next frame on.
  ImGui::Begin("Show", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  if (std::abs(ImGui::GetWindowWidth() - r.w) > 0.5f) gui.showPanelW = ImGui::GetWindowWidth();
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
    // How wide each tab was drawn against what its name needs (ImGui shrinks tabs to fit).
    gui.tabsShown.clear();
    const ImGuiTabBar* bar = GImGui->CurrentTabBar;
    for (const ImGuiTabItem& tab : bar->Tabs)
      gui.tabsShown.push_back({bar->GetTabName(&tab), tab.Width, tab.ContentWidth});
    ImGui::EndTabBar();
    gui.openTab.clear();
  }
  ImGui::End();
}

}  // namespace haze
