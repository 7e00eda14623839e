// Reading a show file: JSON text -> Show. Every structural problem (wrong type, missing key,
// unknown key, a value outside a range that needs no profile, negative times, a bad cue number)
// is collected with its JSON pointer, so `haze validate` can list them all at once. Checks that
// need profiles or compare parts of the show with each other live in show_validate.cpp.
#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fixtures/color.h"
#include "fixtures/core/text_file.h"
#include "fixtures/json_read.h"
#include "shows/cue_number.h"
#include "shows/effects.h"
#include "shows/palettes.h"
#include "shows/timecode.h"
#include "shows/show_json.h"

namespace haze {

namespace {

using json = nlohmann::json;

struct TooDeep {};

constexpr double kInf = INFINITY;
// A wheel spinning 100 turns a second is far past any motor; a bigger number is a typing slip.
constexpr double kMaxSpinDegS = 36000.0;

// A number (grey) or [r, g, b], each not negative.
bool greyOrRgb(JsonProblems& r, const json& j, const std::string& ptr, const char* what, glm::vec3& out) {
  if (j.is_number()) {
    double v = 0;
    if (!r.number(j, ptr, 0.0, kMaxJsonMagnitude, what, v)) return false;
    out = glm::vec3(static_cast<float>(v));
    return true;
  }
  if (j.is_array()) return r.vec3(j, ptr, 0.0, kMaxJsonMagnitude, what, out);
  r.problem(ptr, std::string("expected ") + what + " as a number or [r, g, b], got " + jsonKind(j));
  return false;
}


void readVenue(JsonProblems& r, const json& root, Show& show) {
  const json* v = r.member(root, "", "venue", false);
  if (!v || v->is_null()) return;
  if (!r.isObject(*v, "/venue", "the venue")) return;
  r.onlyKeys(*v, "/venue", {"gltf"});
  r.stringMember(*v, "/venue", "gltf", true, "the path of a glTF file", show.venueGltf, true);
}

void readMvrSource(JsonProblems& r, const json& root, Show& show) {
  const json* v = r.member(root, "", "mvr", false);
  if (!v || v->is_null()) return;
  if (!r.isObject(*v, "/mvr", "the MVR the show came from")) return;
  r.onlyKeys(*v, "/mvr", {"source"});
  r.stringMember(*v, "/mvr", "source", true, "the path of an .mvr file", show.mvrSource, true);
}

// density.grid: cells as a number (each axis) or [x, y, z]; a grid too large to simulate is
// refused with the memory it would need.
void readDensityGrid(JsonProblems& r, const json& g, const std::string& gp, DensitySpec& d) {
  int n[3] = {d.grid[0], d.grid[1], d.grid[2]};
  bool ok = true;
  if (g.is_array() && g.size() == 3) {
    for (size_t k = 0; k < 3; ++k)
      ok = r.integer(g[k], gp + "/" + std::to_string(k), 1, 1 << 20, "cells along an axis", n[k]) && ok;
  } else if (g.is_number()) {
    ok = r.integer(g, gp, 1, 1 << 20, "cells along each axis", n[0]);
    n[1] = n[2] = n[0];
  } else {
    r.problem(gp, "expected the grid's cells as a number or [x, y, z]");
    ok = false;
  }
  if (ok) {
    const long long cells = static_cast<long long>(n[0]) * n[1] * n[2];
    const int side = std::max({n[0], n[1], n[2]});
    if (side > kMaxDensityCellsPerSide || cells > kMaxDensityCells) {
      r.problem(gp, "a grid of " + std::to_string(n[0]) + "x" + std::to_string(n[1]) + "x" + std::to_string(n[2]) +
                        " cells needs about " + std::to_string(cells * 28 / (1 << 20)) +
                        " MB to simulate; at most " + std::to_string(kMaxDensityCellsPerSide) + " per side and " +
                        std::to_string(kMaxDensityCells) + " cells");
    } else {
      for (int k = 0; k < 3; ++k) d.grid[k] = n[k];
    }
  }
}

void readHazers(JsonProblems& r, const json& hs, const std::string& p, DensitySpec& d) {
  for (size_t i = 0; i < hs.size(); ++i) {
    const std::string hp = p + "/hazers/" + std::to_string(i);
    const json& h = hs[i];
    if (!r.isObject(h, hp, "a hazer")) continue;
    HazerSpec hz;
    r.onlyKeys(h, hp, {"position", "direction", "output", "spread", "speed"});
    r.vec3Member(h, hp, "position", true, -kMaxJsonMagnitude, kMaxJsonMagnitude, "a position in metres", hz.positionM);
    if (r.vec3Member(h, hp, "direction", false, -kMaxJsonMagnitude, kMaxJsonMagnitude, "a direction", hz.direction) &&
        hz.direction == glm::vec3(0.0f))
      r.problem(hp + "/direction", "expected a direction, got [0, 0, 0]");
    r.numberMember(h, hp, "output", false, 0.0, 1e4, "an output in m^3/s of haze at density 1", hz.output);
    r.numberMember(h, hp, "spread", false, 1.0, 160.0, "the fan's cone angle in degrees", hz.spreadDeg);
    r.numberMember(h, hp, "speed", false, 0.0, 50.0, "the fan's air speed in m/s", hz.speedMps);
    d.hazers.push_back(hz);
  }
}

// atmosphere.density (docs/shows.md, "Density"). A grid too large to simulate is refused here,
// with what it would need; hazers outside the venue are clamped when the field is made (the
// venue's bounds are not known here).
void readDensity(JsonProblems& r, const json& j, const std::string& p, AtmosphereDef& at) {
  if (!r.isObject(j, p, "the density field")) return;
  DensitySpec d;
  r.onlyKeys(j, p, {"base", "grid", "bounds", "air_flow", "mixing", "dissipation", "warmup", "still", "fog", "boxes",
                    "hazers"});
  r.numberMember(j, p, "base", false, 0.0, 1e6, "a density (1 = the atmosphere's own)", d.base);
  if (const json* g = r.member(j, p, "grid", false)) readDensityGrid(r, *g, p + "/grid", d);
  if (const json* b = r.member(j, p, "bounds", false)) {
    glm::vec3 lo{0.0f}, hi{0.0f};
    if (!b->is_array() || b->size() != 2) {
      r.problem(p + "/bounds", "expected the grid's box as [[x, y, z], [x, y, z]] (its two corners)");
    } else if (r.vec3((*b)[0], p + "/bounds/0", -kMaxJsonMagnitude, kMaxJsonMagnitude, "a corner in metres", lo) &&
               r.vec3((*b)[1], p + "/bounds/1", -kMaxJsonMagnitude, kMaxJsonMagnitude, "a corner in metres", hi)) {
      if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
        r.problem(p + "/bounds", "the second corner must be above the first on every axis");
      d.boundsMinM = lo;
      d.boundsMaxM = hi;
    }
  }
  r.vec3Member(j, p, "air_flow", false, -100.0, 100.0, "the room's air speed in m/s", d.airFlowMps);
  r.numberMember(j, p, "mixing", false, 0.0, 100.0, "a diffusion in m^2/s", d.mixingM2ps);
  r.numberMember(j, p, "dissipation", false, 0.0, 100.0, "a decay rate in 1/s", d.dissipationPerS);
  float warmup = static_cast<float>(d.warmupS);
  if (r.numberMember(j, p, "warmup", false, 0.0, 86400.0, "seconds the hazers ran before GO", warmup)) d.warmupS = warmup;
  if (const json* s = r.member(j, p, "still", false)) {
    if (s->is_boolean())
      d.still = s->get<bool>();
    else
      r.problem(p + "/still", std::string("expected true or false, got ") + jsonKind(*s));
  }
  if (const json* f = r.member(j, p, "fog", false); f && r.isObject(*f, p + "/fog", "the ground fog")) {
    FogLayerSpec fog;
    r.onlyKeys(*f, p + "/fog", {"density", "height", "falloff"});
    r.numberMember(*f, p + "/fog", "density", true, 0.0, 1e6, "the fog's density", fog.density);
    r.numberMember(*f, p + "/fog", "height", false, -1e4, 1e4, "the layer's top in metres", fog.heightM);
    r.numberMember(*f, p + "/fog", "falloff", false, 0.001, 1e4, "a length in metres", fog.falloffM);
    d.fog = fog;
  }
  if (const json* bs = r.member(j, p, "boxes", false); bs && r.isArray(*bs, p + "/boxes", "the density boxes")) {
    for (size_t i = 0; i < bs->size(); ++i) {
      const std::string bp = p + "/boxes/" + std::to_string(i);
      const json& b = (*bs)[i];
      if (!r.isObject(b, bp, "a density box")) continue;
      DensityBoxSpec box;
      r.onlyKeys(b, bp, {"min", "max", "density"});
      r.vec3Member(b, bp, "min", true, -kMaxJsonMagnitude, kMaxJsonMagnitude, "a corner in metres", box.minM);
      r.vec3Member(b, bp, "max", true, -kMaxJsonMagnitude, kMaxJsonMagnitude, "a corner in metres", box.maxM);
      r.numberMember(b, bp, "density", true, 0.0, 1e6, "the box's density", box.density);
      d.boxes.push_back(box);
    }
  }
  if (const json* hs = r.member(j, p, "hazers", false); hs && r.isArray(*hs, p + "/hazers", "the hazers"))
    readHazers(r, *hs, p, d);
  at.density = d;
}

void readSun(JsonProblems& r, const json& j, const std::string& p, AtmosphereDef& at) {
  if (!r.isObject(j, p, "the sun")) return;
  r.onlyKeys(j, p, {"enabled", "azimuth", "elevation", "illuminance_lux", "color"});
  SunDef sun;
  if (const json* e = r.member(j, p, "enabled", false)) {
    if (e->is_boolean())
      sun.enabled = e->get<bool>();
    else
      r.problem(p + "/enabled", std::string("expected true or false, got ") + jsonKind(*e));
  }
  r.numberMember(j, p, "azimuth", false, -360.0, 360.0, "an azimuth in degrees from north (-Z) towards east (+X)",
                 sun.azimuthDeg);
  r.numberMember(j, p, "elevation", false, -90.0, 90.0, "an elevation in degrees above the horizon", sun.elevationDeg);
  r.numberMember(j, p, "illuminance_lux", false, 0.0, 1e6, "an illuminance in lux", sun.illuminanceLux);
  if (const json* c = r.member(j, p, "color", false)) greyOrRgb(r, *c, p + "/color", "the sun's colour", sun.color);
  at.sun = sun;
}

// atmosphere.particles (docs/shows.md, "Particles").
void readParticles(JsonProblems& r, const json& j, const std::string& p, AtmosphereDef& at) {
  if (!r.isObject(j, p, "the particles")) return;
  r.onlyKeys(j, p, {"enabled", "density", "size_um", "size_sigma", "brightness", "seed"});
  ParticleSettings ps;
  if (const json* e = r.member(j, p, "enabled", false)) {
    if (e->is_boolean())
      ps.enabled = e->get<bool>();
    else
      r.problem(p + "/enabled", std::string("expected true or false, got ") + jsonKind(*e));
  }
  r.numberMember(j, p, "density", false, 0.0, kMaxParticleDensityPerM3, "particles per m^3", ps.densityPerM3);
  r.numberMember(j, p, "size_um", false, 1.0, 1000.0, "a median diameter in micrometres", ps.sizeUm);
  r.numberMember(j, p, "size_sigma", false, 0.0, 2.0, "the standard deviation of ln(diameter)", ps.sizeSigma);
  r.numberMember(j, p, "brightness", false, 0.0, 1e7, "a display gain", ps.brightness);
  if (r.member(j, p, "seed", false)) {
    int seed = 1;
    if (r.integer(j["seed"], p + "/seed", 0, 2147483647, "a seed 0..2147483647", seed)) ps.seed = static_cast<uint32_t>(seed);
  }
  at.particles = ps;
}

void readAtmosphere(JsonProblems& r, const json& root, Show& show) {
  const json* a = r.member(root, "", "atmosphere", false);
  if (!a || !r.isObject(*a, "/atmosphere", "the atmosphere")) return;
  const std::string p = "/atmosphere";
  AtmosphereDef& at = show.atmosphere;
  r.onlyKeys(*a, p, {"scattering", "absorption", "phase", "g", "ambient", "background", "density", "shadows", "sun", "particles"});
  r.numberMember(*a, p, "scattering", false, 0.0, kInf, "a scattering coefficient in 1/m", at.scattering);
  r.numberMember(*a, p, "absorption", false, 0.0, kInf, "an absorption coefficient in 1/m", at.absorption);
  std::string phase;
  if (r.stringMember(*a, p, "phase", false, "a phase function", phase, true)) {
    if (phase == "hazy" || phase == "isotropic" || phase == "hg")
      at.phase = phase;
    else
      r.problem(p + "/phase", "unknown phase function \"" + phase + "\"; expected hazy, isotropic or hg");
  }
  r.numberMember(*a, p, "g", false, -0.99, 0.99, "the Henyey-Greenstein g", at.g);
  if (const json* j = r.member(*a, p, "ambient", false)) greyOrRgb(r, *j, p + "/ambient", "the ambient light", at.ambient);
  if (const json* j = r.member(*a, p, "background", false))
    greyOrRgb(r, *j, p + "/background", "the background radiance", at.background);
  if (const json* j = r.member(*a, p, "density", false)) readDensity(r, *j, p + "/density", at);
  std::string shadows;
  if (r.stringMember(*a, p, "shadows", false, "a shadow kind", shadows, true)) {
    if (shadows == "soft" || shadows == "hard")
      at.softShadows = shadows == "soft";
    else
      r.problem(p + "/shadows", "unknown shadow kind \"" + shadows + "\"; expected soft or hard");
  }
  if (const json* j = r.member(*a, p, "sun", false)) readSun(r, *j, p + "/sun", at);
  if (const json* j = r.member(*a, p, "particles", false)) readParticles(r, *j, p + "/particles", at);
}

void readCameras(JsonProblems& r, const json& root, Show& show) {
  const json* cams = r.member(root, "", "cameras", false);
  if (!cams || !r.isArray(*cams, "/cameras", "the camera list")) return;
  for (size_t i = 0; i < cams->size(); ++i) {
    const json& c = (*cams)[i];
    const std::string p = "/cameras/" + std::to_string(i);
    if (!r.isObject(c, p, "a camera")) continue;
    r.onlyKeys(c, p, {"name", "position", "target", "up", "fov_y", "far", "exposure"});
    CameraDef cam;
    r.stringMember(c, p, "name", true, "the camera's name", cam.name, true);
    r.vec3Member(c, p, "position", true, -kInf, kInf, "a position in metres", cam.position);
    r.vec3Member(c, p, "target", true, -kInf, kInf, "a target point in metres", cam.target);
    r.vec3Member(c, p, "up", false, -kInf, kInf, "an up vector", cam.up);
    if (const json* fov = r.member(c, p, "fov_y", true)) {
      double v = 0;
      if (r.number(*fov, p + "/fov_y", 1.0, 179.0, "a vertical field of view in degrees", v))
        cam.fovYDeg = static_cast<float>(v);
    }
    if (const json* far = r.member(c, p, "far", false)) {
      double v = 0;
      if (r.number(*far, p + "/far", 0.01, kInf, "a far distance in metres", v)) cam.farM = static_cast<float>(v);
    }
    if (const json* e = r.member(c, p, "exposure", false); e && r.isObject(*e, p + "/exposure", "the exposure")) {
      const std::string ep = p + "/exposure";
      r.onlyKeys(*e, ep, {"mode", "ev"});
      CameraExposureDef ex;
      std::string mode;
      if (r.stringMember(*e, ep, "mode", true, "an exposure mode", mode, true)) {
        if (mode == "manual" || mode == "auto")
          ex.manual = mode == "manual";
        else
          r.problem(ep + "/mode", "unknown exposure mode \"" + mode + "\"; expected auto or manual");
      }
      r.numberMember(*e, ep, "ev", false, -100.0, 100.0, "an exposure in EV", ex.ev);
      cam.exposure = ex;
    }
    show.cameras.push_back(cam);
  }
}

void readProfiles(JsonProblems& r, const json& root, Show& show) {
  const json* profs = r.member(root, "", "profiles", true);
  if (!profs || !r.isObject(*profs, "/profiles", "profiles by name")) return;
  for (auto it = profs->begin(); it != profs->end(); ++it) {
    const std::string p = "/profiles/" + pointerToken(it.key());
    ProfileRef ref;
    if (it.key().empty()) {
      r.problem(p, "expected a profile name, got an empty string");
      continue;
    }
    if (it->is_string()) {
      if (!r.string(*it, p, "the path of a profile file", ref.path, true)) continue;
    } else if (it->is_object()) {
      auto in = it->find("inline");
      if (it->size() == 1 && in != it->end()) {
        if (!r.isObject(*in, p + "/inline", "an inline profile")) continue;
        ref.inlineObject = *in;
        ref.inlineWrapped = true;
      } else {
        ref.inlineObject = *it;
      }
    } else {
      r.problem(p, std::string("expected the path of a profile file (a string) or an inline profile "
                               "(an object), got ") + jsonKind(*it));
      continue;
    }
    show.profiles[it.key()] = std::move(ref);
  }
}

void readFixtures(JsonProblems& r, const json& root, Show& show) {
  const json* fix = r.member(root, "", "fixtures", true);
  if (!fix || !r.isArray(*fix, "/fixtures", "the fixture list")) return;
  for (size_t i = 0; i < fix->size(); ++i) {
    const json& f = (*fix)[i];
    const std::string p = "/fixtures/" + std::to_string(i);
    FixtureDef d;
    if (r.isObject(f, p, "a fixture")) {
      r.onlyKeys(f, p, {"id", "name", "profile", "mode", "position", "rotation", "patch", "uuid"});
      if (const json* id = r.member(f, p, "id", true)) r.integer(*id, p + "/id", 1, INT_MAX, "a fixture id", d.id);
      r.stringMember(f, p, "name", false, "the fixture's name", d.name, false);
      r.stringMember(f, p, "profile", true, "the name of a profile in /profiles", d.profile, true);
      r.stringMember(f, p, "mode", false, "the name of a DMX mode of the profile", d.mode, true);
      r.vec3Member(f, p, "position", false, -kInf, kInf, "a position in metres", d.position);
      r.vec3Member(f, p, "rotation", false, -kInf, kInf, "a rotation in degrees", d.rotationDeg);
      if (r.stringMember(f, p, "uuid", false, "an MVR uuid (8-4-4-4-12 hexadecimal digits)", d.mvrUuid, true) &&
          !d.mvrUuid.empty() && !isMvrUuid(d.mvrUuid)) {
        r.problem(p + "/uuid", "expected an MVR uuid (8-4-4-4-12 hexadecimal digits, e.g. "
                               "\"2e149740-6a41-bc43-bd59-8968781b11b9\"), got \"" + d.mvrUuid.substr(0, 60) + "\"");
        d.mvrUuid.clear();
      }
      const json* patch = r.member(f, p, "patch", false);
      if (patch && !patch->is_null() && r.isObject(*patch, p + "/patch", "a DMX patch")) {
        r.onlyKeys(*patch, p + "/patch", {"universe", "address"});
        Patch pa;
        bool ok = true;
        if (const json* u = r.member(*patch, p + "/patch", "universe", true))
          ok = r.integer(*u, p + "/patch/universe", 1, 65535, "a universe (counted from 1)", pa.universe) && ok;
        else
          ok = false;
        if (const json* a = r.member(*patch, p + "/patch", "address", true))
          ok = r.integer(*a, p + "/patch/address", 1, 512, "a DMX address", pa.address) && ok;
        else
          ok = false;
        if (ok) d.patch = pa;
      }
    }
    // Kept even when broken, so that later pointers (/fixtures/N) keep their index.
    show.fixtures.push_back(d);
  }
}

bool readFixtureKey(JsonProblems& r, const std::string& key, const std::string& p, int& id) {
  long long v = 0;
  auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), v);
  bool canonical = !key.empty() && key[0] != '0' && ec == std::errc() && end == key.data() + key.size();
  if (!canonical || v < 1 || v > INT_MAX) {
    r.problem(p, "expected a fixture id (a positive whole number written as a string, like \"101\"), got \"" +
                     key + "\"");
    return false;
  }
  id = static_cast<int>(v);
  return true;
}

