#include "shows/frame/frame_builder.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

#include "shows/frame/cell_merge.h"
#include "shows/scene/physics.h"

namespace haze {
namespace {

// Each --cells mode with its name; the first is what an unknown name means.
constexpr std::pair<const char*, CellBeams> kCellBeams[] = {
    {"auto", CellBeams::Auto}, {"separate", CellBeams::Separate}, {"merged", CellBeams::Merged}};

// Cache keys: equal keys promise equal shadow maps (pose) and light maps (optics) to the
// renderer. Dimmer and colour are not in the light map, so fades of them never re-bake it.
uint64_t hashBytes(uint64_t h, const void* data, size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;  // FNV-1a
  return h;
}
template <class T>
uint64_t hashValue(uint64_t h, const T& v) {
  return hashBytes(h, &v, sizeof(T));
}
constexpr uint64_t kFnvBasis = 14695981039346656037ull;

}  // namespace

CameraState cameraState(const CameraDef& def) {
  CameraState c;
  c.position = def.position;
  c.target = def.target;
  c.up = def.up;
  c.fovYDeg = def.fovYDeg;
  c.farM = def.farM;
  return c;
}

MediumState mediumState(const AtmosphereDef& def) {
  MediumState m;
  m.scattering = def.scattering;
  m.absorption = def.absorption;
  m.phase = def.phase == "isotropic" ? Phase::Isotropic : def.phase == "hg" ? Phase::HenyeyGreenstein : Phase::Hazy;
  m.g = def.g;
  m.ambient = def.ambient;
  m.background = def.background;
  return m;
}

SunState sunState(const std::optional<SunDef>& def) {
  SunState s;
  if (!def || !def->enabled) return s;
  s.on = true;
  s.direction = sunDirection(def->azimuthDeg, def->elevationDeg);
  s.illuminance = def->color * def->illuminanceLux;
  return s;
}

uint64_t poseCacheKey(const BeamPose& pose) {
  uint64_t pk = kFnvBasis;
  pk = hashValue(pk, pose.lensPosition);
  pk = hashValue(pk, pose.zb);
  pk = hashValue(pk, pose.xb);
  return pk;
}

const std::vector<std::string>& cellBeamsNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& [name, cells] : kCellBeams) v.emplace_back(name);
    return v;
  }();
  return names;
}

CellBeams cellBeamsNamed(const std::string& name) {
  for (const auto& [n, cells] : kCellBeams)
    if (name == n) return cells;
  return kCellBeams[0].second;
}

const char* cellBeamsName(CellBeams cells) {
  for (const auto& [name, c] : kCellBeams)
    if (c == cells) return name;
  return kCellBeams[0].first;
}

