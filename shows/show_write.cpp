// Writing a show as text a person can diff: keys in the order of docs/show-format.md, 2-space indent,
// number arrays ([x, y, z], colours) on one line, floats in their shortest form, whole numbers
// without ".0", so that loading and saving an unchanged show changes no byte.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "shows/effects.h"
#include "shows/palettes.h"
#include "shows/show_json.h"

namespace haze {

namespace {

using ojson = nlohmann::ordered_json;

ojson vec(const glm::vec3& v) { return ojson::array({tidy(v.x), tidy(v.y), tidy(v.z)}); }

ojson greyOrRgb(const glm::vec3& v) {
  if (v.x == v.y && v.y == v.z) return tidy(v.x);
  return vec(v);
}

bool isScalar(const ojson& j) { return !j.is_object() && !j.is_array(); }

void print(const ojson& j, int indent, std::string& out);

std::string scalar(const ojson& j) {
  if (j.is_number_float()) {
    double v = j.get<double>();
    if (std::isfinite(v) && std::floor(v) == v && std::fabs(v) < 1e15) {
      char buf[32];
      auto res = std::to_chars(buf, buf + sizeof buf, static_cast<long long>(v));
      return std::string(buf, res.ptr);
    }
  }
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

void print(const ojson& j, int indent, std::string& out) {
  const std::string pad(static_cast<size_t>(indent) + 2, ' ');
  if (j.is_object()) {
    if (j.empty()) {
      out += "{}";
      return;
    }
    out += "{\n";
    size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      out += pad + ojson(it.key()).dump(-1, ' ', false, ojson::error_handler_t::replace) + ": ";
      print(*it, indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<size_t>(indent), ' ') + "}";
  } else if (j.is_array()) {
    bool flat = std::all_of(j.begin(), j.end(), [](const ojson& e) { return isScalar(e); });
    if (j.empty() || flat) {
      out += "[";
      for (size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + scalar(j[i]);
      out += "]";
      return;
    }
    out += "[\n";
    for (size_t i = 0; i < j.size(); ++i) {
      out += pad;
      print(j[i], indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<size_t>(indent), ' ') + "]";
  } else {
    out += scalar(j);
  }
}

ojson valuesJson(const CueValues& v) {
  ojson o = ojson::object();
  if (v.intensity) o["intensity"] = tidy(*v.intensity);
  if (v.panDeg) o["pan"] = tidy(*v.panDeg);
  if (v.tiltDeg) o["tilt"] = tidy(*v.tiltDeg);
  if (v.color) o["color"] = vec(*v.color);
  if (v.zoomDeg) o["zoom"] = tidy(*v.zoomDeg);
  if (v.color2) o["color2"] = *v.color2;
  if (v.ctoMired) o["cto"] = tidy(*v.ctoMired);
  if (v.gobo) o["gobo"] = *v.gobo;
  if (v.goboRotationDeg) o["gobo_rotation"] = tidy(*v.goboRotationDeg);
  if (v.gobo2) o["gobo2"] = *v.gobo2;
  if (v.gobo2RotationDeg) o["gobo2_rotation"] = tidy(*v.gobo2RotationDeg);
  if (v.goboSpinDegS) o["gobo_spin"] = tidy(*v.goboSpinDegS);
  if (v.gobo2SpinDegS) o["gobo2_spin"] = tidy(*v.gobo2SpinDegS);
  if (v.animation) o["animation"] = *v.animation;
  if (v.animationRotationDeg) o["animation_rotation"] = tidy(*v.animationRotationDeg);
  if (v.animationSpinDegS) o["animation_spin"] = tidy(*v.animationSpinDegS);
  if (v.iris) o["iris"] = tidy(*v.iris);
  if (!v.cells.empty()) {
    ojson cells = ojson::object();
    for (const auto& [k, cv] : v.cells) {
      ojson c = ojson::object();
      if (cv.intensity) c["intensity"] = tidy(*cv.intensity);
      if (cv.color) c["color"] = vec(*cv.color);
      cells[std::to_string(k + 1)] = std::move(c);
    }
    o["cells"] = std::move(cells);
  }
  if (v.frost) o["frost"] = tidy(*v.frost);
  if (v.gateFocus) o["focus"] = tidy(*v.gateFocus);
  if (v.prism) o["prism"] = *v.prism;
  if (v.prismRotationDeg) o["prism_rotation"] = tidy(*v.prismRotationDeg);
  if (v.prismSpinDegS) o["prism_spin"] = tidy(*v.prismSpinDegS);
  if (v.blades) {
    ojson blades = ojson::array();
    for (const glm::vec2& ends : *v.blades) blades.push_back(ojson::array({tidy(ends.x), tidy(ends.y)}));
    o["blades"] = blades;
  }
  if (v.bladeRotationDeg) o["blade_rotation"] = tidy(*v.bladeRotationDeg);
  if (v.shutter) o["shutter"] = shutterJson(*v.shutter);
  if (!v.palettes.empty()) {
    ojson refs = ojson::object();
    if (!v.palettes.all.empty()) refs["all"] = v.palettes.all;
    if (!v.palettes.position.empty()) refs["position"] = v.palettes.position;
    if (!v.palettes.color.empty()) refs["color"] = v.palettes.color;
    if (!v.palettes.beam.empty()) refs["beam"] = v.palettes.beam;
    o["palettes"] = refs;
  }
  return o;
}

ojson timingJson(const CueTimingDef& t) {
  ojson o = ojson::object();
  auto part = [&](const char* key, const std::optional<PartTiming>& p) {
    if (!p) return;
    ojson j = ojson::object();
    if (p->delayS) j["delay"] = *p->delayS;
    if (p->fadeS) j["fade"] = *p->fadeS;
    o[key] = j;
  };
  part("up", t.up);
  part("down", t.down);
  part("position", t.position);
  part("color", t.color);
  part("beam", t.beam);
  if (t.fan) o["fan"] = ojson{{"group", t.fan->group}, {"delay", t.fan->delayStepS}, {"fade", t.fan->fadeStepS}};
  if (t.curve != FadeCurve::Linear) o["curve"] = "s-curve";
  return o;
}

// atmosphere.density as docs/shows.md lists it; defaults are left out.
ojson densityJson(const DensitySpec& d) {
  const DensitySpec def;
  ojson o = ojson::object();
  o["base"] = tidy(d.base);
  if (d.grid[0] != def.grid[0] || d.grid[1] != def.grid[1] || d.grid[2] != def.grid[2])
    o["grid"] = ojson::array({d.grid[0], d.grid[1], d.grid[2]});
  if (d.boundsMinM && d.boundsMaxM) o["bounds"] = ojson::array({vec(*d.boundsMinM), vec(*d.boundsMaxM)});
  if (d.airFlowMps != glm::vec3(0.0f)) o["air_flow"] = vec(d.airFlowMps);
  if (d.mixingM2ps != def.mixingM2ps) o["mixing"] = tidy(d.mixingM2ps);
  if (d.dissipationPerS != 0.0f) o["dissipation"] = tidy(d.dissipationPerS);
  if (d.warmupS != def.warmupS) o["warmup"] = tidy(static_cast<float>(d.warmupS));
  if (d.still) o["still"] = true;
  if (d.fog) o["fog"] = ojson{{"density", tidy(d.fog->density)}, {"height", tidy(d.fog->heightM)},
                              {"falloff", tidy(d.fog->falloffM)}};
  if (!d.boxes.empty()) {
    ojson boxes = ojson::array();
    for (const DensityBoxSpec& b : d.boxes)
      boxes.push_back(ojson{{"min", vec(b.minM)}, {"max", vec(b.maxM)}, {"density", tidy(b.density)}});
    o["boxes"] = boxes;
  }
  if (!d.hazers.empty()) {
    ojson hazers = ojson::array();
    for (const HazerSpec& h : d.hazers)
      hazers.push_back(ojson{{"position", vec(h.positionM)}, {"direction", vec(h.direction)}, {"output", tidy(h.output)},
                             {"spread", tidy(h.spreadDeg)}, {"speed", tidy(h.speedMps)}});
    o["hazers"] = hazers;
  }
  return o;
}

// atmosphere.particles as docs/shows.md lists it; "enabled" always, the rest when not default.
ojson particlesJson(const ParticleSettings& ps) {
  const ParticleSettings def;
  ojson o = ojson::object();
  o["enabled"] = ps.enabled;
  if (ps.densityPerM3 != def.densityPerM3) o["density"] = tidy(ps.densityPerM3);
  if (ps.sizeUm != def.sizeUm) o["size_um"] = tidy(ps.sizeUm);
  if (ps.sizeSigma != def.sizeSigma) o["size_sigma"] = tidy(ps.sizeSigma);
  if (ps.brightness != def.brightness) o["brightness"] = tidy(ps.brightness);
  if (ps.seed != def.seed) o["seed"] = ps.seed;
  return o;
}

ojson showJson(const Show& s) {
  ojson root = ojson::object();
  root["format"] = "haze-show";
  root["version"] = kShowFormatVersion;
  if (!s.venueGltf.empty()) root["venue"] = ojson{{"gltf", s.venueGltf}};
  if (!s.mvrSource.empty()) root["mvr"] = ojson{{"source", s.mvrSource}};
  const AtmosphereDef& a = s.atmosphere;
  ojson at = ojson::object();
  at["scattering"] = tidy(a.scattering);
  at["absorption"] = tidy(a.absorption);
  at["phase"] = a.phase;
  at["g"] = tidy(a.g);
  at["ambient"] = greyOrRgb(a.ambient);
  if (a.background != glm::vec3(0.0f)) at["background"] = greyOrRgb(a.background);
  if (a.density) at["density"] = densityJson(*a.density);
  if (!a.softShadows) at["shadows"] = "hard";  // soft, the default, is not written
  if (a.sun) {
    ojson sun = ojson::object();
    sun["enabled"] = a.sun->enabled;
    sun["azimuth"] = tidy(a.sun->azimuthDeg);
    sun["elevation"] = tidy(a.sun->elevationDeg);
    sun["illuminance_lux"] = tidy(a.sun->illuminanceLux);
    sun["color"] = greyOrRgb(a.sun->color);
    at["sun"] = sun;
  }
  if (a.particles) at["particles"] = particlesJson(*a.particles);
  root["atmosphere"] = at;
  ojson cams = ojson::array();
  for (const CameraDef& c : s.cameras) {
    ojson o = ojson::object();
    o["name"] = c.name;
    o["position"] = vec(c.position);
    o["target"] = vec(c.target);
    if (c.up != glm::vec3(0.0f, 1.0f, 0.0f)) o["up"] = vec(c.up);
    o["fov_y"] = tidy(c.fovYDeg);
    if (c.farM != 100.0f) o["far"] = tidy(c.farM);
    if (c.exposure) {
      ojson e = ojson::object();
      e["mode"] = c.exposure->manual ? "manual" : "auto";
      e["ev"] = tidy(c.exposure->ev);
      o["exposure"] = e;
    }
    cams.push_back(o);
  }
  root["cameras"] = cams;
  ojson profs = ojson::object();
  for (const auto& [name, ref] : s.profiles) {
    if (ref.inlineObject) {
      // nlohmann::json keeps object keys sorted, so an inline profile writes in a stable order.
      ojson body = ojson::parse(ref.inlineObject->dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
      profs[name] = ref.inlineWrapped ? ojson{{"inline", body}} : body;
    } else {
      profs[name] = ref.path;
    }
  }
  root["profiles"] = profs;
  ojson fixtures = ojson::array();
  for (const FixtureDef& f : s.fixtures) {
    ojson o = ojson::object();
    o["id"] = f.id;
    if (!f.name.empty()) o["name"] = f.name;
    o["profile"] = f.profile;
    if (!f.mode.empty()) o["mode"] = f.mode;
    o["position"] = vec(f.position);
    o["rotation"] = vec(f.rotationDeg);
    if (f.patch) o["patch"] = ojson{{"universe", f.patch->universe}, {"address", f.patch->address}};
    if (!f.mvrUuid.empty()) o["uuid"] = f.mvrUuid;
    fixtures.push_back(o);
  }
  root["fixtures"] = fixtures;
  if (!s.groups.empty()) {
    ojson groups = ojson::array();
    for (const GroupDef& g : s.groups) groups.push_back(ojson{{"name", g.name}, {"fixtures", g.fixtures}});
    root["groups"] = groups;
  }
  if (!s.palettes.empty()) {
    ojson pals = ojson::array();
    for (const PaletteDef& p : s.palettes) {
      ojson o = ojson::object();
      o["name"] = p.name;
      o["kind"] = paletteKindName(p.kind);
      if (!p.groups.empty()) {
        ojson g = ojson::object();
        for (const auto& [name, v] : p.groups) g[name] = valuesJson(v);
        o["groups"] = g;
      }
      if (!p.fixtures.empty()) {
        ojson f = ojson::object();
        for (const auto& [id, v] : p.fixtures) f[std::to_string(id)] = valuesJson(v);
        o["fixtures"] = f;
      }
      pals.push_back(o);
    }
    root["palettes"] = pals;
  }
  ojson lists = ojson::array();
  for (const CueList& l : s.cueLists) {
    ojson cues = ojson::array();
    for (const Cue& c : l.cues) {
      ojson o = ojson::object();
      o["number"] = c.number;
      o["label"] = c.label;
      o["fade"] = c.fadeS;
      o["delay"] = c.delayS;
      o["follow"] = c.followS ? ojson(*c.followS) : ojson(nullptr);
      if (!c.timecode.empty()) o["timecode"] = c.timecode;
      if (!c.timing.empty()) o["timing"] = timingJson(c.timing);
      if (!c.effects.empty()) {
        ojson effects = ojson::array();
        for (const EffectDef& e : c.effects) {
          ojson j = ojson::object();
          j["shape"] = effectShapeName(e.shape);
          if (e.shape != EffectShape::Circle) j["attribute"] = e.attribute;
          j["group"] = e.group;
          j["rate"] = e.rateHz;
          j["size"] = e.size;
          if (e.phaseDeg != 0.0) j["phase"] = e.phaseDeg;
          if (e.spreadDeg != 0.0) j["spread"] = e.spreadDeg;
          if (e.shape == EffectShape::Random) j["seed"] = e.seed;
          if (!e.colors.empty()) {
            ojson colors = ojson::array();
            for (const glm::vec3& c : e.colors) colors.push_back(ojson::array({c.r, c.g, c.b}));
            j["colors"] = colors;
          }
          effects.push_back(j);
        }
        o["effects"] = effects;
      }
      if (!c.hazers.empty()) {
        ojson hazers = ojson::object();
        for (const auto& [n, h] : c.hazers) {
          ojson j = ojson::object();
          if (h.output) j["output"] = tidy(*h.output);
          if (h.fan) j["fan"] = tidy(*h.fan);
          hazers[std::to_string(n)] = j;
        }
        o["hazers"] = hazers;
      }
      ojson vals = ojson::object();
      for (const auto& [id, v] : c.values) vals[std::to_string(id)] = valuesJson(v);
      o["values"] = vals;
      cues.push_back(o);
    }
    lists.push_back(ojson{{"name", l.name}, {"cues", cues}});
  }
  if (s.defaultFadeS > 0.0) root["default_fade"] = s.defaultFadeS;
  root["cue_lists"] = lists;
  return root;
}

}  // namespace

nlohmann::ordered_json shutterJson(const Shutter& s) {
  if (!s.strobing()) return s.mode == ShutterMode::Closed ? "closed" : "open";
  ojson o = ojson::object();
  o["strobe_hz"] = tidy(s.rateHz);
  o["duty"] = tidy(s.duty);
  if (s.mode != ShutterMode::Strobe) o["mode"] = shutterModeName(s.mode);
  return o;
}

double tidy(float f) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf - 1, f);
  *res.ptr = '\0';
  return std::strtod(buf, nullptr);
}

std::string showToText(const Show& show) {
  std::string out;
  print(showJson(show), 0, out);
  out += "\n";
  return out;
}

}  // namespace haze
