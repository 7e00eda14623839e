// A stage with 16 beams in haze (the scene whose reference time is the denominator of the GPU
// renderer's speed ratio): beams add up linearly, each beam shows, and the time is printed.
// HAZE_REFERENCE_BENCH=1280x720 renders it at that size and prints the time (no assertion on it).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "renderer/reference/reference.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

// Floor, back wall, two boxes and a sphere; 16 parametric beams from a truss 6.5 m up.
FrameState sixteenBeamStage(Venue& v) {
  v = test::emptyVenue();
  const int grey = test::addMaterial(v, glm::vec3(0.5f));
  test::addFloor(v, 0.0f, 15.0f, grey);
  test::addQuad(v, {-15, 0, -6}, {15, 0, -6}, {15, 10, -6}, {-15, 10, -6}, grey);
  test::addBox(v, {-4, 0, -2}, {-2, 1, 0}, grey);
  test::addBox(v, {2, 0, -1}, {3, 2, 0}, grey);
  test::addUvSphere(v, {0, 1.7f, 0.5f}, 0.4f, 16, 32, grey);
  FrameState f;
  f.camera.position = {0, 2, 14};
  f.camera.target = {0, 2.5f, 0};
  f.camera.fovYDeg = 45;
  f.medium.scattering = 0.03f;
  f.medium.absorption = 0.005f;
  for (int k = 0; k < 16; ++k) {
    const glm::vec3 aim(0.3f * std::sin(k * 1.3f), -1.0f, 0.3f * std::cos(k * 0.7f));
    const float field = 10.0f + (k % 5) * 5.0f;
    const glm::vec3 colour(0.5f + 0.5f * std::sin(float(k)), 0.6f, 0.5f + 0.5f * std::cos(float(k)));
    f.beams.push_back(test::makeBeam({-7.5f + k, 6.5f, -1}, aim,
                                     test::parametric(field * 0.6f, field, 30000), field, colour));
  }
  return f;
}

TEST(ReferenceStage, SixteenBeamsAddUpAndEachShows) {
  Venue v;
  const FrameState f = sixteenBeamStage(v);
  const Bvh bvh(v);
  const int w = 32, h = 18;
  const auto start = std::chrono::steady_clock::now();
  const ReferenceImages all = renderReferenceImages(bvh, f, w, h);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("reference, 16 beams, %dx%d: %.3f s\n", w, h, seconds);
  FrameState left = f, right = f;
  left.beams.resize(8);
  right.beams.erase(right.beams.begin(), right.beams.begin() + 8);
  const ReferenceImages a = renderReferenceImages(bvh, left, w, h);
  const ReferenceImages b = renderReferenceImages(bvh, right, w, h);
  for (size_t k = 0; k < all.total.pixels.size(); ++k) {
    const glm::vec3 sum = a.inScattered.pixels[k] + b.inScattered.pixels[k];
    EXPECT_NEAR(glm::length(all.inScattered.pixels[k] - sum), 0.0f, 1e-5f * glm::length(sum) + 1e-9f);
    const glm::vec3 surf = a.surface.pixels[k] + b.surface.pixels[k];
    EXPECT_NEAR(glm::length(all.surface.pixels[k] - surf), 0.0f, 1e-5f * glm::length(surf) + 1e-9f);
  }
  // Each beam is seen: the ray towards a point 1 m down its axis gathers its light.
  for (const BeamState& beam : f.beams) {
    const glm::vec3 target = beam.pose.lensPosition + beam.pose.zb;
    const glm::vec3 dir = glm::normalize(target - f.camera.position);
    FrameState only = f;
    only.beams = {beam};
    EXPECT_GT(radianceAlongRay(bvh, only, f.camera.position, dir).inScattered.g, 0.0f);
  }

  int bw = 0, bh = 0;
  if (const char* size = std::getenv("HAZE_REFERENCE_BENCH");
      size && std::sscanf(size, "%dx%d", &bw, &bh) == 2 && bw > 0 && bh > 0) {
    const auto t0 = std::chrono::steady_clock::now();
    const ReferenceImages big = renderReferenceImages(bvh, f, bw, bh);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("reference, 16 beams, %dx%d: %.2f s (%zu triangles)\n", bw, bh, s,
                bvh.triangleCount());
    EXPECT_EQ(big.total.width, bw);
  }
}

}  // namespace
}  // namespace haze
