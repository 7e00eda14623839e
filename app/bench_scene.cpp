#include "app/bench_scene.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "fixtures/photometry.h"
#include "fixtures/pose.h"
#include "shows/scene/scene_builder.h"

namespace haze {
namespace {

uint64_t mixKey(uint64_t h, uint64_t v) { return h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)); }

// How the stage grows with the rig: 16 fixtures or fewer on two 16 m truss lines in a 20 m room
// (the scene every earlier measurement used), more on more lines (pairs, 5 m apart front to back)
// and longer lines (at most 2 fixtures per metre), up to an arena at 1000 fixtures.
struct BenchLayout {
  int lines = 2, perLine = 1;
  float lineLengthM = 16.0f, trussHeightM = 7.5f, frontZ = 1.0f, backZ = -4.0f;
  float halfWidthM() const { return std::max(10.0f, 0.5f * lineLengthM + 2.0f); }
  float lineZ(int line) const {
    return lines > 1 ? frontZ + (backZ - frontZ) * static_cast<float>(line) / static_cast<float>(lines - 1) : frontZ;
  }
};

BenchLayout benchLayout(int fixtures) {
  BenchLayout l;
  const float scale = std::max(1.0f, std::sqrt(static_cast<float>(fixtures) / 16.0f));
  l.lines = 2 * static_cast<int>(std::ceil(scale / 2.0f));
  l.perLine = std::max(1, (fixtures + l.lines - 1) / l.lines);
  l.lineLengthM = std::max(16.0f, 0.5f * static_cast<float>(l.perLine));
  l.trussHeightM = 7.5f * std::min(2.0f, std::sqrt(scale));
  l.backZ = l.frontZ - 5.0f * static_cast<float>(l.lines - 1);
  return l;
}

}  // namespace

Venue benchVenue(int fixtures) {
  const BenchLayout l = benchLayout(fixtures);
  const float hw = l.halfWidthM(), back = std::min(-8.0f, l.backZ - 4.0f), top = l.trussHeightM + 1.5f;
  Venue v = emptyVenue();
  const int deck = addMaterial(v, "deck", glm::vec3(0.2f));
  const int walls = addMaterial(v, "walls", glm::vec3(0.35f, 0.35f, 0.38f));
  const int set = addMaterial(v, "set", glm::vec3(0.6f, 0.55f, 0.5f));
  addBox(v, {-hw, -0.1f, back}, {hw, 0, 6}, deck);  // deck and house floor
  addBox(v, {-hw, 0, back - 0.2f}, {hw, top, back}, walls);  // back wall
  addBox(v, {-hw - 0.2f, 0, back}, {-hw, top, 6}, walls);  // side walls
  addBox(v, {hw, 0, back}, {hw + 0.2f, top, 6}, walls);
  for (float x : {-4.0f, 0.0f, 4.0f}) addBox(v, {x - 0.3f, 0, -3.3f}, {x + 0.3f, 3.5f, -2.7f}, set);  // columns
  for (float x : {-2.5f, -1.5f, -0.5f, 0.5f, 1.5f, 2.5f})                                         // slatted panel
    addBox(v, {x - 0.3f, 4.5f, -1.05f}, {x + 0.3f, 4.6f, -0.95f}, set);
  return v;
}

DensitySpec benchDensity(int cellsPerSide) {
  DensitySpec d;
  d.base = 0.4f;
  d.grid[0] = d.grid[1] = d.grid[2] = cellsPerSide;
  d.airFlowMps = {0.1f, 0.0f, 0.05f};
  d.hazers.push_back({.positionM = {-8.0f, 0.3f, 0.0f}, .direction = {1.0f, 0.15f, 0.0f}, .output = 3.0f,
                      .spreadDeg = 30.0f, .speedMps = 3.0f});
  d.warmupS = 60.0;
  return d;
}

