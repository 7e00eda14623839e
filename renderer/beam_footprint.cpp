#include "renderer/beam_footprint.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "shows/scene/camera_basis.h"

namespace haze {
namespace {

float cross(glm::vec2 o, glm::vec2 a, glm::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points.
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> p) {
  std::sort(p.begin(), p.end(), [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  std::vector<glm::vec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0.0f) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0.0f) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

// Sutherland-Hodgman against the screen square [-1, 1]^2.
std::vector<glm::vec2> clipToScreen(std::vector<glm::vec2> poly) {
  for (int edge = 0; edge < 4 && !poly.empty(); ++edge) {
    const int axis = edge / 2;
    const float sign = (edge % 2) ? -1.0f : 1.0f;  // keep sign * p[axis] <= 1
    auto inside = [&](glm::vec2 p) { return sign * p[axis] <= 1.0f; };
    std::vector<glm::vec2> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      if (inside(a)) out.push_back(a);
      if (inside(a) != inside(b)) {
        const float t = (sign - a[axis]) / (b[axis] - a[axis]);
        out.push_back(a + t * (b - a));
      }
    }
    poly = std::move(out);
  }
  return poly;
}

}  // namespace

float BeamFootprint::areaNdc() const {
  float twice = 0.0f;
  for (int i = 0; i < vertexCount; ++i) {
    const glm::vec2 a = polygonNdc[static_cast<size_t>(i)], b = polygonNdc[static_cast<size_t>((i + 1) % vertexCount)];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5f * std::abs(twice);
}

BeamFootprint beamFootprint(const BeamState& beam, const CameraState& camera, float aspect, float coneLengthM) {
  BeamFootprint fp;
  const CameraBasis b = cameraBasis(camera, aspect);
  const float cutoff = beam.optics.cutoffHalfAngleRad();
  // The cone's hull: the lens and its cap at coneLengthM. 16 points on a circle widened by
  // 1 / cos(pi / 16) circumscribe the cap, so the hull of their projections contains the cone's.
  const float capRadius = coneLengthM * std::tan(cutoff) / std::cos(3.14159265f / 16.0f);
  const glm::vec3 cap = beam.pose.lensPosition + beam.pose.zb * coneLengthM;
  std::vector<glm::vec2> points;
  float zNear = 1e30f, zFar = -1e30f;
  bool crossesEyePlane = false;
  auto addPoint = [&](const glm::vec3& p) {
    const glm::vec3 d = p - camera.position;
    const float z = glm::dot(d, b.forward);
    zNear = std::min(zNear, z);
    zFar = std::max(zFar, z);
    if (z <= camera.nearM) {
      crossesEyePlane = true;
      return;
    }
    points.emplace_back(glm::dot(d, b.right) / (z * b.tanX), glm::dot(d, b.up) / (z * b.tanY));
  };
  addPoint(beam.pose.lensPosition);
  for (int i = 0; i < 16; ++i) {
    const float a = static_cast<float>(i) * 3.14159265f / 8.0f;
    addPoint(cap + capRadius * (std::cos(a) * beam.pose.xb + std::sin(a) * beam.pose.yb));
  }
  if (zFar <= camera.nearM) return fp;  // wholly behind the camera
  std::vector<glm::vec2> poly = crossesEyePlane
                                    ? std::vector<glm::vec2>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}
                                    : clipToScreen(convexHull(std::move(points)));
  if (poly.size() < 3 || poly.size() > static_cast<size_t>(BeamFootprint::kMaxVertices)) return fp;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (size_t i = 0; i < poly.size(); ++i) {
    fp.polygonNdc[i] = poly[i];
    lo = glm::min(lo, poly[i]);
    hi = glm::max(hi, poly[i]);
  }
  fp.vertexCount = static_cast<int>(poly.size());
  if (lo.x >= hi.x || lo.y >= hi.y) return fp;
  fp.rectNdc = glm::vec4(lo, hi);
  fp.zNear = std::max(zNear, camera.nearM);
  fp.zFar = std::min(zFar, camera.farM);
  fp.visible = fp.zFar > fp.zNear;
  return fp;
}

}  // namespace haze