// A key counting from 1 ("1" .. "4096", no leading zero), as cells and hazers are numbered; 0
// when it is not one.
int countedKey(const std::string& key) {
  long long n = 0;
  auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), n);
  if (key.empty() || key[0] == '0' || ec != std::errc() || end != key.data() + key.size() || n < 1 || n > 4096) return 0;
  return static_cast<int>(n);
}

// "cells": {"1": {"intensity", "color"}, ...}: cells counted from 1 (docs/cells.md).
void readCellValues(JsonProblems& r, const json& cells, const std::string& cp, CueValues& v) {
  if (!r.isObject(cells, cp, "values by cell number")) return;
  for (auto it = cells.begin(); it != cells.end(); ++it) {
    const std::string p = cp + "/" + pointerToken(it.key());
    const int n = countedKey(it.key());
    if (n == 0) {
      r.problem(p, "expected a cell number (1 to 4096, written as a string like \"3\"), got \"" + it.key() + "\"");
      continue;
    }
    const json& c = *it;
    if (!r.isObject(c, p, "cell values")) continue;
    r.onlyKeys(c, p, {"intensity", "color"});
    CellValues cv;
    double x = 0;
    if (const json* j = r.member(c, p, "intensity", false))
      if (r.number(*j, p + "/intensity", 0.0, 1.0, "an intensity", x)) cv.intensity = static_cast<float>(x);
    glm::vec3 col{1.0f};
    if (r.vec3Member(c, p, "color", false, 0.0, 1.0, "a colour component", col)) cv.color = col;
    v.cells[static_cast<int>(n - 1)] = cv;
  }
}

