// The viewport: the orbit camera (drag orbits, right/middle or Shift+drag pans, the wheel zooms;
// View > Camera jumps to a show camera), clicks by tool (select a fixture or its beam, place a
// fixture on a surface, focus the selection on a point), dragging a selected fixture (move on
// its level, Ctrl: up and down, Alt: turn), dragging the end of a selected beam (aims it at the
// venue point under the pointer, focus to point as it moves), and the overlay: a marker per fixture, the
// selection highlighted with its name and beam axis, and the point under the pointer while
// placing or focusing. The picking itself is shows/edit/picking.h (tested without a window).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/gui/gui.h"
#include "fixtures/pose.h"

namespace haze {

Orbit Orbit::from(const CameraDef& c) {
  Orbit o;
  o.target = c.target;
  const glm::vec3 d = c.position - c.target;
  o.distanceM = std::max(glm::length(d), 0.5f);
  o.yawRad = std::atan2(d.x, d.z);
  o.pitchRad = std::asin(std::clamp(d.y / o.distanceM, -1.0f, 1.0f));
  return o;
}

glm::vec3 Orbit::position() const {
  return target + distanceM * glm::vec3(std::cos(pitchRad) * std::sin(yawRad), std::sin(pitchRad),
                                        std::cos(pitchRad) * std::cos(yawRad));
}

CameraState Gui::cameraState() const {
  CameraState c;
  c.position = orbit.position();
  c.target = orbit.target;
  c.fovYDeg = fovYDeg;
  if (camera >= 0 && static_cast<size_t>(camera) < doc->show().cameras.size()) c.farM = doc->show().cameras[camera].farM;
  return c;
}

namespace {

enum class DragKind { None, Pending, Orbit, Pan, MoveFixture, LiftFixture, TurnFixture, Aim };

struct ViewDrag {
  DragKind kind = DragKind::None;
  int button = 0;
  ImVec2 pressPos{};
  bool moved = false;
  bool merge = false;      // later moves of the same drag fold into one undo step
  int fixture = 0;
  glm::vec3 startPosM{0.0f}, startRotDeg{0.0f}, grabOffsetM{0.0f};
};
ViewDrag gDrag;

glm::vec2 toLocal(const Rect& vp, ImVec2 p) { return {p.x - vp.x, p.y - vp.y}; }

// Where a fixture's beam axis leaves the lens and where it meets the venue (10 m when it meets
// nothing): the overlay draws it, and dragging its end aims the beam.
struct BeamAxis {
  glm::vec3 lensM{0.0f}, endM{0.0f};
};
std::optional<BeamAxis> beamAxis(const Gui& gui, const FixtureDef& f) {
  const ShowDocument& doc = *gui.doc;
  const auto st = gui.stage.find(f.id);
  const auto prof = doc.profiles().find(f.profile);
  if (st == gui.stage.end() || prof == doc.profiles().end() || !prof->second) return std::nullopt;
  const BeamPose pose = beamPose(f.position, f.rotationDeg, st->second.panDeg, st->second.tiltDeg, prof->second->lensOffset);
  const glm::vec3 dir = glm::normalize(pose.zb);
  float len = 10.0f;
  if (auto h = castVenue(doc.bvh(), Ray{pose.lensPosition, dir}, 200.0f)) len = h->distanceM;
  return BeamAxis{pose.lensPosition, pose.lensPosition + len * dir};
}

std::string vecText(const glm::vec3& v) {
  char s[64];
  std::snprintf(s, sizeof(s), "(%.2f, %.2f, %.2f)", v.x, v.y, v.z);
  return s;
}

void click(Gui& gui, const ViewCamera& view, glm::vec2 local, bool ctrl, bool shift) {
  ShowDocument& doc = *gui.doc;
  switch (gui.tool) {
    case Tool::Select: {
      const auto picked = pickFixture(doc.show(), doc.profiles(), gui.stage, view, local, &doc.bvh());
      applyClickToSelection(doc.selection, picked, ctrl, shift);
      if (picked) {
        const FixtureDef* f = doc.show().findFixture(*picked);
        gui.say("selected " + std::to_string(*picked) + " " + (f ? f->name : ""));
      }
      return;
    }
    case Tool::Place: {
      const auto hit = pickVenue(doc.bvh(), view, local, 6.0f);
      if (!hit) {
        gui.say("nothing to place on there: click a truss, a floor or a wall", true);
        return;
      }
      const MountPose pose = mountOnSurface(*hit);
      auto id = doc.placeFixtureAt(gui.placeProfile, pose);
      if (!id) {
        gui.say(id.error().str(), true);
        return;
      }
      const char* how = pose.kind == MountPose::Kind::Hanging ? "hanging" : pose.kind == MountPose::Kind::Standing ? "standing" : "on the wall";
      gui.say("placed fixture " + std::to_string(*id) + " " + how + " at " + vecText(pose.positionM) +
              "; F then a click aims it");
      if (!shift) gui.tool = Tool::Select;
      return;
    }
    case Tool::Focus: {
      const auto hit = pickVenue(doc.bvh(), view, local, 0.0f);
      if (!hit) {
        gui.say("no surface there to focus on", true);
        return;
      }
      auto results = doc.focusSelectionOn(hit->surface.positionM, gui.stage);
      if (!results) {
        gui.say(results.error().str(), true);
        return;
      }
      size_t missed = 0;
      std::string note;
      for (const FocusResult& r : *results)
        if (!r.reached) {
          ++missed;
          note = r.note;
        }
      std::string line = "focused " + std::to_string(results->size()) + " fixture(s) on " + vecText(hit->surface.positionM);
      if (missed) line += "; " + std::to_string(missed) + " out of reach (" + note + "): nearest direction";
      gui.say(line, missed > 0);
      if (!shift) gui.tool = Tool::Select;
      return;
    }
  }
}

void pressed(Gui& gui, const ViewCamera& view, glm::vec2 local, int button) {
  const ImGuiIO& io = ImGui::GetIO();
  gDrag = ViewDrag{};
  gDrag.button = button;
  gDrag.pressPos = io.MousePos;
  gDrag.kind = button == ImGuiMouseButton_Left ? DragKind::Pending : DragKind::Pan;
  if (button != ImGuiMouseButton_Left || gui.tool != Tool::Select) return;
  ShowDocument& doc = *gui.doc;
  // The end of a selected fixture's beam axis (the ring where it meets the venue): aim by drag.
  for (int id : doc.selection) {
    const FixtureDef* f = doc.show().findFixture(id);
    const auto axis = f ? beamAxis(gui, *f) : std::nullopt;
    const auto end = axis ? view.project(axis->endM) : std::nullopt;
    if (end && glm::length(*end - local) <= 7.0f) {
      gDrag.kind = DragKind::Aim;
      return;
    }
  }
  // Its body or its marker (not its beam); the venue hides a body behind it, as for a click.
  const auto picked = pickFixture(doc.show(), doc.profiles(), gui.stage, view, local, &doc.bvh(),
                                  PickOptions{.beamRadiusPx = 0.0f});
  if (!picked || std::find(doc.selection.begin(), doc.selection.end(), *picked) == doc.selection.end()) return;
  const FixtureDef* f = doc.show().findFixture(*picked);
  if (!f) return;
  gDrag.fixture = f->id;
  gDrag.startPosM = f->position;
  gDrag.startRotDeg = f->rotationDeg;
  gDrag.kind = io.KeyAlt ? DragKind::TurnFixture : io.KeyCtrl ? DragKind::LiftFixture : DragKind::MoveFixture;
  const Ray ray = view.ray(local);
  if (gDrag.kind == DragKind::MoveFixture) {
    if (auto p = intersectHorizontalPlane(ray, f->position.y)) gDrag.grabOffsetM = f->position - *p;
  } else if (gDrag.kind == DragKind::LiftFixture) {
    gDrag.grabOffsetM = f->position - closestOnVerticalLine(ray, f->position);
  }
}

void dragged(Gui& gui, const ViewCamera& view, glm::vec2 local) {
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 d = io.MouseDelta;
  ShowDocument& doc = *gui.doc;
  const Ray ray = view.ray(local);
  switch (gDrag.kind) {
    case DragKind::Pending:
      gDrag.kind = io.KeyShift ? DragKind::Pan : DragKind::Orbit;
      return;
    case DragKind::Orbit:
      gui.orbit.yawRad -= d.x * 0.005f;
      gui.orbit.pitchRad = std::clamp(gui.orbit.pitchRad + d.y * 0.005f, -1.5f, 1.5f);
      return;
    case DragKind::Pan: {
      const CameraState c = gui.cameraState();
      const glm::vec3 fwd = glm::normalize(c.target - c.position);
      const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
      const glm::vec3 up = glm::cross(right, fwd);
      const float mPerPx = 2.0f * gui.orbit.distanceM * std::tan(glm::radians(gui.fovYDeg) * 0.5f) / gui.layout.viewport.h;
      gui.orbit.target += (-d.x * right + d.y * up) * mPerPx;
      return;
    }
    case DragKind::Aim: {
      // Focus to point, continuously: the selection follows the venue point under the pointer.
      const auto hit = pickVenue(doc.bvh(), view, local, 0.0f);
      if (!hit) return;
      auto r = doc.focusSelectionOn(hit->surface.positionM, gui.stage, gDrag.merge);
      if (!r) gui.say(r.error().str(), true);
      gDrag.merge = gDrag.merge || r.ok();  // the whole drag is one undo step
      return;
    }
    case DragKind::MoveFixture:
    case DragKind::LiftFixture:
    case DragKind::TurnFixture: {
      Status s = Ok{};
      if (gDrag.kind == DragKind::MoveFixture) {
        auto p = intersectHorizontalPlane(ray, gDrag.startPosM.y);
        if (!p) return;
        s = doc.run(moveFixture(gDrag.fixture, *p + gDrag.grabOffsetM), gDrag.merge);
      } else if (gDrag.kind == DragKind::LiftFixture) {
        glm::vec3 p = gDrag.startPosM;
        p.y = (closestOnVerticalLine(ray, gDrag.startPosM) + gDrag.grabOffsetM).y;
        s = doc.run(moveFixture(gDrag.fixture, p), gDrag.merge);
      } else {
        glm::vec3 rot = gDrag.startRotDeg;
        rot.y += (io.MousePos.x - gDrag.pressPos.x) * 0.5f;
        s = doc.run(rotateFixture(gDrag.fixture, rot), gDrag.merge);
      }
      if (!s) gui.say(s.error().str(), true);
      gDrag.merge = gDrag.merge || s.ok();
      return;
    }
    case DragKind::None: return;
  }
}

void drawOverlay(Gui& gui, const ViewCamera& view, std::optional<VenueHit> hover) {
  const Rect& vp = gui.layout.viewport;
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  dl->PushClipRect(ImVec2(vp.x, vp.y), ImVec2(vp.x + vp.w, vp.y + vp.h), true);
  const ShowDocument& doc = *gui.doc;
  auto toScreen = [&](glm::vec2 p) { return ImVec2(vp.x + p.x, vp.y + p.y); };
  // The selected fixtures' labels, "101 Spot 1", laid out so that none covers another
  // (label_layout.h): a row of adjacent spots would otherwise print their names over each other.
  std::vector<const FixtureDef*> byId;
  for (const FixtureDef& f : doc.show().fixtures) byId.push_back(&f);
  std::stable_sort(byId.begin(), byId.end(), [](const FixtureDef* a, const FixtureDef* b) { return a->id < b->id; });
  std::vector<LabelRequest> labels;
  std::vector<std::string> labelTexts;
  for (const FixtureDef* f : byId) {
    if (std::find(doc.selection.begin(), doc.selection.end(), f->id) == doc.selection.end()) continue;
    const auto s = view.project(f->position);
    if (!s) continue;
    std::string text = gui.showNumbers ? std::to_string(f->id) + (f->name.empty() ? "" : " " + f->name) : f->name;
    if (text.empty()) continue;
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    labels.push_back({.fixture = f->id, .anchor = glm::vec2(vp.x, vp.y) + *s, .sizePx = {size.x + 4.0f, size.y + 2.0f}});
    labelTexts.push_back(std::move(text));
  }
  gui.placedLabels = placeLabels(labels);
  for (const FixtureDef& f : doc.show().fixtures) {
    const auto s = view.project(f.position);
    if (!s) continue;
    const bool selected = std::find(doc.selection.begin(), doc.selection.end(), f.id) != doc.selection.end();
    const bool programmed = doc.programmer().values.count(f.id) > 0;
    const ImVec2 at = toScreen(*s);
    if (selected) {
      // The beam axis, from the lens to where it meets the venue; its end is a handle to aim by.
      if (const auto axis = beamAxis(gui, f)) {
        const auto a = view.project(axis->lensM), b = view.project(axis->endM);
        if (a && b) dl->AddLine(toScreen(*a), toScreen(*b), IM_COL32(255, 220, 40, 200), 1.5f);
        if (b) dl->AddCircle(toScreen(*b), 5.0f, IM_COL32(255, 220, 40, 220), 12, 1.5f);
      }
      dl->AddCircle(at, 9.0f, IM_COL32(255, 220, 40, 255), 16, 2.5f);
    } else if (gui.showNumbers) {
      // The id under an unselected marker, small and dim: which fixture is which, at a glance.
      const std::string id = std::to_string(f.id);
      const float size = ImGui::GetFontSize() * 0.85f;
      const ImVec2 extent = ImGui::GetFont()->CalcTextSizeA(size, FLT_MAX, 0.0f, id.c_str());
      dl->AddText(ImGui::GetFont(), size, ImVec2(at.x - extent.x * 0.5f, at.y + 6.0f), IM_COL32(220, 220, 230, 200), id.c_str());
    }
    const ImU32 fill = selected ? IM_COL32(255, 220, 40, 255) : programmed ? IM_COL32(255, 140, 40, 230) : IM_COL32(200, 200, 210, 200);
    dl->AddCircleFilled(at, 4.0f, fill, 12);
    dl->AddCircle(at, 4.5f, IM_COL32(20, 20, 20, 200), 12, 1.0f);
  }
  for (size_t i = 0; i < gui.placedLabels.size(); ++i) {
    const PlacedLabel& l = gui.placedLabels[i];
    const ImVec2 min(l.box.x, l.box.y), max(l.box.x + l.box.w, l.box.y + l.box.h);
    // A label pushed off its marker's side keeps a line to it, so it still names the right one.
    if (l.moved) dl->AddLine(ImVec2(l.anchor.x + 5.0f, l.anchor.y), ImVec2(min.x, (min.y + max.y) * 0.5f), IM_COL32(255, 220, 40, 160), 1.0f);
    dl->AddRectFilled(min, max, IM_COL32(20, 20, 24, 190), 2.0f);
    dl->AddText(ImVec2(min.x + 2.0f, min.y + 1.0f), IM_COL32(255, 230, 120, 255), labelTexts[i].c_str());
  }
  if (hover) {
    if (const auto s = view.project(hover->surface.positionM)) {
      const ImVec2 at = toScreen(*s);
      const ImU32 c = gui.tool == Tool::Place ? IM_COL32(80, 255, 120, 255) : IM_COL32(80, 200, 255, 255);
      dl->AddLine(ImVec2(at.x - 8, at.y), ImVec2(at.x + 8, at.y), c, 2.0f);
      dl->AddLine(ImVec2(at.x, at.y - 8), ImVec2(at.x, at.y + 8), c, 2.0f);
      if (gui.tool == Tool::Place) {
        const MountPose m = mountOnSurface(*hover);
        if (const auto q = view.project(m.positionM)) dl->AddCircle(toScreen(*q), 6.0f, c, 12, 2.0f);
      }
    }
  }
  const char* hint = gui.tool == Tool::Place   ? "PLACE: click a surface (Esc: cancel)"
                     : gui.tool == Tool::Focus ? "FOCUS: click the point to aim at (Esc: cancel)"
                                               : nullptr;
  if (hint) dl->AddText(ImVec2(vp.x + 8, vp.y + 6), IM_COL32(255, 255, 255, 255), hint);
  dl->PopClipRect();
}

}  // namespace

void handleViewport(Gui& gui) {
  const ImGuiIO& io = ImGui::GetIO();
  const Rect& vp = gui.layout.viewport;
  const ViewCamera view(gui.cameraState(), {vp.w, vp.h});
  const glm::vec2 local = toLocal(vp, io.MousePos);
  const bool over = vp.contains(io.MousePos) && !io.WantCaptureMouse;

  if (gDrag.kind == DragKind::None && over) {
    for (int b : {ImGuiMouseButton_Left, ImGuiMouseButton_Right, ImGuiMouseButton_Middle})
      if (ImGui::IsMouseClicked(b)) {
        pressed(gui, view, local, b);
        break;
      }
  }
  if (gDrag.kind != DragKind::None) {
    if (ImGui::IsMouseDown(gDrag.button)) {
      const float dx = io.MousePos.x - gDrag.pressPos.x, dy = io.MousePos.y - gDrag.pressPos.y;
      if (!gDrag.moved && dx * dx + dy * dy > 9.0f) gDrag.moved = true;
      if (gDrag.moved && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || gDrag.kind == DragKind::Pending))
        dragged(gui, view, local);
    } else {
      if (!gDrag.moved && gDrag.button == ImGuiMouseButton_Left) click(gui, view, local, io.KeyCtrl, io.KeyShift);
      gDrag = ViewDrag{};
    }
  }
  if (over && io.MouseWheel != 0.0f)
    gui.orbit.distanceM = std::clamp(gui.orbit.distanceM * std::pow(0.9f, io.MouseWheel), 0.5f, 200.0f);

  std::optional<VenueHit> hover;
  if (over && gui.tool != Tool::Select) hover = pickVenue(gui.doc->bvh(), view, local, gui.tool == Tool::Place ? 6.0f : 0.0f);
  drawOverlay(gui, view, hover);
}

}  // namespace haze
