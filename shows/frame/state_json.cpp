// The stage state as JSON (see state_json.h).
#include "shows/frame/state_json.h"

#include <optional>
#include <string>

#include "shows/show_json.h"

namespace haze {

nlohmann::ordered_json stageStateJson(const Show& show, const ProfileSet& profiles, const StageState& state,
                                      std::optional<double> gateAtS) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [id, a] : state) {
    std::optional<float> zoom = a.zoomDeg;
    size_t cells = 0;
    bool gateFocus = false;
    if (const FixtureDef* f = show.findFixture(id))
      if (auto p = profiles.find(f->profile); p != profiles.end() && p->second) {
        if (!zoom) zoom = p->second->fieldAngleDeg;
        cells = p->second->cells.size();
        gateFocus = p->second->hasGateFocus;
      }
    nlohmann::ordered_json o;
    o["intensity"] = tidy(a.intensity);
    o["pan"] = tidy(a.panDeg);
    o["tilt"] = tidy(a.tiltDeg);
    o["color"] = {tidy(a.color.r), tidy(a.color.g), tidy(a.color.b)};
    if (a.color2 != "Open") o["color2"] = a.color2;
    if (a.ctoMired != 0.0f) o["cto"] = tidy(a.ctoMired);
    o["zoom"] = zoom ? nlohmann::ordered_json(tidy(*zoom)) : nlohmann::ordered_json(nullptr);
    o["gobo"] = a.gobo;
    o["gobo_rotation"] = tidy(a.goboRotationDeg);
    // The second wheel and the spins only where they are in, so that states of fixtures
    // without them print as before. "*_angle": where the spinning wheel stands at --at.
    const double t = gateAtS.value_or(0.0);
    if (a.goboSpinDegS != 0.0f) {
      o["gobo_spin"] = tidy(a.goboSpinDegS);
      o["gobo_angle"] = tidy(spunDeg(a.goboRotationDeg, a.goboSpinDegS, t));
    }
    if (a.gobo2 != "Open" || a.gobo2RotationDeg != 0.0f || a.gobo2SpinDegS != 0.0f) {
      o["gobo2"] = a.gobo2;
      o["gobo2_rotation"] = tidy(a.gobo2RotationDeg);
    }
    if (a.gobo2SpinDegS != 0.0f) {
      o["gobo2_spin"] = tidy(a.gobo2SpinDegS);
      o["gobo2_angle"] = tidy(spunDeg(a.gobo2RotationDeg, a.gobo2SpinDegS, t));
    }
    if (a.animation != "Open" || a.animationRotationDeg != 0.0f || a.animationSpinDegS != 0.0f) {
      o["animation"] = a.animation;
      o["animation_rotation"] = tidy(a.animationRotationDeg);
    }
    if (a.animationSpinDegS != 0.0f) {
      o["animation_spin"] = tidy(a.animationSpinDegS);
      o["animation_angle"] = tidy(spunDeg(a.animationRotationDeg, a.animationSpinDegS, t));
    }
    o["iris"] = tidy(a.iris);
    // The lens's focus (docs/physics.md, "Focus") where the fixture has one.
    if (gateFocus || a.gateFocus != Attributes{}.gateFocus) o["focus"] = tidy(a.gateFocus);
    if (cells > 0) {  // docs/cells.md: every cell of the profile, 1 and white where unset
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (size_t k = 0; k < cells; ++k) {
        const CellAttributes c = cellAttributes(a, k);
        list.push_back({{"intensity", tidy(c.intensity)}, {"color", {tidy(c.color.r), tidy(c.color.g), tidy(c.color.b)}}});
      }
      o["cells"] = std::move(list);
    }
    o["frost"] = tidy(a.frost);
    o["prism"] = a.prism;
    o["prism_rotation"] = tidy(a.prismRotationDeg);
    if (a.prismSpinDegS != 0.0f) {
      o["prism_spin"] = tidy(a.prismSpinDegS);
      o["prism_angle"] = tidy(spunDeg(a.prismRotationDeg, a.prismSpinDegS, t));
    }
    nlohmann::ordered_json blades = nlohmann::ordered_json::array();
    for (const glm::vec2& ends : a.blades) blades.push_back({tidy(ends.x), tidy(ends.y)});
    o["blades"] = blades;
    o["blade_rotation"] = tidy(a.bladeRotationDeg);
    o["shutter"] = shutterJson(a.shutter);
    if (gateAtS) o["gate"] = tidy(shutterGate(a.shutter, *gateAtS));
    out[std::to_string(id)] = std::move(o);
  }
  return out;
}

}  // namespace haze