// frost, focus, prism, prism_rotation, blades, blade_rotation, shutter (docs/show-format.md).
void readOpticsValues(JsonProblems& r, const json& a, const std::string& p, CueValues& v) {
  double x = 0;
  if (const json* j = r.member(a, p, "frost", false))
    if (r.number(*j, p + "/frost", 0.0, 1.0, "a frost (0..1)", x)) v.frost = static_cast<float>(x);
  if (const json* j = r.member(a, p, "focus", false))
    if (r.number(*j, p + "/focus", 0.0, 1.0, "a focus (0..1 over the lens's range)", x)) v.gateFocus = static_cast<float>(x);
  if (const json* j = r.member(a, p, "prism_rotation", false))
    if (r.number(*j, p + "/prism_rotation", -kInf, kInf, "a prism rotation in degrees", x)) v.prismRotationDeg = static_cast<float>(x);
  if (const json* j = r.member(a, p, "blade_rotation", false))
    if (r.number(*j, p + "/blade_rotation", -kInf, kInf, "a blade rotation in degrees", x)) v.bladeRotationDeg = static_cast<float>(x);
  std::string prism;
  if (r.stringMember(a, p, "prism", false, "a prism name", prism, true)) v.prism = prism;
  if (const json* j = r.member(a, p, "blades", false)) {
    const std::string bp = p + "/blades";
    if (!j->is_array() || j->size() != 4) {
      r.problem(bp, std::string("expected four [a, b] pairs (one per blade), got ") +
                        (j->is_array() ? "an array of " + std::to_string(j->size()) : std::string(jsonKind(*j))));
    } else {
      BladeInsertions blades{};
      bool ok = true;
      for (size_t k = 0; k < 4; ++k) {
        const json& e = (*j)[k];
        const std::string ep = bp + "/" + std::to_string(k);
        if (!e.is_array() || e.size() != 2) {
          r.problem(ep, std::string("expected the insertions of the blade's two ends, [a, b], got ") +
                            (e.is_array() ? "an array of " + std::to_string(e.size()) : std::string(jsonKind(e))));
          ok = false;
          continue;
        }
        for (size_t end = 0; end < 2; ++end) {
          if (r.number(e[end], ep + "/" + std::to_string(end), 0.0, 1.0, "a blade insertion", x))
            blades[k][static_cast<int>(end)] = static_cast<float>(x);
          else
            ok = false;
        }
      }
      if (ok) v.blades = blades;
    }
  }
  if (const json* j = r.member(a, p, "shutter", false)) {
    const std::string sp = p + "/shutter";
    if (j->is_string()) {
      const std::string mode = j->get<std::string>();
      if (mode == "open" || mode == "closed")
        v.shutter = Shutter{mode == "open" ? ShutterMode::Open : ShutterMode::Closed, 0.0f, 0.5f};
      else
        r.problem(sp, "expected \"open\", \"closed\" or {\"strobe_hz\": f, \"duty\": d}, got \"" + mode + "\"");
    } else if (r.isObject(*j, sp, "a shutter: \"open\", \"closed\" or {\"strobe_hz\": f, \"duty\": d}")) {
      r.onlyKeys(*j, sp, {"strobe_hz", "duty", "mode"});
      Shutter sh{ShutterMode::Strobe, 0.0f, 0.5f};
      bool ok = r.numberMember(*j, sp, "strobe_hz", true, kMinStrobeHz, kMaxStrobeHz, "a strobe rate in Hz", sh.rateHz);
      if (const json* d = r.member(*j, sp, "duty", false)) {
        if (r.number(*d, sp + "/duty", 0.0, 1.0, "a duty cycle", x) && x > 0.0)
          sh.duty = static_cast<float>(x);
        else {
          if (x <= 0.0 && d->is_number()) r.problem(sp + "/duty", "a duty of 0 never opens; expected a duty above 0 up to 1, or \"closed\"");
          ok = false;
        }
      }
      std::string mode;
      if (r.stringMember(*j, sp, "mode", false, "a strobe mode", mode, true)) {
        auto m = shutterModeFromName(mode);
        if (m && *m != ShutterMode::Open && *m != ShutterMode::Closed)
          sh.mode = *m;
        else {
          r.problem(sp + "/mode", "unknown strobe mode \"" + mode + "\"; expected strobe, pulse, pulse_open, pulse_close or random");
          ok = false;
        }
      }
      if (ok) v.shutter = sh;
    }
  }
}

