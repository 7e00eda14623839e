// Bvh: a bounding volume hierarchy (binned SAH) over every triangle of a Venue, for the CPU
// reference: closest-hit queries for eye rays and any-hit queries for exact shadow tests.
// A hit names its primitive, triangle and barycentrics, so the caller gets uv, normal and albedo
// from the Venue itself (surfaceAt below).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shows/scene/venue.h"

namespace haze {

struct RayHit {
  float tM = std::numeric_limits<float>::infinity();  // distance along the (unit) direction
  int primitive = -1;   // index into Venue::primitives, -1 = no hit
  int triangle = -1;    // triangle k of that primitive: indices[3k], [3k+1], [3k+2]
  float b1 = 0.0f;      // barycentric weight of the triangle's second vertex
  float b2 = 0.0f;      // ... of its third; the first gets 1 - b1 - b2
  bool hit() const { return primitive >= 0; }
};

// What a hit means on the surface, looked up in the Venue.
struct SurfacePoint {
  glm::vec3 positionM{0.0f};
  glm::vec3 geometricNormal{0.0f, 1.0f, 0.0f};  // unit, from the winding (v1 - v0) x (v2 - v0)
  glm::vec3 shadingNormal{0.0f, 1.0f, 0.0f};    // unit, interpolated vertex normals (else geometric)
  glm::vec2 uv{0.0f};                           // (0, 0) when the primitive has no uvs
  const Primitive* primitive = nullptr;
};

class Bvh {
 public:
  // Keeps a reference to the venue (it must outlive the Bvh). Triangles with an index out of
  // range or a non-finite vertex are left out; degenerate (zero-area) ones are kept but never hit.
  explicit Bvh(const Venue& venue);

  // The nearest triangle with tMinM < t < tMaxM along origin + t * dir (dir need not be unit;
  // t is then in units of |dir|). Two-sided: back faces are hit too.
  RayHit closestHit(const glm::vec3& origin, const glm::vec3& dir, float tMinM, float tMaxM) const;
  // Whether any triangle lies with tMinM < t < tMaxM; stops at the first one found.
  bool anyHit(const glm::vec3& origin, const glm::vec3& dir, float tMinM, float tMaxM) const;
  // Conservatively, whether any triangle may come within radiusM of the segment
  // origin + t * dir, tMinM <= t <= tMaxM: false promises that none does (the segment against
  // node and triangle boxes grown by radiusM); true may be a box's corner only.
  bool mayComeNear(const glm::vec3& origin, const glm::vec3& dir, float tMinM, float tMaxM, float radiusM) const;

  SurfacePoint surfaceAt(const RayHit& hit) const;

  const Venue& venue() const { return *venue_; }
  size_t triangleCount() const { return tris_.size(); }
  size_t nodeCount() const { return nodes_.size(); }
  int depth() const { return depth_; }

 private:
  struct Node {
    glm::vec3 lo{0.0f};
    glm::vec3 hi{0.0f};
    // Inner node: first = index of the left child (the right one is first + 1), count = 0.
    // Leaf: first = first triangle in tris_, count = number of triangles.
    uint32_t first = 0;
    uint32_t count = 0;
  };
  struct Tri {
    glm::vec3 v0, e1, e2;  // v0, v1 - v0, v2 - v0
    int primitive;
    int triangle;
  };

  const Venue* venue_;
  std::vector<Node> nodes_;
  std::vector<Tri> tris_;
  int depth_ = 0;

  template <bool kAnyHit>
  RayHit traverse(const glm::vec3& origin, const glm::vec3& dir, float tMinM, float tMaxM) const;
};

}  // namespace haze
