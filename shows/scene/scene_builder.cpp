// Venues built in code (see scene_builder.h).
#include "shows/scene/scene_builder.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace haze {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Appends quad p0 p1 p2 p3 to a primitive: triangles (0 1 2) and (0 2 3), flat normal.
void appendQuad(Primitive& p, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
  const auto base = static_cast<uint32_t>(p.positions.size());
  const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p3 - p0));
  p.positions.insert(p.positions.end(), {p0, p1, p2, p3});
  p.normals.insert(p.normals.end(), {n, n, n, n});
  p.uvs.insert(p.uvs.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

void addPrimitive(Venue& v, Primitive p) {
  for (const glm::vec3& q : p.positions) {
    v.boundsMin = glm::min(v.boundsMin, q);
    v.boundsMax = glm::max(v.boundsMax, q);
  }
  v.primitives.push_back(std::move(p));
}

}  // namespace

Venue emptyVenue() {
  Venue v;
  v.materials.push_back(Material{.name = "default"});
  v.boundsMin = glm::vec3(std::numeric_limits<float>::max());
  v.boundsMax = glm::vec3(-std::numeric_limits<float>::max());
  return v;
}

int addMaterial(Venue& v, const std::string& name, glm::vec3 albedo, glm::vec3 emissive) {
  Material m;
  m.name = name;
  m.baseColor = glm::vec4(albedo, 1.0f);
  m.emissive = emissive;
  v.materials.push_back(m);
  return static_cast<int>(v.materials.size()) - 1;
}

void addQuad(Venue& v, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, int material) {
  Primitive p;
  p.name = "quad";
  appendQuad(p, p0, p1, p2, p3);
  p.material = material;
  addPrimitive(v, std::move(p));
}

void addFloor(Venue& v, float y, float halfSizeM, int material, bool faceDown) {
  const float s = halfSizeM;
  if (!faceDown)
    addQuad(v, {-s, y, -s}, {-s, y, s}, {s, y, s}, {s, y, -s}, material);
  else
    addQuad(v, {-s, y, -s}, {s, y, -s}, {s, y, s}, {-s, y, s}, material);
}

void addBox(Venue& v, glm::vec3 lo, glm::vec3 hi, int material) {
  const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                          {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  Primitive p;  // one primitive, so a box is one draw
  p.name = "box";
  appendQuad(p, c[0], c[3], c[2], c[1]);  // -z
  appendQuad(p, c[4], c[5], c[6], c[7]);  // +z
  appendQuad(p, c[0], c[4], c[7], c[3]);  // -x
  appendQuad(p, c[1], c[2], c[6], c[5]);  // +x
  appendQuad(p, c[0], c[1], c[5], c[4]);  // -y
  appendQuad(p, c[3], c[7], c[6], c[2]);  // +y
  p.material = material;
  addPrimitive(v, std::move(p));
}

void addUvSphere(Venue& v, glm::vec3 centre, float radiusM, int rings, int segments, int material) {
  Primitive p;
  p.name = "sphere";
  for (int i = 0; i <= rings; ++i) {
    const double theta = kPi * i / rings;
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2.0 * kPi * j / segments;
      const glm::vec3 n(static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                        static_cast<float>(std::sin(theta) * std::sin(phi)));
      p.positions.push_back(centre + radiusM * n);
      p.normals.push_back(n);
      p.uvs.push_back({static_cast<float>(j) / static_cast<float>(segments), static_cast<float>(i) / static_cast<float>(rings)});
    }
  }
  const auto row = static_cast<uint32_t>(segments + 1);
  for (uint32_t i = 0; i < static_cast<uint32_t>(rings); ++i) {
    for (uint32_t j = 0; j < static_cast<uint32_t>(segments); ++j) {
      const uint32_t a = i * row + j, b = a + row, c = b + 1, d = a + 1;
      if (i != 0) p.indices.insert(p.indices.end(), {a, b, d});
      if (i + 1 != static_cast<uint32_t>(rings)) p.indices.insert(p.indices.end(), {d, b, c});
    }
  }
  p.material = material;
  addPrimitive(v, std::move(p));
}

}  // namespace haze