// "palettes": {"position": "Centre", "color": "Red", ...}: one palette name per kind.
void readPaletteRefs(JsonProblems& r, const json& j, const std::string& p, PaletteRefs& refs) {
  if (!r.isObject(j, p, "palette names by kind")) return;
  r.onlyKeys(j, p, {"all", "position", "color", "beam"});
  r.stringMember(j, p, "all", false, "the name of an \"all\" palette", refs.all, true);
  r.stringMember(j, p, "position", false, "the name of a position palette", refs.position, true);
  r.stringMember(j, p, "color", false, "the name of a colour palette", refs.color, true);
  r.stringMember(j, p, "beam", false, "the name of a beam palette", refs.beam, true);
}

// One fixture's (or group's) attribute values; `palettes` only where references are allowed
// (cues: yes; palettes themselves: no, so references cannot form a cycle).
void readAttributeValues(JsonProblems& r, const json& a, const std::string& p, CueValues& v, bool allowPalettes) {
  if (allowPalettes)
    r.onlyKeys(a, p, {"intensity", "pan", "tilt", "color", "zoom", "gobo", "gobo_rotation", "gobo2", "gobo2_rotation",
                      "color2", "cto",
                      "gobo_spin", "gobo2_spin", "animation", "animation_rotation", "animation_spin", "iris", "frost", "focus",
                      "prism", "prism_rotation", "prism_spin", "blades",
                      "blade_rotation", "shutter", "cells", "palettes"});
  else
    r.onlyKeys(a, p, {"intensity", "pan", "tilt", "color", "zoom", "gobo", "gobo_rotation", "gobo2", "gobo2_rotation",
                      "color2", "cto",
                      "gobo_spin", "gobo2_spin", "animation", "animation_rotation", "animation_spin", "iris", "frost", "focus",
                      "prism", "prism_rotation", "prism_spin", "blades",
                      "blade_rotation", "shutter", "cells"});
  double x = 0;
  auto num = [&](const char* key, double lo, double hi, const char* what, std::optional<float>& out) {
    if (const json* j = r.member(a, p, key, false))
      if (r.number(*j, p + "/" + key, lo, hi, what, x)) out = static_cast<float>(x);
  };
  num("intensity", 0.0, 1.0, "an intensity", v.intensity);
  num("pan", -kInf, kInf, "a pan angle in degrees", v.panDeg);
  num("tilt", -kInf, kInf, "a tilt angle in degrees", v.tiltDeg);
  num("zoom", 0.1, 179.0, "a zoom (field angle) in degrees", v.zoomDeg);
  num("gobo_rotation", -kInf, kInf, "a gobo rotation in degrees", v.goboRotationDeg);
  num("gobo2_rotation", -kInf, kInf, "a gobo rotation in degrees", v.gobo2RotationDeg);
  num("gobo_spin", -kMaxSpinDegS, kMaxSpinDegS, "a gobo spin in degrees per second", v.goboSpinDegS);
  num("gobo2_spin", -kMaxSpinDegS, kMaxSpinDegS, "a gobo spin in degrees per second", v.gobo2SpinDegS);
  num("prism_spin", -kMaxSpinDegS, kMaxSpinDegS, "a prism spin in degrees per second", v.prismSpinDegS);
  num("animation_rotation", -kInf, kInf, "an animation wheel angle in degrees", v.animationRotationDeg);
  num("animation_spin", -kMaxSpinDegS, kMaxSpinDegS, "an animation wheel spin in degrees per second", v.animationSpinDegS);
  num("cto", -kMaxCtoMired, kMaxCtoMired, "a colour temperature shift in mired", v.ctoMired);
  num("iris", 0.0, 1.0, "an iris", v.iris);
  glm::vec3 c{1.0f};
  if (r.vec3Member(a, p, "color", false, 0.0, 1.0, "a colour component", c)) v.color = c;
  std::string gobo;
  if (r.stringMember(a, p, "gobo", false, "a gobo slot name", gobo, true)) v.gobo = gobo;
  if (r.stringMember(a, p, "gobo2", false, "a slot name of the second gobo wheel", gobo, true)) v.gobo2 = gobo;
  if (r.stringMember(a, p, "color2", false, "a slot name of the second colour wheel", gobo, true)) v.color2 = gobo;
  if (r.stringMember(a, p, "animation", false, "a slot name of the animation wheel", gobo, true)) v.animation = gobo;
  if (const json* cells = r.member(a, p, "cells", false)) readCellValues(r, *cells, p + "/cells", v);
  readOpticsValues(r, a, p, v);
  if (allowPalettes)
    if (const json* refs = r.member(a, p, "palettes", false)) readPaletteRefs(r, *refs, p + "/palettes", v.palettes);
}

