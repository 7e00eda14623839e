// The reference integrator. In-scattering per beam is marched only over the eye ray's chord
// through the beam's cone (I_eff is exactly 0 outside), in equal steps of the angle seen from
// the lens: with D the ray's distance to the lens and t = t_c + D tan(phi),
// dt / r^2 = dphi / D, so the 1/r^2 peak is integrated exactly and the samples follow the
// beam's angular structure (I_eff, gobo and shadow edges are all functions of direction seen
// from the lens). Visibility is sampled at step boundaries and shadow edges are located by
// bisection; everything else is sampled at step midpoints.
#include "renderer/reference/reference.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <memory>
#include <thread>

#include <glm/geometric.hpp>

#include "renderer/reference/cone.h"
#include "renderer/reference/sun.h"
#include "shows/scene/body_hit.h"
#include "shows/scene/body_shadow.h"
#include "shows/scene/camera_basis.h"
#include "shows/scene/physics.h"

namespace haze {

namespace {

// A ray closer than this to a lens passes through it: the integral diverges there (a point
// light seen directly), so the distance is clamped to keep the pixel finite.
constexpr double kMinLensDistanceM = 1e-6;
// Shadow rays stop this far short of their target, so the target's own surface never shadows it.
constexpr float kShadowEndGapM = 1e-4f;
constexpr int kEdgeBisections = 12;
// A step whose end values of I_eff differ by more than this fraction is split in 16.
constexpr float kIntensityJump = 0.2f;
constexpr int kIntensitySubsteps = 16;
// Soft shadows: a step across which the disc's visible fraction changes by more than this is
// split into as many pieces as the change holds (at most kSoftSubsteps).
constexpr double kSoftStepChange = 0.05;
constexpr int kSoftSubsteps = 16;

// The integral of D along a -> b: the path's length in metres of medium at the nominal density
// (docs/physics.md, "A medium that is not uniform"); its length itself in the uniform medium.
float densityLength(const MediumState& m, const glm::vec3& a, const glm::vec3& b) {
  return m.density ? m.density->integral(a, b) : glm::length(b - a);
}

struct ActiveBeam {
  const BeamState* beam;
  float cutoffRad;
  // Soft shadows (FrameState::softShadows): the lens disc's radius that V(x) sees; 0 = the
  // point test from the lens centre.
  float discRadiusM;
  // The other fixtures' bodies that can shadow it (body_shadow.h), tested in V(x) after the
  // venue; accels: the frame's mesh accelerations, by index into FrameState::bodyMeshes.
  ShadowCasters casters;
  const FrameState* frame = nullptr;
  const std::vector<std::shared_ptr<const MeshAccel>>* accels = nullptr;
};

std::vector<ActiveBeam> activeBeams(const FrameState& frame, const std::vector<std::shared_ptr<const MeshAccel>>& accels) {
  std::vector<ActiveBeam> out;
  const std::vector<BodyBound> boxBounds = bodyBounds(frame.bodies), meshBounds = bodyBounds(frame.bodyMeshes);
  for (const BeamState& b : frame.beams) {
    if (!b.optics.distribution || !(b.optics.dimmer > 0.0f)) continue;
    const glm::vec3& c = b.optics.color;
    if (!(c.r > 0.0f || c.g > 0.0f || c.b > 0.0f)) continue;
    const float cutoff = b.optics.cutoffHalfAngleRad();
    if (!(cutoff > 0.0f) || !std::isfinite(cutoff)) continue;
    // The cone test needs a convex cone; BeamOptics promises at most kMaxCutoffDeg (< 90).
    const float disc = frame.softShadows ? std::max(b.optics.lensRadiusM, 0.0f) : 0.0f;
    const float cone = std::min(cutoff, 89.9f * kPi / 180.0f);
    out.push_back({&b, cone, disc, shadowCasters(b, cone, boxBounds, meshBounds), &frame, &accels});
  }
  return out;
}

// V(x) for a point x at distance distM from the lens along the unit direction w: the venue,
// then the bodies of other fixtures that can lie in the beam.
bool visibleFromLens(const Bvh& bvh, const ActiveBeam& ab, const glm::vec3& lens, const glm::vec3& w, float distM,
                     const ReferenceOptions& o) {
  const float tMax = distM - kShadowEndGapM;
  if (!(tMax > o.lensClearanceM)) return true;
  if (bvh.anyHit(lens, w, o.lensClearanceM, tMax)) return false;
  if (ab.casters.empty()) return true;
  return !anyBodyHit(ab.frame->bodies, ab.frame->bodyMeshes, *ab.accels, ab.casters.boxes, ab.casters.meshes, lens, w,
                     o.lensClearanceM, tMax);
}

// Whether a caster's bound comes within radiusM of the segment from p along unit d, length len.
bool castersComeNear(const ActiveBeam& ab, const glm::vec3& p, const glm::vec3& d, float len, float radiusM) {
  for (const glm::vec4& s : ab.casters.spheres) {
    const glm::vec3 c(s);
    const float t = std::clamp(glm::dot(c - p, d), 0.0f, len);
    if (glm::length(p + d * t - c) <= s.w + radiusM) return true;
  }
  return false;
}

// The point of the lens disc (centre lens, radius, in the plane of xb and yb) at polar
// coordinates (rho, angle), rho as a fraction of the radius.
glm::vec3 discPoint(const BeamPose& pose, float radiusM, float rho, float angle) {
  return pose.lensPosition + (radiusM * rho) * (std::cos(angle) * pose.xb + std::sin(angle) * pose.yb);
}

// Whether the segment from the lens point p to x is free of triangles.
bool segmentClear(const Bvh& bvh, const ActiveBeam& ab, const glm::vec3& p, const glm::vec3& x,
                  const ReferenceOptions& o) {
  const glm::vec3 d = x - p;
  const float len = glm::length(d);
  if (!(len > 0.0f)) return true;
  return visibleFromLens(bvh, ab, p, d / len, len, o);
}

// V(x) with soft shadows (docs/physics.md, "Soft shadows"): the fraction of the lens disc
// visible from x. First a probe of nine points (the centre and eight on the rim, 45 degrees
// apart); when they agree that is the answer, otherwise the disc's area is sampled by
// `samples` stratified points (a sunflower: point k at radius sqrt((k + 0.5) / N),
// angle k times the golden angle, so every ring of equal area holds its share of points).
// The probe can miss a blocker that covers only a sliver of the rim between two rim probes
// (at most 1.2 % of the disc, where an edge cuts a 45-degree chord) or that fits between
// the probes without touching any (a pole much thinner than the disc, seen end-on).
double discVisibleFraction(const Bvh& bvh, const ActiveBeam& ab, const glm::vec3& x, int samples,
                           const ReferenceOptions& o) {
  const BeamPose& pose = ab.beam->pose;
  const float radius = ab.discRadiusM;
  if (o.lensDiscProbe) {
    // Every point of the cone from x to the disc lies within r_lens of the segment from x to
    // the centre: with no triangle that near, the whole disc is seen (exact, and one traversal
    // instead of nine rays where the haze is far from everything).
    const glm::vec3 d = x - pose.lensPosition;
    const float len = glm::length(d);
    if (len > 0.0f && !bvh.mayComeNear(pose.lensPosition, d / len, 0.0f, len, radius) &&
        !castersComeNear(ab, pose.lensPosition, d / len, len, radius))
      return 1.0;
    const bool centre = segmentClear(bvh, ab, pose.lensPosition, x, o);
    bool agree = true;
    for (int k = 0; k < 8 && agree; ++k)
      agree = segmentClear(bvh, ab, discPoint(pose, radius, 1.0f, k * (kPi / 4.0f)), x, o) == centre;
    if (agree) return centre ? 1.0 : 0.0;
  }
  const int n = std::max(samples, 1);
  constexpr float kGoldenAngle = 2.39996322972865332f;
  int clear = 0;
  for (int k = 0; k < n; ++k) {
    const float rho = std::sqrt((k + 0.5f) / n);
    clear += segmentClear(bvh, ab, discPoint(pose, radius, rho, k * kGoldenAngle), x, o) ? 1 : 0;
  }
  return static_cast<double>(clear) / n;
}

// L_in of one beam along [0, T] of the ray.
glm::vec3 inScatterOneBeam(const Bvh& bvh, const MediumState& medium, const ActiveBeam& ab,
                           const glm::vec3& e, const glm::vec3& v, float depthM,
                           const ReferenceOptions& o) {
  const BeamState& beam = *ab.beam;
  const glm::vec3 lens = beam.pose.lensPosition;
  const ConeInterval chord = intersectCone(e, v, lens, beam.pose.zb, ab.cutoffRad, 0.0, depthM);
  if (chord.empty()) return glm::vec3(0.0f);

  // Closest approach of the ray's line to the lens: t_c, and distance D.
  const double ex = e.x, ey = e.y, ez = e.z;
  const double vx = v.x, vy = v.y, vz = v.z;
  const double lx = lens.x - ex, ly = lens.y - ey, lz = lens.z - ez;
  const double tc = lx * vx + ly * vy + lz * vz;
  const double px = lx - tc * vx, py = ly - tc * vy, pz = lz - tc * vz;
  const double dist = std::max(std::sqrt(px * px + py * py + pz * pz), kMinLensDistanceM);
  const double phi0 = std::atan2(chord.t0 - tc, dist);
  const double phi1 = std::atan2(chord.t1 - tc, dist);
  const double range = phi1 - phi0;
  if (!(range > 0.0)) return glm::vec3(0.0f);
  const double steps = std::max(static_cast<double>(std::max(o.minStepsPerChord, 1)),
                                std::ceil(range / std::max(double(o.maxStepAngleRad), 1e-7)));
  const int n = static_cast<int>(std::min(steps, 1e6));
  const double dphi = range / n;
  const float sigmaT = medium.extinction();
  const DensityField* field = medium.density.get();
  // With a density field the eye's optical path is carried along the chord (the samples come
  // in increasing t), from the eye to the chord's start first.
  double tauT = chord.t0;
  float tauEye = 0.0f;
  if (field) tauEye = field->integral(e, e + v * static_cast<float>(chord.t0));
  auto eyeLength = [&](double t) {
    if (!field) return static_cast<float>(t);
    if (t > tauT) {
      tauEye += field->integral(e + v * static_cast<float>(tauT), e + v * static_cast<float>(t));
      tauT = t;
    }
    return tauEye;
  };

  auto pointAt = [&](double phi, glm::vec3& x, glm::vec3& w, float& r) {
    const double t = tc + dist * std::tan(phi);
    x = glm::vec3(float(ex + t * vx), float(ey + t * vy), float(ez + t * vz));
    const glm::vec3 d = x - lens;
    r = glm::length(d);
    w = r > 0.0f ? d / r : beam.pose.zb;
    return t;
  };
  auto visibleAt = [&](double phi) {
    glm::vec3 x, w;
    float r;
    pointAt(phi, x, w, r);
    return visibleFromLens(bvh, ab, lens, w, r, o);
  };

  // sigma_s p(a) I_eff exp(-sigma_t (r + t)) at one angle, without V and the constant 1/D.
  auto integrand = [&](double phi) {
    glm::vec3 x, w;
    float r;
    const double t = pointAt(phi, x, w, r);
    const glm::vec3 intensity = beamIntensityTowards(beam, x);
    if (intensity == glm::vec3(0.0f)) return glm::vec3(0.0f);
    // cos a = dot(w_in, w_out) with w_in = w (the way the light travels), w_out = -v.
    const float p = phaseFunction(medium, -glm::dot(w, v));
    if (!field) return intensity * (p * std::exp(-sigmaT * (r + static_cast<float>(t))));
    // sigma_s(x) = D(x) sigma_s, and both transmittances integrals of sigma_t(x).
    const float path = field->integral(lens, x) + eyeLength(t);
    return intensity * (field->sample(x) * p * std::exp(-sigmaT * path));
  };
  auto intensityAt = [&](double phi) {
    glm::vec3 x, w;
    float r;
    pointAt(phi, x, w, r);
    const glm::vec3 i = beamIntensityTowards(beam, x);
    return i.r + i.g + i.b;
  };

  // Soft shadows: V is the disc's visible fraction, continuous across a penumbra; sampled at
  // the step boundaries, a step whose two values differ by more than kSoftStepChange is split
  // into up to kSoftSubsteps midpoints (a narrow penumbra, a blocker close to the receiver),
  // otherwise the mean of the two ends is the step's V.
  auto fractionAt = [&](double phi) {
    glm::vec3 x, w;
    float r;
    pointAt(phi, x, w, r);
    return discVisibleFraction(bvh, ab, x, o.lensDiscSamples, o);
  };
  const bool soft = ab.discRadiusM > 0.0f;
  double fracPrev = soft ? fractionAt(phi0) : 1.0;

  glm::vec3 sum(0.0f);
  bool visPrev = !soft && o.refineShadowEdges ? visibleAt(phi0) : true;
  float iPrev = o.refineIntensityEdges ? intensityAt(phi0) : 0.0f;
  for (int k = 0; k < n; ++k) {
    const double a = phi0 + k * dphi;
    const double b = a + dphi;
    // Visible fraction of the step.
    double visible;
    if (soft) {
      const double fracNext = fractionAt(b);
      const double change = std::fabs(fracNext - fracPrev);
      if (change <= kSoftStepChange) {
        visible = 0.5 * (fracPrev + fracNext);
      } else {
        const int m = std::min(kSoftSubsteps, static_cast<int>(std::ceil(change / kSoftStepChange)));
        visible = 0.0;
        for (int i = 0; i < m; ++i) visible += fractionAt(a + (i + 0.5) * dphi / m);
        visible /= m;
      }
      fracPrev = fracNext;
    } else if (o.refineShadowEdges) {
      const bool visNext = visibleAt(b);
      if (visPrev == visNext) {
        visible = visPrev ? 1.0 : 0.0;
      } else {
        double lo = a, hi = b;  // V(lo) = visPrev, V(hi) = visNext
        for (int i = 0; i < kEdgeBisections; ++i) {
          const double mid = 0.5 * (lo + hi);
          (visibleAt(mid) == visPrev ? lo : hi) = mid;
        }
        const double edge = 0.5 * (lo + hi);
        visible = visPrev ? (edge - a) / dphi : (b - edge) / dphi;
      }
      visPrev = visNext;
    } else {
      visible = visibleAt(a + 0.5 * dphi) ? 1.0 : 0.0;
    }
    // A steep change of I_eff within the step (a gobo edge, a photometric cut-off): sample the
    // step finely instead of once.
    int substeps = 1;
    if (o.refineIntensityEdges) {
      const float iNext = intensityAt(b);
      if (std::fabs(iNext - iPrev) > kIntensityJump * std::max(iNext, iPrev))
        substeps = kIntensitySubsteps;
      iPrev = iNext;
    }
    if (visible <= 0.0) continue;
    glm::vec3 step(0.0f);
    for (int s = 0; s < substeps; ++s) step += integrand(a + (s + 0.5) * dphi / substeps);
    sum += step * static_cast<float>(visible / substeps);
  }
  return sum * static_cast<float>(medium.scattering * dphi / dist);
}

// L_surf at a point of a surface with geometric normal ng and shading normal n (both unit).
glm::vec3 shadeSurface(const Bvh& bvh, const FrameState& frame, const std::vector<ActiveBeam>& beams,
                       const glm::vec3& position, glm::vec3 ng, glm::vec3 n, const glm::vec3& albedo,
                       const glm::vec3& emission, const glm::vec3& v, const ReferenceOptions& o) {
  // Two-sided: both normals turned towards the eye.
  if (glm::dot(ng, v) > 0.0f) ng = -ng;
  if (glm::dot(n, ng) < 0.0f) n = -n;
  const float maxAbs = std::max({std::fabs(position.x), std::fabs(position.y), std::fabs(position.z)});
  // Lift the shadow ray's end off the surface by more than float rounding at this position.
  const glm::vec3 lifted = position + ng * (1e-4f + 4e-6f * maxAbs);
  const float sigmaT = frame.medium.extinction();

  glm::vec3 direct(0.0f);
  for (const ActiveBeam& ab : beams) {
    const glm::vec3 lens = ab.beam->pose.lensPosition;
    const glm::vec3 toLens = lens - position;
    if (!(glm::dot(ng, toLens) > 0.0f)) continue;  // the light is behind the surface's plane
    const float r = glm::length(toLens);
    if (!(r > 0.0f)) continue;
    const float cosine = glm::dot(n, toLens / r);
    if (!(cosine > 0.0f)) continue;
    const glm::vec3 intensity = beamIntensityTowards(*ab.beam, position);
    if (intensity == glm::vec3(0.0f)) continue;
    double vis = 1.0;
    if (ab.discRadiusM > 0.0f) {
      // The segments end kShadowEndGapM short of x: aim that far past the lifted point.
      vis = discVisibleFraction(bvh, ab, lifted + glm::normalize(lifted - lens) * kShadowEndGapM,
                                o.surfaceDiscSamples, o);
      if (!(vis > 0.0)) continue;
    } else {
      const glm::vec3 d = lifted - lens;
      const float len = glm::length(d);
      if (len > 0.0f && !visibleFromLens(bvh, ab, lens, d / len, len + kShadowEndGapM, o)) continue;
    }
    const float path = frame.medium.density ? frame.medium.density->integral(lens, position) : r;
    direct += intensity * static_cast<float>(vis * cosine * std::exp(-sigmaT * path) / (r * r));
  }
  direct += sunIrradiance(bvh, frame.medium, frame.sun, position, lifted, ng, n);
  return albedo / kPi * direct + albedo * frame.medium.ambient + emission;
}

glm::vec3 surfaceRadiance(const Bvh& bvh, const FrameState& frame,
                          const std::vector<ActiveBeam>& beams, const RayHit& hit,
                          const glm::vec3& v, const ReferenceOptions& o) {
  const SurfacePoint s = bvh.surfaceAt(hit);
  const Venue& venue = bvh.venue();
  return shadeSurface(bvh, frame, beams, s.positionM, s.geometricNormal, s.shadingNormal,
                      venue.albedo(*s.primitive, s.uv), venue.emission(*s.primitive, s.uv), v, o);
}

struct LensHit {
  const BeamState* beam = nullptr;
  float tM = 0.0f;
};

// The nearest lens disc on the ray before tMax (docs/physics.md, "The lens"). Every beam has
// one, lit or not: a dark lens is still an opaque black disc.
LensHit closestLens(const FrameState& frame, const glm::vec3& e, const glm::vec3& v, float tMax) {
  LensHit best;
  for (const BeamState& b : frame.beams) {
    const float r = b.optics.lensRadiusM;
    if (!(r > 0.0f)) continue;
    const glm::vec3& z = b.pose.zb;
    const double dv = glm::dot(v, z);
    if (dv == 0.0) continue;  // along the disc's plane: the rim, which has no width
    const glm::vec3 lens = b.pose.lensPosition;
    const double t = glm::dot(glm::dvec3(lens) - glm::dvec3(e), glm::dvec3(z)) / dv;
    if (!(t > 0.0) || !(t < tMax) || (best.beam && !(t < best.tM))) continue;
    const glm::dvec3 x = glm::dvec3(e) + t * glm::dvec3(v) - glm::dvec3(lens);
    if (glm::dot(x, x) > double(r) * r) continue;
    best = {&b, static_cast<float>(t)};
  }
  return best;
}

}  // namespace

glm::vec3 lensLuminance(const BeamState& beam, const glm::vec3& eye) {
  const glm::vec3 toEye = eye - beam.pose.lensPosition;
  const float d = glm::length(toEye);
  if (!(d > 0.0f)) return glm::vec3(0.0f);
  const float cosE = glm::dot(toEye / d, beam.pose.zb);
  if (!(cosE > 0.0f)) return glm::vec3(0.0f);  // the back of the lens is black
  const float r = beam.optics.lensRadiusM;
  if (!(r > 0.0f) || !beam.optics.distribution) return glm::vec3(0.0f);
  return beamIntensityTowards(beam, eye) / (kPi * r * r * cosE);
}

namespace {

PixelRadiance radiance(const Bvh& bvh, const FrameState& frame,
                       const std::vector<ActiveBeam>& beams,
                       const std::vector<std::shared_ptr<const MeshAccel>>& accels, const glm::vec3& e,
                       const glm::vec3& v, const ReferenceOptions& o) {
  PixelRadiance out;
  const float far = frame.camera.farM > 0.0f ? frame.camera.farM : 100.0f;
  const RayHit hit = bvh.closestHit(e, v, 0.0f, far);
  out.hitSurface = hit.hit();
  out.depthM = out.hitSurface ? hit.tM : far;
  const BodyHit body = closestBody(frame.bodies, frame.bodyMeshes, accels, e, v, out.depthM);
  if (body.hit) {
    out.hitSurface = true;
    out.depthM = body.tM;
  }
  const LensHit lens = closestLens(frame, e, v, out.depthM);
  if (lens.beam) {
    out.hitSurface = false;
    out.hitLens = true;
    out.depthM = lens.tM;
  }
  const float transmit = std::exp(-frame.medium.extinction() * densityLength(frame.medium, e, e + v * out.depthM));
  if (out.hitLens) {
    out.surface = lensLuminance(*lens.beam, e) * transmit;
  } else if (body.hit) {
    out.surface = shadeSurface(bvh, frame, beams, e + v * body.tM, body.geometricNormal, body.shadingNormal,
                               body.albedo, glm::vec3(0.0f), v, o) *
                  transmit;
  } else if (out.hitSurface) {
    out.surface = surfaceRadiance(bvh, frame, beams, hit, v, o) * transmit;
  } else {
    out.background = frame.medium.background * transmit;
  }
  if (frame.medium.scattering > 0.0f) {
    for (const ActiveBeam& ab : beams)
      out.inScattered += inScatterOneBeam(bvh, frame.medium, ab, e, v, out.depthM, o);
    out.inScattered += sunInScatter(bvh, frame.medium, frame.sun, e, v, out.depthM, o.sunStepM);
  }
  return out;
}

}  // namespace

glm::vec3 cameraRayDirection(const CameraState& camera, int width, int height, float pixelX,
                             float pixelY) {
  const CameraBasis b = cameraBasis(camera, static_cast<float>(width) / static_cast<float>(height));
  const float sx = (2.0f * pixelX / static_cast<float>(width) - 1.0f) * b.tanX;
  const float sy = (1.0f - 2.0f * pixelY / static_cast<float>(height)) * b.tanY;
  return glm::normalize(b.forward + sx * b.right + sy * b.up);
}

PixelRadiance radianceAlongRay(const Bvh& bvh, const FrameState& frame, const glm::vec3& origin,
                               const glm::vec3& dir, const ReferenceOptions& options) {
  const auto accels = bodyMeshAccels(frame.bodyMeshes);
  return radiance(bvh, frame, activeBeams(frame, accels), accels, origin, dir, options);
}

PixelRadiance radianceAtPixel(const Bvh& bvh, const FrameState& frame, int width, int height,
                              int i, int j, const ReferenceOptions& options) {
  const glm::vec3 dir = cameraRayDirection(frame.camera, width, height, i + 0.5f, j + 0.5f);
  return radianceAlongRay(bvh, frame, frame.camera.position, dir, options);
}

ReferenceImages renderReferenceImages(const Bvh& bvh, const FrameState& frame, int width,
                                      int height, const ReferenceOptions& options) {
  assert(width > 0 && height > 0 && "renderReference: validate the image size before calling");
  ReferenceImages out;
  const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
  for (ImageRGB* img : {&out.total, &out.surface, &out.inScattered}) {
    img->width = width;
    img->height = height;
    img->pixels.assign(count, glm::vec3(0.0f));
  }
  out.depthM.assign(count, 0.0f);
  const auto accels = bodyMeshAccels(frame.bodyMeshes);
  const std::vector<ActiveBeam> beams = activeBeams(frame, accels);

  std::atomic<int> nextRow{0}, rowsDone{0};
  const std::thread::id caller = std::this_thread::get_id();
  auto worker = [&] {
    for (int j = nextRow++; j < height; j = nextRow++) {
      for (int i = 0; i < width; ++i) {
        const glm::vec3 dir = cameraRayDirection(frame.camera, width, height, i + 0.5f, j + 0.5f);
        const PixelRadiance px = radiance(bvh, frame, beams, accels, frame.camera.position, dir, options);
        const size_t at = static_cast<size_t>(j) * width + i;
        out.total.pixels[at] = px.total();
        out.surface.pixels[at] = px.surface + px.background;
        out.inScattered.pixels[at] = px.inScattered;
        out.depthM[at] = px.depthM;
      }
      const int done = ++rowsDone;
      if (options.onRows && std::this_thread::get_id() == caller) options.onRows(done, height);
    }
  };
  int threads = options.threads > 0 ? options.threads
                                    : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, std::max(1, height));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return out;
}

ImageRGB renderReference(const Venue& venue, const FrameState& frame, int width, int height,
                         const ReferenceOptions& options) {
  const Bvh bvh(venue);
  return std::move(renderReferenceImages(bvh, frame, width, height, options).total);
}

}  // namespace haze
