// Venues and beams built in code for the reference's tests (quads, boxes, UV spheres; uniform
// and parametric beams), so the tests need no glTF loader and every answer is known by hand.
#pragma once

#include <cmath>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "fixtures/beam_optics.h"
#include "fixtures/photometry.h"
#include "renderer/scene/frame_state.h"
#include "renderer/scene/venue.h"

namespace haze::test {

constexpr double kPiD = 3.14159265358979323846;

// A venue with the default white material at index 0.
inline Venue emptyVenue() {
  Venue v;
  v.materials.push_back(Material{});
  return v;
}

inline int addMaterial(Venue& v, glm::vec3 albedo, glm::vec3 emissive = glm::vec3(0.0f)) {
  Material m;
  m.baseColor = glm::vec4(albedo, 1.0f);
  m.emissive = emissive;
  v.materials.push_back(m);
  return static_cast<int>(v.materials.size()) - 1;
}

// Quad p0 p1 p2 p3 (in order around it) as triangles (0 1 2) and (0 2 3); the winding normal
// is (p1 - p0) x (p3 - p0).
inline void addQuad(Venue& v, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
                    int material = 0) {
  Primitive p;
  p.positions = {p0, p1, p2, p3};
  const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p3 - p0));
  p.normals = {n, n, n, n};
  p.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = material;
  v.primitives.push_back(std::move(p));
}

// Horizontal square at height y, facing up (+Y) unless faceDown.
inline void addFloor(Venue& v, float y, float halfSizeM, int material = 0, bool faceDown = false) {
  const float s = halfSizeM;
  if (!faceDown)
    addQuad(v, {-s, y, -s}, {-s, y, s}, {s, y, s}, {s, y, -s}, material);
  else
    addQuad(v, {-s, y, -s}, {s, y, -s}, {s, y, s}, {-s, y, s}, material);
}

inline void addBox(Venue& v, glm::vec3 lo, glm::vec3 hi, int material = 0) {
  const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                          {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                          {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  addQuad(v, c[0], c[3], c[2], c[1], material);  // -z
  addQuad(v, c[4], c[5], c[6], c[7], material);  // +z
  addQuad(v, c[0], c[4], c[7], c[3], material);  // -x
  addQuad(v, c[1], c[2], c[6], c[5], material);  // +x
  addQuad(v, c[0], c[1], c[5], c[4], material);  // -y
  addQuad(v, c[3], c[7], c[6], c[2], material);  // +y
}

// A UV sphere of rings x segments quads (the poles as fans), smooth normals.
inline void addUvSphere(Venue& v, glm::vec3 centre, float radiusM, int rings, int segments,
                        int material = 0) {
  Primitive p;
  for (int i = 0; i <= rings; ++i) {
    const double theta = kPiD * i / rings;
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2.0 * kPiD * j / segments;
      const glm::vec3 n(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                        float(std::sin(theta) * std::sin(phi)));
      p.positions.push_back(centre + radiusM * n);
      p.normals.push_back(n);
      p.uvs.push_back({float(j) / segments, float(i) / rings});
    }
  }
  const uint32_t row = static_cast<uint32_t>(segments + 1);
  for (uint32_t i = 0; i < static_cast<uint32_t>(rings); ++i) {
    for (uint32_t j = 0; j < static_cast<uint32_t>(segments); ++j) {
      const uint32_t a = i * row + j, b = a + row, c = b + 1, d = a + 1;
      if (i != 0) p.indices.insert(p.indices.end(), {a, b, d});
      if (i + 1 != static_cast<uint32_t>(rings)) p.indices.insert(p.indices.end(), {d, b, c});
    }
  }
  p.material = material;
  v.primitives.push_back(std::move(p));
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
  return b;
}

}  // namespace haze::test