// Values keyed by fixture id, as cues and palettes hold them.
void readFixtureValues(JsonProblems& r, const json& vals, const std::string& vp, std::map<int, CueValues>& out,
                       bool allowPalettes) {
  if (!r.isObject(vals, vp, "values by fixture id")) return;
  for (auto it = vals.begin(); it != vals.end(); ++it) {
    const std::string p = vp + "/" + pointerToken(it.key());
    int id = 0;
    if (!readFixtureKey(r, it.key(), p, id)) continue;
    if (!r.isObject(*it, p, "attribute values")) continue;
    CueValues v;
    readAttributeValues(r, *it, p, v, allowPalettes);
    out[id] = v;
  }
}

void readGroups(JsonProblems& r, const json& root, Show& show) {
  const json* groups = r.member(root, "", "groups", false);
  if (!groups || !r.isArray(*groups, "/groups", "the groups")) return;
  for (size_t i = 0; i < groups->size(); ++i) {
    const json& g = (*groups)[i];
    const std::string p = "/groups/" + std::to_string(i);
    GroupDef d;
    if (r.isObject(g, p, "a group")) {
      r.onlyKeys(g, p, {"name", "fixtures"});
      r.stringMember(g, p, "name", true, "the group's name", d.name, true);
      if (const json* f = r.member(g, p, "fixtures", true); f && r.isArray(*f, p + "/fixtures", "the group's fixture ids"))
        for (size_t k = 0; k < f->size(); ++k) {
          int id = 0;
          if (r.integer((*f)[k], p + "/fixtures/" + std::to_string(k), 1, INT_MAX, "a fixture id", id))
            d.fixtures.push_back(id);
        }
    }
    show.groups.push_back(std::move(d));  // kept when broken, so /groups/N keeps its index
  }
}

