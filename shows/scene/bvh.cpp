// The reference's BVH: binned SAH build (16 bins, leaves of at most 4 triangles) and a
// stack traversal; triangles by Moeller-Trumbore with a tiny barycentric tolerance so rays
// through a shared edge never slip between two triangles (no cracks in the floor).
#include "shows/scene/bvh.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

namespace haze {

namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxLeaf = 4;
constexpr int kStackSize = 128;  // the build splits by index when SAH cannot, so depth ~ log2(n)
// Barycentric slack: a ray through a shared edge hits both triangles instead of neither.
constexpr float kEdgeTolerance = 1e-6f;

struct Box {
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};
  void grow(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  float area() const {
    if (lo.x > hi.x) return 0.0f;
    const glm::vec3 d = hi - lo;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Slab test; inv holds 1/dir with zeros replaced by huge finite values (no 0 * inf NaN).
bool hitBox(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& origin,
            const glm::vec3& inv, float tMin, float tMax, float& tEnter) {
  const glm::vec3 t0 = (lo - origin) * inv;
  const glm::vec3 t1 = (hi - origin) * inv;
  const glm::vec3 tn = glm::min(t0, t1);
  const glm::vec3 tf = glm::max(t0, t1);
  const float enter = std::max(std::max(tn.x, tn.y), std::max(tn.z, tMin));
  const float exit = std::min(std::min(tf.x, tf.y), std::min(tf.z, tMax));
  tEnter = enter;
  return enter <= exit;
}

}  // namespace

Bvh::Bvh(const Venue& venue) : venue_(&venue) {
  std::vector<Box> boxes;
  std::vector<glm::vec3> centroids;
  for (size_t p = 0; p < venue.primitives.size(); ++p) {
    const Primitive& prim = venue.primitives[p];
    const size_t n = prim.indices.size() / 3;
    for (size_t k = 0; k < n; ++k) {
      const uint32_t i0 = prim.indices[3 * k], i1 = prim.indices[3 * k + 1],
                     i2 = prim.indices[3 * k + 2];
      if (i0 >= prim.positions.size() || i1 >= prim.positions.size() ||
          i2 >= prim.positions.size())
        continue;
      const glm::vec3 a = prim.positions[i0], b = prim.positions[i1], c = prim.positions[i2];
      if (!finite(a) || !finite(b) || !finite(c)) continue;
      tris_.push_back(Tri{a, b - a, c - a, static_cast<int>(p), static_cast<int>(k)});
      Box box;
      box.grow(a);
      box.grow(b);
      box.grow(c);
      boxes.push_back(box);
      centroids.push_back((a + b + c) / 3.0f);
    }
  }

  std::vector<uint32_t> order(tris_.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;

  nodes_.reserve(tris_.empty() ? 1 : 2 * tris_.size());
  nodes_.push_back(Node{});
  struct Task {
    uint32_t node, begin, end;
    int depth;
  };
  std::vector<Task> tasks{{0, 0, static_cast<uint32_t>(order.size()), 1}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    depth_ = std::max(depth_, task.depth);
    Box bounds, cbounds;
    for (uint32_t i = task.begin; i < task.end; ++i) {
      bounds.grow(boxes[order[i]]);
      cbounds.grow(centroids[order[i]]);
    }
    Node& node = nodes_[task.node];
    node.lo = task.end > task.begin ? bounds.lo : glm::vec3(0.0f);
    node.hi = task.end > task.begin ? bounds.hi : glm::vec3(0.0f);
    const uint32_t count = task.end - task.begin;
    if (count <= kMaxLeaf) {
      node.first = task.begin;
      node.count = count;
      continue;
    }

    // Binned SAH over the longest centroid axis.
    const glm::vec3 extent = cbounds.hi - cbounds.lo;
    int axis = 0;
    if (extent.y > extent[axis]) axis = 1;
    if (extent.z > extent[axis]) axis = 2;
    uint32_t mid = task.begin;
    if (extent[axis] > 0.0f && std::isfinite(extent[axis])) {
      std::array<Box, kBins> binBox;
      std::array<uint32_t, kBins> binCount{};
      const float scale = kBins / extent[axis];
      auto binOf = [&](uint32_t t) {
        // Clamped as a float first: a huge or NaN coordinate must not reach the int cast.
        const float f = (centroids[t][axis] - cbounds.lo[axis]) * scale;
        return f >= 0.0f ? static_cast<int>(std::min(f, float(kBins - 1))) : 0;
      };
      for (uint32_t i = task.begin; i < task.end; ++i) {
        const int b = binOf(order[i]);
        binBox[b].grow(boxes[order[i]]);
        ++binCount[b];
      }
      std::array<float, kBins> rightCost{};
      Box acc;
      uint32_t accCount = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.grow(binBox[b]);
        accCount += binCount[b];
        rightCost[b] = acc.area() * static_cast<float>(accCount);
      }
      Box left;
      uint32_t leftCount = 0;
      float bestCost = std::numeric_limits<float>::infinity();
      int bestSplit = -1;
      for (int b = 1; b < kBins; ++b) {
        left.grow(binBox[b - 1]);
        leftCount += binCount[b - 1];
        if (leftCount == 0 || leftCount == count) continue;
        const float cost = left.area() * static_cast<float>(leftCount) + rightCost[b];
        if (cost < bestCost) {
          bestCost = cost;
          bestSplit = b;
        }
      }
      if (bestSplit > 0) {
        auto it = std::partition(order.begin() + task.begin, order.begin() + task.end,
                                 [&](uint32_t t) { return binOf(t) < bestSplit; });
        mid = static_cast<uint32_t>(it - order.begin());
      }
    }
    if (mid == task.begin || mid == task.end) {
      // All centroids in one bin (or all equal): halve by index, which keeps the depth ~ log2(n).
      mid = task.begin + count / 2;
    }
    const uint32_t left = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back(Node{});
    nodes_.push_back(Node{});
    nodes_[task.node].first = left;
    nodes_[task.node].count = 0;
    tasks.push_back({left, task.begin, mid, task.depth + 1});
    tasks.push_back({left + 1, mid, task.end, task.depth + 1});
  }
  assert(depth_ < kStackSize && "Bvh: tree deeper than the traversal stack");

  std::vector<Tri> sorted;
  sorted.reserve(tris_.size());
  for (uint32_t i : order) sorted.push_back(tris_[i]);
  tris_ = std::move(sorted);
}

template <bool kAnyHit>
RayHit Bvh::traverse(const glm::vec3& origin, const glm::vec3& dir, float tMinM,
                     float tMaxM) const {
  RayHit best;
  if (tris_.empty() || !(tMaxM > tMinM) || !finite(origin) || !finite(dir)) return best;
  glm::vec3 inv;
  for (int a = 0; a < 3; ++a) {
    const float d = dir[a];
    inv[a] = std::fabs(d) > 1e-30f ? 1.0f / d : (std::signbit(d) ? -1e30f : 1e30f);
  }
  float tFar = tMaxM;
  std::array<uint32_t, kStackSize> stack;
  int top = 0;
  float enter;
  if (!hitBox(nodes_[0].lo, nodes_[0].hi, origin, inv, tMinM, tFar, enter)) return best;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!hitBox(node.lo, node.hi, origin, inv, tMinM, tFar, enter)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Tri& tri = tris_[i];
        const glm::vec3 p = glm::cross(dir, tri.e2);
        const float det = glm::dot(tri.e1, p);
        if (det == 0.0f || !std::isfinite(det)) continue;  // degenerate or parallel
        const float invDet = 1.0f / det;
        const glm::vec3 s = origin - tri.v0;
        const float u = glm::dot(s, p) * invDet;
        if (u < -kEdgeTolerance || u > 1.0f + kEdgeTolerance) continue;
        const glm::vec3 q = glm::cross(s, tri.e1);
        const float v = glm::dot(dir, q) * invDet;
        if (v < -kEdgeTolerance || u + v > 1.0f + kEdgeTolerance) continue;
        const float t = glm::dot(tri.e2, q) * invDet;
        if (!(t > tMinM && t < tFar)) continue;  // also rejects NaN
        best.tM = t;
        best.primitive = tri.primitive;
        best.triangle = tri.triangle;
        best.b1 = std::clamp(u, 0.0f, 1.0f);
        best.b2 = std::clamp(v, 0.0f, 1.0f - best.b1);
        if constexpr (kAnyHit) return best;
        tFar = t;
      }
      continue;
    }
    // Visit the nearer child first so closest-hit shrinks tFar early.
    float enterL, enterR;
    const Node& l = nodes_[node.first];
    const Node& r = nodes_[node.first + 1];
    const bool hitL = hitBox(l.lo, l.hi, origin, inv, tMinM, tFar, enterL);
    const bool hitR = hitBox(r.lo, r.hi, origin, inv, tMinM, tFar, enterR);
    if (hitL && hitR) {
      if (enterL <= enterR) {
        stack[top++] = node.first + 1;
        stack[top++] = node.first;
      } else {
        stack[top++] = node.first;
        stack[top++] = node.first + 1;
      }
    } else if (hitL) {
      stack[top++] = node.first;
    } else if (hitR) {
      stack[top++] = node.first + 1;
    }
  }
  return best;
}

