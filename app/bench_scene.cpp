#include "app/bench_scene.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "fixtures/photometry.h"
#include "fixtures/pose.h"
#include "renderer/scene/scene_builder.h"

namespace haze {

Venue benchVenue() {
  Venue v = emptyVenue();
  const int deck = addMaterial(v, "deck", glm::vec3(0.2f));
  const int walls = addMaterial(v, "walls", glm::vec3(0.35f, 0.35f, 0.38f));
  const int set = addMaterial(v, "set", glm::vec3(0.6f, 0.55f, 0.5f));
  addBox(v, {-10, -0.1f, -8}, {10, 0, 6}, deck);  // deck and house floor
  addBox(v, {-10, 0, -8.2f}, {10, 9, -8}, walls);  // back wall
  addBox(v, {-10.2f, 0, -8}, {-10, 9, 6}, walls);  // side walls
  addBox(v, {10, 0, -8}, {10.2f, 9, 6}, walls);
  for (float x : {-4.0f, 0.0f, 4.0f}) addBox(v, {x - 0.3f, 0, -3.3f}, {x + 0.3f, 3.5f, -2.7f}, set);  // columns
  for (float x : {-2.5f, -1.5f, -0.5f, 0.5f, 1.5f, 2.5f})                                         // slatted panel
    addBox(v, {x - 0.3f, 4.5f, -1.05f}, {x + 0.3f, 4.6f, -0.95f}, set);
  return v;
}

FrameState benchFrame(int fixtures) {
  FrameState f;
  f.camera.position = {0.0f, 4.0f, 14.0f};
  f.camera.target = {0.0f, 3.0f, -2.0f};
  f.camera.fovYDeg = 45.0f;
  f.medium.scattering = 0.03f;
  f.medium.ambient = glm::vec3(0.02f);
  auto dist = std::make_shared<Distribution>(*parametricDistribution(14.0f, 20.0f, 60000.0f));
  for (int i = 0; i < fixtures; ++i) {
    // Two truss lines, fixtures spread along them, aimed to cross on the deck.
    const int perLine = (fixtures + 1) / 2;
    const int line = i % 2, k = i / 2;
    const float x = perLine > 1 ? -8.0f + 16.0f * static_cast<float>(k) / static_cast<float>(perLine - 1) : 0.0f;
    const glm::vec3 pos(x, 7.5f, line ? -4.0f : 1.0f);
    const glm::vec3 target(-x * 0.6f, 0.0f, line ? -1.0f : -3.0f);
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