void readPalettes(JsonProblems& r, const json& root, Show& show) {
  const json* pals = r.member(root, "", "palettes", false);
  if (!pals || !r.isArray(*pals, "/palettes", "the palettes")) return;
  for (size_t i = 0; i < pals->size(); ++i) {
    const json& pj = (*pals)[i];
    const std::string p = "/palettes/" + std::to_string(i);
    PaletteDef d;
    if (r.isObject(pj, p, "a palette")) {
      r.onlyKeys(pj, p, {"name", "kind", "groups", "fixtures"});
      r.stringMember(pj, p, "name", true, "the palette's name", d.name, true);
      std::string kind;
      if (r.stringMember(pj, p, "kind", true, "a palette kind", kind, true)) {
        if (auto k = paletteKindFromName(kind))
          d.kind = *k;
        else
          r.problem(p + "/kind", "unknown palette kind \"" + kind + "\"; expected position, color, beam or all");
      }
      if (const json* g = r.member(pj, p, "groups", false); g && r.isObject(*g, p + "/groups", "values by group name"))
        for (auto it = g->begin(); it != g->end(); ++it) {
          const std::string gp = p + "/groups/" + pointerToken(it.key());
          if (!r.isObject(*it, gp, "attribute values")) continue;
          CueValues v;
          readAttributeValues(r, *it, gp, v, false);
          d.groups[it.key()] = v;
        }
      if (const json* f = r.member(pj, p, "fixtures", false)) readFixtureValues(r, *f, p + "/fixtures", d.fixtures, false);
    }
    show.palettes.push_back(std::move(d));
  }
}

// "timing": {"up", "down", "position", "color", "beam": {"delay", "fade"}, "fan": {"group",
// "delay", "fade"}, "curve": "linear" | "s-curve"} (docs/show-format.md, "Timing").
void readTiming(JsonProblems& r, const json& j, const std::string& p, CueTimingDef& t) {
  if (!r.isObject(j, p, "the cue's timing")) return;
  r.onlyKeys(j, p, {"up", "down", "position", "color", "beam", "fan", "curve"});
  double x = 0;
  auto part = [&](const char* key, std::optional<PartTiming>& out) {
    const json* pj = r.member(j, p, key, false);
    const std::string pp = p + "/" + key;
    if (!pj || !r.isObject(*pj, pp, "a delay and fade")) return;
    r.onlyKeys(*pj, pp, {"delay", "fade"});
    PartTiming pt;
    if (const json* d = r.member(*pj, pp, "delay", false))
      if (r.number(*d, pp + "/delay", 0.0, kInf, "a delay in seconds", x)) pt.delayS = x;
    if (const json* f = r.member(*pj, pp, "fade", false))
      if (r.number(*f, pp + "/fade", 0.0, kInf, "a fade time in seconds", x)) pt.fadeS = x;
    out = pt;
  };
  part("up", t.up);
  part("down", t.down);
  part("position", t.position);
  part("color", t.color);
  part("beam", t.beam);
  if (const json* f = r.member(j, p, "fan", false); f && r.isObject(*f, p + "/fan", "a fan across a group")) {
    const std::string fp = p + "/fan";
    r.onlyKeys(*f, fp, {"group", "delay", "fade"});
    FanTiming fan;
    r.stringMember(*f, fp, "group", true, "the name of a group in /groups", fan.group, true);
    if (const json* d = r.member(*f, fp, "delay", false))
      if (r.number(*d, fp + "/delay", 0.0, kInf, "a delay step in seconds per fixture", x)) fan.delayStepS = x;
    if (const json* d = r.member(*f, fp, "fade", false))
      if (r.number(*d, fp + "/fade", 0.0, kInf, "a fade step in seconds per fixture", x)) fan.fadeStepS = x;
    t.fan = fan;
  }
  std::string curve;
  if (r.stringMember(j, p, "curve", false, "a fade curve", curve, true)) {
    if (curve == "linear" || curve == "s-curve")
      t.curve = curve == "linear" ? FadeCurve::Linear : FadeCurve::SCurve;
    else
      r.problem(p + "/curve", "unknown fade curve \"" + curve + "\"; expected linear or s-curve");
  }
}

constexpr const char* kEffectAttributes[] = {"intensity", "pan", "tilt", "zoom", "iris", "frost", "gobo_rotation",
                                             "gobo2_rotation", "prism_rotation", "color"};
constexpr size_t kMaxEffectColors = 64;

// "effects": [{"shape", "attribute", "group", "rate", "size", "phase", "spread", "seed", "colors"}]
// "hazers": {"1": {"output", "fan"}}: hazers of atmosphere.density counted from 1 (docs/shows.md,
// "Hazers in cues"); the atmosphere is read before the cue lists.
void readHazerLevels(JsonProblems& r, const json& j, const std::string& hp, const Show& show, std::map<int, HazerCueDef>& out) {
  if (!r.isObject(j, hp, "hazer levels by hazer number")) return;
  const size_t count = show.atmosphere.density ? show.atmosphere.density->hazers.size() : 0;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string p = hp + "/" + pointerToken(it.key());
    const int n = countedKey(it.key());
    if (n == 0) {
      r.problem(p, "expected a hazer number (from 1, written as a string like \"2\"), got \"" + it.key() + "\"");
      continue;
    }
    if (static_cast<size_t>(n) > count) {
      r.problem(p, "hazer " + it.key() + " does not exist: atmosphere.density has " + std::to_string(count) +
                       (count == 1 ? " hazer" : " hazers"));
      continue;
    }
    const json& h = *it;
    if (!r.isObject(h, p, "a hazer's levels")) continue;
    r.onlyKeys(h, p, {"output", "fan"});
    HazerCueDef d;
    double x = 0;
    if (const json* v = r.member(h, p, "output", false))
      if (r.number(*v, p + "/output", 0.0, 1.0, "an output level (0..1 of the hazer's output)", x)) d.output = static_cast<float>(x);
    if (const json* v = r.member(h, p, "fan", false))
      if (r.number(*v, p + "/fan", 0.0, 1.0, "a fan level (0..1 of the fan's speed)", x)) d.fan = static_cast<float>(x);
    out[static_cast<int>(n)] = d;
  }
}

