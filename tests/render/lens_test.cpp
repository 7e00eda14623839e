// Looking into a lamp: the pixels around a lens,
// GPU against the reference and against the closed form of docs/physics.md, "The lens".
// LensInScatter: no disc (r_lens = 0), so only the in-scattering just in front of the lens is
// seen; the lamp's own pixel came out black on the GPU. LensDisc: the glowing disc, seen along
// the beam and from 30 degrees off its axis (an ellipse): inside it the GPU is within 10 % of
// I_eff(w_e) / (pi r^2 cos theta_e) exp(-sigma_t t) plus the reference's in-scattering, and
// the ring of pixels around it within 10 % of the reference.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/render_session.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/camera_basis.h"
#include "shows/scene/physics.h"

namespace haze::test {
namespace {

constexpr int kW = 160, kH = 120;
constexpr float kSigmaS = 0.05f;
const glm::vec3 kLens{0.0f, 3.0f, 0.0f};

// A 2000 W-class spot 8 m from the camera; the camera looks at the lens through a narrow lens
// (10 degrees), so a 5 cm lens spans about nine pixels, and off a pixel corner.
FrameState lampFrame(float offAxisDeg, float lensRadiusM) {
  FrameState f;
  const float a = glm::radians(offAxisDeg);
  f.camera.position = kLens + 8.0f * glm::vec3(std::sin(a), 0.0f, std::cos(a));
  f.camera.target = kLens + glm::vec3(0.0017f, 0.0011f, 0.0f);
  f.camera.fovYDeg = 10.0f;
  f.medium.scattering = kSigmaS;
  // Off the axis within the beam (30 degrees): a wide spot, so the eye sees a lit ellipse.
  // Farther (60 degrees, the audience seeing a spot aimed at the stage): outside the cone.
  const bool wide = offAxisDeg > 0.0f && offAxisDeg < 45.0f;
  f.beams.push_back(makeBeam(kLens, {0, 0, 1}, wide ? 50.0f : 15.0f, wide ? 70.0f : 25.0f, 150000.0f));
  f.beams[0].optics.lensRadiusM = lensRadiusM;
  return f;
}

struct PixelCheck {
  int checked = 0, failed = 0;
  double worst = 0.0;
  void add(double actual, double expected, double tolerance, int x, int y, const char* what) {
    ++checked;
    const double rel = std::abs(actual - expected) / std::max(expected, 1e-9);
    worst = std::max(worst, rel);
    if (rel > tolerance) {
      ++failed;
      if (failed <= 8) std::printf("  %s pixel (%d, %d): %.6g, expected %.6g (%.1f %%)\n", what, x, y, actual, expected, 100 * rel);
    }
  }
};

// Where on the image the lens centre projects (fractional pixel coordinates, row 0 at the top).
glm::vec2 lensPixel(const FrameState& f) {
  const CameraBasis b = cameraBasis(f.camera, float(kW) / kH);
  const glm::vec3 d = kLens - f.camera.position;
  const float z = glm::dot(d, b.forward);
  const float sx = glm::dot(d, b.right) / (z * b.tanX), sy = glm::dot(d, b.up) / (z * b.tanY);
  return {(sx + 1.0f) * 0.5f * kW, (1.0f - sy) * 0.5f * kH};
}

class LensVsReference : public GlTest {
 protected:
  ImageRGB gpu(const Venue& venue, const FrameState& f, Quality q) {
    return renderRadiance(venue, f, renderSettingsFor(q, kW, kH));
  }
};

void checkInScatter(const Venue& venue, const FrameState& f, const std::vector<ImageRGB>& images) {
  const Bvh bvh(venue);
  const ReferenceImages ref = renderReferenceImages(bvh, f, kW, kH);
  const glm::vec2 c = lensPixel(f);
  const int cx = int(c.x), cy = int(c.y);
  float refMax = 0.0f;
  for (int y = cy - 3; y <= cy + 3; ++y)
    for (int x = cx - 3; x <= cx + 3; ++x) refMax = std::max(refMax, ref.total.at(x, y).r);
  std::printf("lamp pixel (%d, %d): reference %.1f cd/m^2, brightest of 7x7 %.1f\n", cx, cy, ref.total.at(cx, cy).r, refMax);
  EXPECT_GT(refMax, 100.0f) << "the scene should put bright in-scattering next to the lens";
  for (size_t i = 0; i < images.size(); ++i) {
    const ImageRGB& img = images[i];
    ASSERT_EQ(img.width, kW);
    PixelCheck check;
    for (int y = cy - 3; y <= cy + 3; ++y)
      for (int x = cx - 3; x <= cx + 3; ++x) check.add(img.at(x, y).r, ref.total.at(x, y).r, 0.10, x, y, "in-scatter");
    std::printf("[ %s ] lamp pixel %.1f (reference %.1f), neighbour %.1f (reference %.1f); worst of 7x7 %.1f %%\n",
                i == 1 ? "high" : "default", img.at(cx, cy).r, ref.total.at(cx, cy).r,
                img.at(cx + 1, cy).r, ref.total.at(cx + 1, cy).r, 100 * check.worst);
    EXPECT_EQ(check.failed, 0) << check.failed << " of " << check.checked << " pixels off by more than 10 %";
  }
}

TEST_F(LensVsReference, InScatterInFrontOfTheLensIsNotLost) {
  const Venue venue = floorVenue(16.0f, 0.2f);
  // Along the beam: the camera inside the cone, looking into the lamp.
  const FrameState along = lampFrame(0.0f, 0.0f);
  checkInScatter(venue, along, {gpu(venue, along, Quality::Default), gpu(venue, along, Quality::High)});
  // From the audience, 60 degrees off the axis: the eye ray grazes the apex of the cone.
  const FrameState audience = lampFrame(60.0f, 0.0f);
  checkInScatter(venue, audience, {gpu(venue, audience, Quality::Default), gpu(venue, audience, Quality::High)});
}

void checkDisc(const Venue& venue, const FrameState& f, const ImageRGB& img, const char* name) {
  const Bvh bvh(venue);
  const ReferenceImages ref = renderReferenceImages(bvh, f, kW, kH);
  const BeamState& b = f.beams[0];
  const float r = b.optics.lensRadiusM;
  const glm::vec3 eye = f.camera.position;
  const glm::vec3 we = glm::normalize(eye - kLens);
  const double cosE = glm::dot(we, b.pose.zb);
  // The closed form, from the photometry directly: I_eff(w_e) / (pi r^2 cos theta_e).
  const double lLens = beamIntensityTowards(b, eye).r / (3.14159265358979 * r * r * cosE);
  PixelCheck disc, ring;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const glm::vec3 v = cameraRayDirection(f.camera, kW, kH, x + 0.5f, y + 0.5f);
      const float t = glm::dot(kLens - eye, b.pose.zb) / glm::dot(v, b.pose.zb);
      const float rho = glm::length(eye + t * v - kLens) / r;  // where the ray meets the disc's plane
      if (rho < 0.9f) {
        const PixelRadiance px = radianceAlongRay(bvh, f, eye, v);
        EXPECT_TRUE(px.hitLens) << name << " (" << x << ", " << y << ")";
        const double expected = lLens * std::exp(-f.medium.extinction() * t) + ref.inScattered.at(x, y).r;
        disc.add(img.at(x, y).r, expected, 0.10, x, y, "disc");
        EXPECT_NEAR(ref.total.at(x, y).r, expected, 1e-3 * expected) << "the reference's lens, pixel " << x << ", " << y;
      } else if (rho > 1.15f && rho < 2.5f) {
        ring.add(img.at(x, y).r, ref.total.at(x, y).r, 0.10, x, y, "ring");
      }
    }
  std::printf("[ %s ] L_lens %.4g cd/m^2: %d disc pixels (worst %.2f %%), %d ring pixels (worst %.2f %%)\n", name, lLens,
              disc.checked, 100 * disc.worst, ring.checked, 100 * ring.worst);
  EXPECT_GT(disc.checked, 20) << name;
  EXPECT_GT(ring.checked, 40) << name;
  EXPECT_EQ(disc.failed, 0) << name;
  EXPECT_EQ(ring.failed, 0) << name;
}

TEST_F(LensVsReference, LensSeenAlongTheBeamGlows) {
  const Venue venue = floorVenue(16.0f, 0.2f);
  const FrameState f = lampFrame(0.0f, 0.05f);
  checkDisc(venue, f, gpu(venue, f, Quality::Default), "along_default");
  checkDisc(venue, f, gpu(venue, f, Quality::High), "along_high");
}

TEST_F(LensVsReference, LensSeenFromTheSideIsAnEllipse) {
  const Venue venue = floorVenue(16.0f, 0.2f);
  const FrameState f = lampFrame(30.0f, 0.05f);
  checkDisc(venue, f, gpu(venue, f, Quality::Default), "side_default");
  checkDisc(venue, f, gpu(venue, f, Quality::High), "side_high");
}

// Outside the beam the front face is dark (I_eff(w_e) = 0) and still hides what is behind it.
TEST_F(LensVsReference, LensSeenFromOutsideTheBeamIsDark) {
  const Venue venue = floorVenue(16.0f, 0.2f);
  const FrameState f = lampFrame(60.0f, 0.05f);
  checkDisc(venue, f, gpu(venue, f, Quality::Default), "audience_default");
}

}  // namespace
}  // namespace haze::test
