// Venues and beams built in code for the reference's tests (quads, boxes, UV spheres; uniform
// and parametric beams), so the tests need no glTF loader and every answer is known by hand.
#pragma once

#include <cmath>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "fixtures/beam_optics.h"
#include "fixtures/photometry.h"
#include "shows/scene/frame_state.h"
#include "shows/scene/scene_builder.h"
#include "shows/scene/venue.h"

namespace haze::test {

constexpr double kPiD = 3.14159265358979323846;

// The scene builders of the product (shows/scene/scene_builder.h), under the names the tests use.
using haze::addBox;
using haze::addFloor;
using haze::addQuad;
using haze::addUvSphere;
using haze::emptyVenue;

inline int addMaterial(Venue& v, glm::vec3 albedo, glm::vec3 emissive = glm::vec3(0.0f)) {
  return haze::addMaterial(v, "test", albedo, emissive);
}

// I(theta) = cd for theta <= halfAngleDeg, 0 beyond: a hand-built uniform beam.
inline std::shared_ptr<const Distribution> uniformDistribution(float halfAngleDeg, float cd) {
  auto d = std::make_shared<Distribution>();
  d->gammaDeg = {0.0f, halfAngleDeg};
  d->cDeg = {0.0f};
  d->candela = {cd, cd};
  d->symmetry = Symmetry::Axial;
  return d;
}

inline std::shared_ptr<const Distribution> parametric(float beamDeg, float fieldDeg, float peakCd) {
  Result<Distribution> d = parametricDistribution(beamDeg, fieldDeg, peakCd);
  if (!d.ok()) return nullptr;
  return std::make_shared<Distribution>(std::move(d.value()));
}

// A beam from lens along zb at full intensity and no zoom (F = F0 = fieldAngleDeg).
inline BeamState makeBeam(glm::vec3 lens, glm::vec3 zb, std::shared_ptr<const Distribution> dist,
                          float fieldAngleDeg, glm::vec3 color = glm::vec3(1.0f)) {
  BeamState b;
  b.pose = beamAlong(lens, zb);
  b.optics.distribution = std::move(dist);
  b.optics.profileFieldAngleDeg = fieldAngleDeg;
  b.optics.fieldAngleDeg = fieldAngleDeg;
  b.optics.dimmer = 1.0f;
  b.optics.color = color;
  // No lens disc: these scenes check point-light answers, and some look through a lamp at the
  // floor it lights. reference_lens_test.cpp gives its beams a radius.
  b.optics.lensRadiusM = 0.0f;
  return b;
}

}  // namespace haze::test