void readEffects(JsonProblems& r, const json& j, const std::string& ep, std::vector<EffectDef>& out) {
  if (!r.isArray(j, ep, "the cue's effects")) return;
  for (size_t i = 0; i < j.size(); ++i) {
    const json& e = j[i];
    const std::string p = ep + "/" + std::to_string(i);
    if (!r.isObject(e, p, "an effect")) continue;
    r.onlyKeys(e, p, {"shape", "attribute", "group", "rate", "size", "phase", "spread", "seed", "colors"});
    EffectDef d;
    bool ok = true;
    std::string shape;
    if (r.stringMember(e, p, "shape", true, "an effect shape", shape, true)) {
      const std::pair<const char*, EffectShape> shapes[] = {{"sine", EffectShape::Sine}, {"circle", EffectShape::Circle},
                                                            {"square", EffectShape::Square}, {"ramp", EffectShape::Ramp},
                                                            {"random", EffectShape::Random}};
      bool known = false;
      for (const auto& [name, s] : shapes)
        if (shape == name) {
          known = true;
          d.shape = s;
        }
      if (!known) {
        r.problem(p + "/shape", "unknown effect shape \"" + shape + "\"; expected sine, circle, square, ramp or random");
        ok = false;
      }
    } else {
      ok = false;
    }
    if (d.shape == EffectShape::Circle) {
      d.attribute = "position";
      if (const json* a = r.member(e, p, "attribute", false); a && !(a->is_string() && *a == "position"))
        r.problem(p + "/attribute", "a circle moves pan and tilt together; expected \"position\" or no attribute");
    } else if (ok && r.stringMember(e, p, "attribute", true, "the attribute the effect moves", d.attribute, true)) {
      bool known = false;
      for (const char* a : kEffectAttributes) known = known || d.attribute == a;
      if (!known)
        r.problem(p + "/attribute", "an effect cannot move \"" + d.attribute + "\"; expected intensity, pan, tilt, zoom, "
                                    "iris, frost, gobo_rotation, gobo2_rotation, prism_rotation or color (or a circle on position)");
    }
    const json* colors = r.member(e, p, "colors", false);
    if (d.attribute == "color") {
      if (!colors) {
        r.problem(p + "/colors", "a colour effect needs \"colors\": the [r, g, b] colours it runs through, at least two");
      } else if (r.isArray(*colors, p + "/colors", "the effect's colours")) {
        if (colors->size() < 2 || colors->size() > kMaxEffectColors)
          r.problem(p + "/colors", "expected 2 to " + std::to_string(kMaxEffectColors) + " colours, got " +
                                       std::to_string(colors->size()));
        for (size_t c = 0; c < colors->size() && c < kMaxEffectColors; ++c) {
          glm::vec3 rgb(0.0f);
          if (r.vec3((*colors)[c], p + "/colors/" + std::to_string(c), 0.0, 1.0, "an [r, g, b] colour, each 0..1", rgb))
            d.colors.push_back(rgb);
        }
      }
    } else if (colors) {
      r.problem(p + "/colors", "\"colors\" belongs to a colour effect (attribute \"color\")");
    }
    r.stringMember(e, p, "group", true, "the name of a group in /groups", d.group, true);
    double x = 0;
    if (const json* v = r.member(e, p, "rate", true))
      if (r.number(*v, p + "/rate", -100.0, 100.0, "a rate in cycles per second", x)) d.rateHz = x;
    if (const json* v = r.member(e, p, "size", true))
      if (r.number(*v, p + "/size", 0.0, d.attribute == "color" ? 1.0 : 360.0,
                   d.attribute == "color" ? "a colour effect's depth" : "a size in the attribute's unit", x))
        d.size = x;
    if (const json* v = r.member(e, p, "phase", false))
      if (r.number(*v, p + "/phase", -3600.0, 3600.0, "a phase in degrees", x)) d.phaseDeg = x;
    if (const json* v = r.member(e, p, "spread", false))
      if (r.number(*v, p + "/spread", -3600.0, 3600.0, "a phase spread across the group in degrees", x)) d.spreadDeg = x;
    if (const json* v = r.member(e, p, "seed", false)) {
      int seed = 0;
      if (r.integer(*v, p + "/seed", 0, INT_MAX, "a random seed", seed)) d.seed = static_cast<std::uint32_t>(seed);
    }
    out.push_back(d);
  }
}

void readCueLists(JsonProblems& r, const json& root, Show& show) {
  const json* lists = r.member(root, "", "cue_lists", false);
  if (!lists || !r.isArray(*lists, "/cue_lists", "the cue lists")) return;
  for (size_t li = 0; li < lists->size(); ++li) {
    const json& l = (*lists)[li];
    const std::string lp = "/cue_lists/" + std::to_string(li);
    CueList list;
    if (r.isObject(l, lp, "a cue list")) {
      r.onlyKeys(l, lp, {"name", "cues"});
      r.stringMember(l, lp, "name", true, "the cue list's name", list.name, true);
      const json* cues = r.member(l, lp, "cues", true);
      if (cues && r.isArray(*cues, lp + "/cues", "the cues")) {
        for (size_t ci = 0; ci < cues->size(); ++ci) {
          const json& c = (*cues)[ci];
          const std::string p = lp + "/cues/" + std::to_string(ci);
          Cue cue;
          if (r.isObject(c, p, "a cue")) {
            r.onlyKeys(c, p, {"number", "label", "fade", "delay", "follow", "timecode", "timing", "effects", "hazers",
                              "values"});
            if (r.stringMember(c, p, "number", true, "a cue number (a decimal string like \"1.5\")", cue.number, true) &&
                !isCueNumber(cue.number)) {
              r.problem(p + "/number", "expected a cue number: digits with an optional decimal part, like \"1\" "
                                       "or \"1.5\", got \"" + cue.number + "\"");
              cue.number.clear();
            }
            r.stringMember(c, p, "label", false, "a label", cue.label, false);
            double t = 0;
            if (const json* j = r.member(c, p, "fade", false))
              if (r.number(*j, p + "/fade", 0.0, kInf, "a fade time in seconds", t)) cue.fadeS = t;
            if (const json* j = r.member(c, p, "delay", false))
              if (r.number(*j, p + "/delay", 0.0, kInf, "a delay in seconds", t)) cue.delayS = t;
            if (const json* j = r.member(c, p, "follow", false); j && !j->is_null()) {
              if (j->is_number()) {
                if (r.number(*j, p + "/follow", 0.0, kInf, "a follow time in seconds", t)) cue.followS = t;
              } else {
                r.problem(p + "/follow", std::string("expected a follow time in seconds (a number) or null, got ") +
                                             jsonKind(*j));
              }
            }
            if (r.stringMember(c, p, "timecode", false, "a timecode \"hh:mm:ss:ff\"", cue.timecode, false) &&
                !cue.timecode.empty() && !parseTimecode(cue.timecode)) {
              r.problem(p + "/timecode", "expected a timecode \"hh:mm:ss:ff\" within a day (hours 00..23, frames "
                                         "00..29), got \"" + cue.timecode + "\"");
              cue.timecode.clear();
            }
            if (const json* j = r.member(c, p, "timing", false)) readTiming(r, *j, p + "/timing", cue.timing);
            if (const json* j = r.member(c, p, "effects", false)) readEffects(r, *j, p + "/effects", cue.effects);
            if (const json* j = r.member(c, p, "hazers", false)) readHazerLevels(r, *j, p + "/hazers", show, cue.hazers);
            if (const json* j = r.member(c, p, "values", false)) readFixtureValues(r, *j, p + "/values", cue.values, true);
          }
          list.cues.push_back(std::move(cue));
        }
      }
    }
    show.cueLists.push_back(std::move(list));
  }
}

// Each step rewrites the JSON of version v into version v + 1 in place; false for a version this
// haze never knew. 1 -> 2: version 2 only added `groups` and `palettes` (both optional), so a
// version-1 document is a version-2 document as it stands.
bool migrate(json& root, int version) {
  if (version < 1 || version > kShowFormatVersion) return false;
  for (int v = version; v < kShowFormatVersion; ++v) root["version"] = v + 1;
  return true;
}