FrameState benchFrame(int fixtures) {
  const BenchLayout l = benchLayout(fixtures);
  FrameState f;
  // Far enough back to see the whole width (1 for the original 20 m room).
  const float k = l.halfWidthM() / 10.0f;
  f.camera.position = {0.0f, 4.0f * k, -2.0f + 16.0f * k};
  f.camera.target = {0.0f, 3.0f * k, -2.0f + 0.5f * (l.backZ - l.frontZ + 5.0f)};
  f.camera.fovYDeg = 45.0f;
  f.camera.farM = std::max(f.camera.farM, 5.0f * l.halfWidthM());
  f.medium.scattering = 0.03f;
  f.medium.ambient = glm::vec3(0.02f);
  auto dist = std::make_shared<Distribution>(*parametricDistribution(14.0f, 20.0f, 60000.0f));
  for (int i = 0; i < fixtures; ++i) {
    // Fixtures spread along the lines, aimed to cross on the deck: even lines aim upstage, odd
    // ones downstage.
    const int line = i % l.lines, k2 = i / l.lines;
    const float half = 0.5f * l.lineLengthM;
    const float x = l.perLine > 1 ? -half + l.lineLengthM * static_cast<float>(k2) / static_cast<float>(l.perLine - 1)
                                  : 0.0f;
    const float z = l.lineZ(line);
    const glm::vec3 pos(x, l.trussHeightM, z);
    const glm::vec3 target(-x * 0.6f, 0.0f, line % 2 ? z + 3.0f : z - 4.0f);
    const glm::vec3 d = glm::normalize(target - pos);
    // Pan and tilt that aim the head at the target (docs/physics.md: beam = Ry(pan) Rx(tilt) (0,-1,0)).
    const float tilt = std::acos(std::clamp(-d.y, -1.0f, 1.0f));
    const float pan = std::atan2(-d.x, -d.z);
    BeamState b;
    b.fixtureId = i + 1;
    b.pose = beamPose(pos, glm::vec3(0.0f), glm::degrees(pan), glm::degrees(tilt), glm::vec3(0, -0.25f, 0));
    b.optics.distribution = dist;
    b.optics.profileFieldAngleDeg = 20.0f;
    b.optics.fieldAngleDeg = 20.0f;
    b.optics.dimmer = 1.0f;
    const float hue = static_cast<float>(i) / static_cast<float>(std::max(fixtures, 1));
    b.optics.color = glm::vec3(0.6f + 0.4f * std::cos(6.2832f * hue), 0.6f + 0.4f * std::cos(6.2832f * (hue - 0.33f)),
                               0.6f + 0.4f * std::cos(6.2832f * (hue - 0.67f)));
    b.poseKey = static_cast<uint64_t>(i + 1);
    b.opticsKey = 1;  // one distribution for all: light maps are equal
    f.beams.push_back(std::move(b));
  }
  return f;
}

FrameState turnedBeams(FrameState f, float deg) {
  const glm::mat3 r(glm::rotate(glm::mat4(1.0f), glm::radians(deg), glm::vec3(0.0f, 1.0f, 0.0f)));
  for (BeamState& b : f.beams) {
    b.pose.xb = r * b.pose.xb;
    b.pose.yb = r * b.pose.yb;
    b.pose.zb = r * b.pose.zb;
    b.poseKey = mixKey(b.poseKey, static_cast<uint64_t>(std::llround(deg * 1000.0f)));
  }
  return f;
}

Venue studyVenue() {
  Venue v = emptyVenue();
  const int floor = addMaterial(v, "floor", glm::vec3(0.4f));
  addBox(v, {-8, -0.1f, -8}, {8, 0, 8}, floor);
  addUvSphere(v, {0.3f, 3.0f, 0.0f}, 0.6f, 24, 48, floor);  // in the beam
  return v;
}

FrameState studyFrame() {
  FrameState f;
  f.camera.position = {0.0f, 3.5f, 11.0f};
  f.camera.target = {0.0f, 3.0f, 0.0f};
  f.camera.fovYDeg = 45.0f;
  f.medium.scattering = 0.05f;
  BeamState b;
  b.fixtureId = 1;
  b.pose = beamPose({0.0f, 7.0f, 0.0f}, glm::vec3(0.0f), 0.0f, 0.0f, glm::vec3(0.0f));
  b.optics.distribution = std::make_shared<Distribution>(*parametricDistribution(22.0f, 32.0f, 50000.0f));
  b.optics.profileFieldAngleDeg = 32.0f;
  b.optics.fieldAngleDeg = 32.0f;
  b.optics.dimmer = 1.0f;
  b.poseKey = 1;
  b.opticsKey = 1;
  f.beams.push_back(std::move(b));
  return f;
}

}  // namespace haze
