// The planes pass draws each beam only over its footprint polygon, so the polygon must hold the
// projection of every point of the cone (up to the given length) that the camera sees: checked
// for random beams, cameras and points, against the projection written out here.
#include <random>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "render_test_util.h"
#include "renderer/beam_footprint.h"
#include "shows/scene/camera_basis.h"

namespace haze::test {
namespace {

bool insideConvex(const BeamFootprint& fp, glm::vec2 p) {
  for (int i = 0; i < fp.vertexCount; ++i) {
    const glm::vec2 a = fp.polygonNdc[static_cast<size_t>(i)];
    const glm::vec2 b = fp.polygonNdc[static_cast<size_t>((i + 1) % fp.vertexCount)];
    if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < -1e-4f) return false;  // right of a CCW edge
  }
  return true;
}

TEST(BeamFootprint, HoldsEveryVisiblePointOfTheCone) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), unit(0.0f, 1.0f);
  int checked = 0, partial = 0;
  for (int trial = 0; trial < 300; ++trial) {
    CameraState cam;
    cam.position = glm::vec3(8.0f * u(rng), 1.0f + 4.0f * unit(rng), 8.0f + 6.0f * u(rng));
    cam.target = glm::vec3(3.0f * u(rng), 2.0f * unit(rng), 3.0f * u(rng));
    cam.fovYDeg = 30.0f + 40.0f * unit(rng);
    const float aspect = 0.75f + unit(rng);
    const glm::vec3 lens(6.0f * u(rng), 3.0f + 5.0f * unit(rng), 6.0f * u(rng));
    const glm::vec3 axis = glm::normalize(glm::vec3(u(rng), -1.0f - unit(rng), u(rng)));
    const float field = 5.0f + 50.0f * unit(rng);
    const BeamState beam = makeBeam(lens, axis, field, field * 1.4f, 10000.0f);
    const float length = 3.0f + 15.0f * unit(rng);
    const BeamFootprint fp = beamFootprint(beam, cam, aspect, length);
    const float cutoff = beam.optics.cutoffHalfAngleRad();

    const CameraBasis basis = cameraBasis(cam, aspect);
    const glm::vec3 f = basis.forward, r = basis.right, up = basis.up;
    const float tanY = basis.tanY, tanX = basis.tanX;
    bool anyVisible = false;
    for (int k = 0; k < 400; ++k) {
      // A point inside the cone, no farther than `length` along the axis.
      const float along = length * unit(rng);
      const float radius = along * std::tan(cutoff) * std::sqrt(unit(rng));
      const float a = 6.2831853f * unit(rng);
      const glm::vec3 p = lens + along * beam.pose.zb +
                          radius * (std::cos(a) * beam.pose.xb + std::sin(a) * beam.pose.yb);
      const glm::vec3 d = p - cam.position;
      const float z = glm::dot(d, f);
      if (z <= cam.nearM * 1.01f) continue;
      const glm::vec2 ndc(glm::dot(d, r) / (z * tanX), glm::dot(d, up) / (z * tanY));
      if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f) continue;  // off screen
      anyVisible = true;
      ASSERT_TRUE(fp.visible) << "trial " << trial << ": a visible cone point, no footprint";
      EXPECT_TRUE(insideConvex(fp, ndc)) << "trial " << trial << ": point at (" << ndc.x << ", " << ndc.y
                                         << ") outside the footprint";
      EXPECT_GE(z, fp.zNear - 1e-3f);
      EXPECT_LE(z, fp.zFar + 1e-3f);
      ++checked;
    }
    if (anyVisible && fp.areaNdc() < 3.99f) ++partial;
  }
  EXPECT_GT(checked, 10000);
  // Most footprints are a part of the screen, not all of it: the culling does something.
  EXPECT_GT(partial, 100);
}

}  // namespace
}  // namespace haze::test