Result<FrameState> buildFrame(const Show& show, const ProfileSet& profiles, const StageState& state,
                              const std::string& cameraName, const FrameOptions& options) {
  FrameState frame;
  if (!cameraName.empty()) {
    const CameraDef* found = nullptr;
    for (const CameraDef& c : show.cameras)
      if (c.name == cameraName) found = &c;
    if (!found) {
      std::string names;
      for (const CameraDef& c : show.cameras) names += (names.empty() ? "" : ", ") + c.name;
      return Error{show.file.string(), "/cameras", "no camera named '" + cameraName + "' (the show has: " +
                                                       (names.empty() ? "none" : names) + ")"};
    }
    frame.camera = cameraState(*found);
  } else if (!show.cameras.empty()) {
    frame.camera = cameraState(show.cameras.front());
  }
  frame.medium = mediumState(show.atmosphere);
  frame.medium.density = options.density;
  frame.softShadows = options.softShadows.value_or(show.atmosphere.softShadows);
  frame.sun = sunState(show.atmosphere.sun);
  // Visible dust (docs/shows.md, "Particles"): the show's settings, switched by the options; it
  // moves with the room's air of the density spec and stands where the show clock puts it.
  frame.particles.settings = show.atmosphere.particles.value_or(ParticleSettings{});
  if (options.particles) frame.particles.settings.enabled = *options.particles;
  frame.particles.timeS = options.clockS;
  if (show.atmosphere.density) frame.particles.airFlowMps = show.atmosphere.density->airFlowMps;

  for (const FixtureDef& f : show.fixtures) {
    auto p = profiles.find(f.profile);
    if (p == profiles.end() || !p->second)
      return Error{show.file.string(), "/fixtures", "fixture " + std::to_string(f.id) + " uses unknown profile '" +
                                                        f.profile + "'"};
    const Profile& profile = *p->second;
    const auto s = state.find(f.id);
    const Attributes a = spunAt(s != state.end() ? s->second : Attributes{}, options.clockS);
    if (options.bodies) {
      const size_t boxes = frame.bodies.size(), meshes = frame.bodyMeshes.size();
      poseBody(profile.housing(), f.position, f.rotationDeg, a.panDeg, a.tiltDeg, frame.bodies, &frame.bodyMeshes);
      for (size_t k = boxes; k < frame.bodies.size(); ++k) frame.bodies[k].fixtureId = f.id;
      for (size_t k = meshes; k < frame.bodyMeshes.size(); ++k) frame.bodyMeshes[k].fixtureId = f.id;
    }
    const std::optional<FrameTime>& time = options.time;
    const float gate = time ? shutterAverage(a.shutter, time->timeS, time->timeS + time->exposureS) : shutterMean(a.shutter);
    if (a.intensity * gate <= 0.0f) continue;  // a dark fixture adds nothing to any pixel
    // One beam per cell of a multi-cell fixture (docs/cells.md), else the profile's one beam.
    // Every cell passes the fixture's shutter, blades and frost.
    const size_t beams = std::max<size_t>(1, profile.cells.size());
    std::vector<BeamState> fixtureBeams;
    for (size_t cell = 0; cell < beams; ++cell) {
      BeamState b;
      b.fixtureId = f.id;
      if (profile.cells.empty()) {
        b.pose = beamPose(f.position, f.rotationDeg, a.panDeg, a.tiltDeg, profile.lensOffset);
        b.optics = profile.optics(a);
      } else {
        b.cell = static_cast<int>(cell);
        b.optics = cellOptics(profile, a, cell);
        if (b.optics.dimmer <= 0.0f) continue;
        b.pose = beamPose(f.position, f.rotationDeg, a.panDeg, a.tiltDeg, profile.cells[cell].lensOffset);
      }
      b.optics.dimmer *= gate;
      b.poseKey = poseCacheKey(b.pose);
      uint64_t ok = kFnvBasis;
      ok = hashValue(ok, b.optics.distribution.get());  // per cell, and frosted when frost is in
      ok = hashValue(ok, b.optics.profileFieldAngleDeg);
      ok = hashValue(ok, b.optics.fieldAngleDeg);
      ok = hashValue(ok, b.optics.gobo.get());
      ok = hashValue(ok, b.optics.goboRotationDeg);
      ok = hashValue(ok, b.optics.gobo2.get());
      ok = hashValue(ok, b.optics.gobo2RotationDeg);
      ok = hashValue(ok, b.optics.animation.get());
      ok = hashValue(ok, b.optics.animationAngleDeg);
      ok = hashValue(ok, b.optics.iris);
      ok = hashValue(ok, b.optics.blades);
      ok = hashValue(ok, b.optics.focusBlur);
      b.opticsKey = ok;
      fixtureBeams.push_back(std::move(b));
    }
    if (options.cells == CellBeams::Merged || (options.cells == CellBeams::Auto && cellsActAsOne(fixtureBeams, profile.cells.size())))
      mergeCellBeams(fixtureBeams);
    // A prism: one beam per facet for each cell's beam, each with 1/N of its light (the copies
    // share one light map).
    const PrismSpec* prism = profile.findPrism(a.prism);
    for (BeamState& b : fixtureBeams) {
      const std::vector<BeamPose> poses = prism ? prismCopies(b.pose, *prism, a.prismRotationDeg) : std::vector<BeamPose>{b.pose};
      b.optics.dimmer /= static_cast<float>(poses.size());
      for (const BeamPose& pose : poses) {
        BeamState copy = b;
        copy.pose = pose;
        copy.poseKey = poseCacheKey(copy.pose);
        frame.beams.push_back(std::move(copy));
      }
    }
  }
  return frame;
}

}  // namespace haze