RayHit Bvh::closestHit(const glm::vec3& origin, const glm::vec3& dir, float tMinM,
                       float tMaxM) const {
  return traverse<false>(origin, dir, tMinM, tMaxM);
}

bool Bvh::anyHit(const glm::vec3& origin, const glm::vec3& dir, float tMinM, float tMaxM) const {
  return traverse<true>(origin, dir, tMinM, tMaxM).hit();
}

bool Bvh::mayComeNear(const glm::vec3& origin, const glm::vec3& dir, float tMinM, float tMaxM,
                      float radiusM) const {
  if (tris_.empty()) return false;
  if (!(tMaxM >= tMinM) || !finite(origin) || !finite(dir) || !(radiusM >= 0.0f) || !std::isfinite(radiusM))
    return true;  // nothing promised
  glm::vec3 inv;
  for (int a = 0; a < 3; ++a) {
    const float d = dir[a];
    inv[a] = std::fabs(d) > 1e-30f ? 1.0f / d : (std::signbit(d) ? -1e30f : 1e30f);
  }
  const glm::vec3 grow(radiusM);
  std::array<uint32_t, kStackSize> stack;
  int top = 0;
  float enter;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!hitBox(node.lo - grow, node.hi + grow, origin, inv, tMinM, tMaxM, enter)) continue;
    if (node.count == 0) {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const Tri& tri = tris_[i];
      const glm::vec3 v1 = tri.v0 + tri.e1, v2 = tri.v0 + tri.e2;
      const glm::vec3 lo = glm::min(tri.v0, glm::min(v1, v2)) - grow;
      const glm::vec3 hi = glm::max(tri.v0, glm::max(v1, v2)) + grow;
      if (hitBox(lo, hi, origin, inv, tMinM, tMaxM, enter)) return true;
    }
  }
  return false;
}

