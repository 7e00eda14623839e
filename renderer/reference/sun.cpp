// The sun's light is the same at every point up to V_sun and T_sun, and the scattering angle is
// the same all along an eye ray, so the march carries only visibility and the two paths. Samples
// are uniform in t over the ray's chord through the venue's box (where the sun's medium is);
// visibility is sampled at step ends and a change within a step is bisected, as the beams' is.
#include "renderer/reference/sun.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shows/scene/physics.h"

namespace haze {
namespace {

constexpr int kEdgeBisections = 12;
// The shadow ray towards the sun has no end; this one is far beyond any venue.
constexpr float kSunRayM = 1e5f;
// The march stops this far short of the surface that ends the eye ray: a shadow ray from the
// surface itself can slip past it (float rounding) and see a sun the surface hides.
constexpr float kSurfaceGapM = 1e-4f;

bool seesSun(const Bvh& bvh, const glm::vec3& x, const glm::vec3& towardsSun) {
  return !bvh.anyHit(x, towardsSun, 0.0f, kSunRayM);
}

// The sun's optical path to x in metres of nominal medium: its length inside the box, or the
// integral of D over it.
float sunPath(const MediumState& m, const glm::vec3& x, const glm::vec3& d, const glm::vec3& lo,
              const glm::vec3& hi) {
  const float s = sunPathInBox(x, d, lo, hi);
  if (!m.density || !(s > 0.0f)) return s;
  return m.density->integral(x, x - d * s);
}

// The ray's chord [t0, t1] through the box, clipped to [0, tMax]; false when empty.
bool chordInBox(const glm::vec3& e, const glm::vec3& v, const glm::vec3& lo, const glm::vec3& hi, float tMax,
                float& t0, float& t1) {
  t0 = 0.0f;
  t1 = tMax;
  for (int a = 0; a < 3; ++a) {
    if (v[a] == 0.0f) {
      if (e[a] < lo[a] || e[a] > hi[a]) return false;
      continue;
    }
    float ta = (lo[a] - e[a]) / v[a], tb = (hi[a] - e[a]) / v[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t1 > t0;
}

}  // namespace

glm::vec3 sunInScatter(const Bvh& bvh, const MediumState& medium, const SunState& sun, const glm::vec3& e,
                       const glm::vec3& v, float depthM, float maxStepM) {
  if (!sun.lit() || !(medium.scattering > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 lo = bvh.venue().boundsMin, hi = bvh.venue().boundsMax;
  float t0, t1;
  if (!chordInBox(e, v, lo, hi, depthM - kSurfaceGapM, t0, t1)) return glm::vec3(0.0f);
  const glm::vec3 d = sun.direction, towardsSun = -sun.direction;
  const int n = static_cast<int>(std::clamp(std::ceil((t1 - t0) / std::max(maxStepM, 1e-4f)), 64.0f, 1e6f));
  const double dt = (double(t1) - t0) / n;
  const float sigmaT = medium.extinction();
  const DensityField* field = medium.density.get();
  // cos a = dot(w_in, w_out): the light travels along d, the eye looks back along -v.
  const float p = phaseFunction(medium, -glm::dot(d, v));
  auto at = [&](double t) { return e + v * static_cast<float>(t); };
  auto visible = [&](double t) { return seesSun(bvh, at(t), towardsSun); };

  double sum = 0.0;
  // With a field the eye's optical path is carried along in increasing t.
  float eyePath = field ? field->integral(e, at(t0)) : 0.0f;
  double eyeT = t0;
  bool visPrev = visible(t0);
  for (int k = 0; k < n; ++k) {
    const double a = t0 + k * dt, b = a + dt;
    const bool visNext = visible(b);
    double fraction;
    if (visPrev == visNext) {
      fraction = visPrev ? 1.0 : 0.0;
    } else {
      double lo2 = a, hi2 = b;
      for (int i = 0; i < kEdgeBisections; ++i) {
        const double mid = 0.5 * (lo2 + hi2);
        (visible(mid) == visPrev ? lo2 : hi2) = mid;
      }
      const double edge = 0.5 * (lo2 + hi2);
      fraction = visPrev ? (edge - a) / dt : (b - edge) / dt;
    }
    visPrev = visNext;
    const double mid = a + 0.5 * dt;
    if (field) {
      eyePath += field->integral(at(eyeT), at(mid));
      eyeT = mid;
    }
    if (fraction <= 0.0) continue;
    const glm::vec3 x = at(mid);
    const float sPath = sunPath(medium, x, d, lo, hi);
    if (!field) {
      sum += fraction * std::exp(-double(sigmaT) * (double(sPath) + mid));
    } else {
      sum += fraction * field->sample(x) * std::exp(-double(sigmaT) * (double(sPath) + eyePath));
    }
  }
  return sun.illuminance * static_cast<float>(double(medium.scattering) * p * sum * dt);
}

glm::vec3 sunIrradiance(const Bvh& bvh, const MediumState& medium, const SunState& sun, const glm::vec3& position,
                        const glm::vec3& lifted, const glm::vec3& ng, const glm::vec3& n) {
  if (!sun.lit()) return glm::vec3(0.0f);
  const glm::vec3 towardsSun = -sun.direction;
  if (!(glm::dot(ng, towardsSun) > 0.0f)) return glm::vec3(0.0f);
  const float cosine = glm::dot(n, towardsSun);
  if (!(cosine > 0.0f)) return glm::vec3(0.0f);
  if (!seesSun(bvh, lifted, towardsSun)) return glm::vec3(0.0f);
  const float path = sunPath(medium, position, sun.direction, bvh.venue().boundsMin, bvh.venue().boundsMax);
  return sun.illuminance * (cosine * std::exp(-medium.extinction() * path));
}

}  // namespace haze