// The text as JSON, nesting limited; nullopt (and the problem) when it is not.
std::optional<json> parseShowJson(std::string_view text, JsonProblems& r) {
  try {
    json::parser_callback_t limitDepth = [](int depth, json::parse_event_t, json&) {
      if (depth > kMaxShowJsonDepth) throw TooDeep{};
      return true;
    };
    return json::parse(text.begin(), text.end(), limitDepth);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..."
    auto colon = what.find(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    r.problem(parseErrorPlace(text, e.byte), "the show is not valid JSON: " + what);
  } catch (const TooDeep&) {
    r.problem("", "the show nests JSON deeper than " + std::to_string(kMaxShowJsonDepth) +
                      " levels; a show needs a handful");
  } catch (const std::exception& e) {
    r.problem("", std::string("the show cannot be read as JSON: ") + e.what());
  }
  return std::nullopt;
}

// "version", migrated to the newest; 0 (and the problem) when the show cannot be read on.
int readVersion(JsonProblems& r, json& root) {
  int version = 0;
  const json* v = r.member(root, "", "version", true);
  if (!v || !r.integer(*v, "/version", 1, INT_MAX, "a format version", version)) return 0;
  if (version > kShowFormatVersion) {
    r.problem("/version", "this show has format version " + std::to_string(version) +
                              ", newer than this haze reads (up to " + std::to_string(kShowFormatVersion) +
                              "); open it with a newer haze");
    return 0;
  }
  if (!migrate(root, version)) {
    r.problem("/version", "unknown format version " + std::to_string(version) + "; expected " +
                              std::to_string(kShowFormatVersion));
    return 0;
  }
  return version;
}

// Cue parts that format version 1 does not have, each a problem in a version-1 file.
void refuseVersion2Cues(JsonProblems& r, const Show& show, int version) {
  if (version >= 2) return;
  for (size_t l = 0; l < show.cueLists.size(); ++l)
    for (size_t c = 0; c < show.cueLists[l].cues.size(); ++c) {
      const Cue& cue = show.cueLists[l].cues[c];
      const std::string p = "/cue_lists/" + std::to_string(l) + "/cues/" + std::to_string(c);
      const std::string need = " needs format version 2; this file says " + std::to_string(version) +
                               " (set \"version\": 2)";
      if (!cue.timing.empty()) r.problem(p + "/timing", "\"timing\"" + need);
      if (!cue.effects.empty()) r.problem(p + "/effects", "\"effects\"" + need);
      if (!cue.hazers.empty()) r.problem(p + "/hazers", "\"hazers\"" + need);
    }
}

}  // namespace

FileStamp stampOf(std::string_view bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return FileStamp{h, bytes.size()};
}

Result<std::string> readShowBytes(const std::filesystem::path& file) {
  std::error_code ec;
  auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status))
    return Error{file.string(), "", "cannot open the show: no such file"};
  if (!std::filesystem::is_regular_file(status))
    return Error{file.string(), "", "cannot open the show: not a regular file"};
  std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) return Error{file.string(), "", "cannot read the show: " + ec.message()};
  if (size > kMaxShowFileBytes)
    return Error{file.string(), "", "the show is " + std::to_string(size) + " bytes; expected at most " +
                                        std::to_string(kMaxShowFileBytes) + " (is this really a show?)"};
  std::ifstream in(file, std::ios::binary);
  if (!in) return Error{file.string(), "", "cannot open the show for reading (permissions?)"};
  std::string bytes;
  bytes.resize(static_cast<size_t>(size));
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  bytes.resize(static_cast<size_t>(in.gcount()));
  if (in.bad()) return Error{file.string(), "", "cannot read the show: read error"};
  return bytes;
}

ShowParse parseShowText(std::string_view text, const std::filesystem::path& file) {
  ShowParse out;
  out.show.file = file;
  JsonProblems r(file.string(), out.problems);
  std::optional<json> parsed = parseShowJson(text, r);
  if (!parsed) return out;
  json& root = *parsed;

  try {
    if (!root.is_object()) {
      r.problem("", std::string("expected a show (a JSON object), got ") + jsonKind(root));
      return out;
    }
    std::string format;
    if (r.stringMember(root, "", "format", true, "the format name \"haze-show\"", format, false) &&
        format != "haze-show") {
      r.problem("/format", "expected \"haze-show\", got \"" + format +
                               "\"" + (format == "haze-fixture" ? " (this is a fixture profile, not a show)" : ""));
      return out;
    }
    const int version = readVersion(r, root);
    if (version == 0) return out;
    out.show.fileVersion = version;
    if (version < 2)
      for (const char* key : {"groups", "palettes"})
        if (root.contains(key))
          r.problem(std::string("/") + key, std::string("\"") + key + "\" needs format version 2; this file says " +
                                                std::to_string(version) + " (set \"version\": 2)");
    r.onlyKeys(root, "", {"format", "version", "venue", "mvr", "atmosphere", "cameras", "profiles", "fixtures", "groups",
                          "palettes", "cue_lists", "default_fade"});
    if (const json* fade = r.member(root, "", "default_fade", false))
      r.number(*fade, "/default_fade", 0.0, kMaxDefaultFadeS, "a fade in seconds (0..3600)", out.show.defaultFadeS);
    readVenue(r, root, out.show);
    readMvrSource(r, root, out.show);
    readAtmosphere(r, root, out.show);
    readCameras(r, root, out.show);
    readProfiles(r, root, out.show);
    readFixtures(r, root, out.show);
    readGroups(r, root, out.show);
    readPalettes(r, root, out.show);
    readCueLists(r, root, out.show);
    refuseVersion2Cues(r, out.show, version);
  } catch (const std::exception& e) {
    // Every access above checks types first; this is a last guard so nothing escapes the library.
    r.problem("", std::string("the show cannot be read: ") + e.what());
  }
  return out;
}

Result<Show> loadShow(const std::filesystem::path& file) {
  auto bytes = readShowBytes(file);
  if (!bytes) return bytes.error();
  ShowParse parse = parseShowText(*bytes, file);
  // A reference that names nothing would play as nothing, in silence: refuse it here as well.
  if (parse.problems.empty()) parse.problems = checkGroupsAndPalettes(parse.show);
  if (!parse.problems.empty()) {
    Error first = parse.problems.front();
    if (parse.problems.size() > 1)
      first.message += " (and " + std::to_string(parse.problems.size() - 1) +
                       " more problems: haze validate lists them all)";
    return first;
  }
  parse.show.stamp = stampOf(*bytes);
  return std::move(parse.show);
}

}  // namespace haze