SurfacePoint Bvh::surfaceAt(const RayHit& hit) const {
  assert(hit.hit() && "Bvh::surfaceAt needs a hit: check RayHit::hit() first");
  const Primitive& prim = venue_->primitives[static_cast<size_t>(hit.primitive)];
  const size_t k = static_cast<size_t>(hit.triangle);
  const uint32_t i0 = prim.indices[3 * k], i1 = prim.indices[3 * k + 1],
                 i2 = prim.indices[3 * k + 2];
  const float b0 = 1.0f - hit.b1 - hit.b2;
  SurfacePoint s;
  s.primitive = &prim;
  const glm::vec3 a = prim.positions[i0], b = prim.positions[i1], c = prim.positions[i2];
  s.positionM = b0 * a + hit.b1 * b + hit.b2 * c;
  const glm::vec3 ng = glm::cross(b - a, c - a);
  const float len = glm::length(ng);
  s.geometricNormal = len > 0.0f && std::isfinite(len) ? ng / len : glm::vec3(0.0f, 1.0f, 0.0f);
  s.shadingNormal = s.geometricNormal;
  if (prim.normals.size() == prim.positions.size()) {
    const glm::vec3 n = b0 * prim.normals[i0] + hit.b1 * prim.normals[i1] + hit.b2 * prim.normals[i2];
    const float nl = glm::length(n);
    if (nl > 1e-12f && std::isfinite(nl)) s.shadingNormal = n / nl;
  }
  if (prim.uvs.size() == prim.positions.size())
    s.uv = b0 * prim.uvs[i0] + hit.b1 * prim.uvs[i1] + hit.b2 * prim.uvs[i2];
  return s;
}

}  // namespace haze
