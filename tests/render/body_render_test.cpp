// Fixture bodies on the GPU against the CPU reference (docs/rendering.md, "Fixture bodies"): a
// moving head panned and tilted, lit by a wash from the side and seen up close in haze, with
// its own beam on. Over the body's pixels (the reference's rays that end on a body box, away
// from its silhouette) the GPU's radiance must match the reference's; the head hides the venue
// behind it, the lens still glows in front of the head, and a frame without bodies shows the
// floor there instead. The same for a GDTF body's meshes (the BMFL's .3ds models), and a head
// drawn at two tilts has moved its silhouette.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "app/render_session.h"
#include "fixtures/gdtf.h"
#include "fixtures/pose.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "test_data.h"

namespace haze::test {
namespace {

constexpr int kW = 160, kH = 120;

FrameState bodyFrame() {
  FrameState f;
  const glm::vec3 pivot(0.0f, 4.0f, 0.0f), rotation(0.0f);
  const float pan = 30.0f, tilt = 40.0f;
  const glm::vec3 lensOffset(0.0f, -0.2f, 0.0f);
  f.camera.position = pivot + glm::vec3(2.5f, -0.6f, 2.0f);
  f.camera.target = pivot;
  f.camera.fovYDeg = 25.0f;
  f.medium.scattering = 0.02f;
  f.medium.ambient = glm::vec3(0.5f);
  BeamState own = makeBeam(pivot, {0, -1, 0}, 15.0f, 20.0f, 50000.0f);
  own.pose = beamPose(pivot, rotation, pan, tilt, lensOffset);
  own.optics.lensRadiusM = 0.05f;
  f.beams.push_back(own);
  // A wash from the camera's side lights the faces the camera sees.
  BeamState wash = makeBeam(pivot + glm::vec3(4.0f, 1.0f, 3.0f), glm::normalize(glm::vec3(-4.0f, -1.0f, -3.0f)), 40.0f,
                            60.0f, 20000.0f);
  wash.optics.lensRadiusM = 0.0f;
  f.beams.push_back(wash);
  for (size_t i = 0; i < f.beams.size(); ++i) f.beams[i].poseKey = f.beams[i].opticsKey = i + 1;
  poseBody(defaultBody(0.05f, {lensOffset}, true), pivot, rotation, pan, tilt, f.bodies);
  return f;
}

class BodyVsReference : public GlTest {
 protected:
  ImageRGB gpu(const Venue& venue, const FrameState& f, Quality q) {
    return renderRadiance(venue, f, renderSettingsFor(q, kW, kH));
  }
};

// Which box (index into frame.bodies) the ray of pixel (x, y) ends on, -1 for none.
int bodyAt(const FrameState& f, float x, float y) {
  const glm::vec3 v = cameraRayDirection(f.camera, kW, kH, x, y);
  int best = -1;
  float t = f.camera.farM;
  for (size_t i = 0; i < f.bodies.size(); ++i) {
    const BoxHit h = intersectBox(f.bodies[i], f.camera.position, v, t);
    if (h.hit) {
      best = static_cast<int>(i);
      t = h.tM;
    }
  }
  return best;
}

TEST_F(BodyVsReference, BodyPixelsMatchTheReference) {
  const Venue venue = floorVenue(16.0f, 0.3f);
  const FrameState f = bodyFrame();
  const Bvh bvh(venue);
  const ReferenceImages ref = renderReferenceImages(bvh, f, kW, kH);
  for (Quality q : {Quality::Default, Quality::High}) {
    const ImageRGB img = gpu(venue, f, q);
    ASSERT_EQ(img.width, kW);
    const double tolerance = q == Quality::High ? 0.03 : 0.06, meanLimit = q == Quality::High ? 0.004 : 0.01;
    int interior = 0, failed = 0, lit = 0;
    double worst = 0.0, sumRel = 0.0;
    for (int y = 1; y < kH - 1; ++y)
      for (int x = 1; x < kW - 1; ++x) {
        // Away from silhouettes and face edges: the pixel's corners all end on the same box.
        const int b = bodyAt(f, x + 0.5f, y + 0.5f);
        if (b < 0) continue;
        bool inside = true;
        for (float dx : {0.0f, 1.0f})
          for (float dy : {0.0f, 1.0f}) inside = inside && bodyAt(f, x + dx, y + dy) == b;
        if (!inside) continue;
        const PixelRadiance px = radianceAtPixel(bvh, f, kW, kH, x, y);
        if (px.hitLens) continue;
        ++interior;
        const double want = ref.total.at(x, y).r, got = img.at(x, y).r;
        if (ref.surface.at(x, y).r > 0.5) ++lit;
        const double rel = std::abs(got - want) / std::max(want, 1e-6);
        worst = std::max(worst, rel);
        sumRel += rel;
        // Tolerance: the surface shading is the same formula in float on both; what differs is
        // the in-scattering in front of the body (the GPU's planes against the reference's march)
        // and the shadow-map lookups. Measured: mean 0.59 %, worst 4.0 % at default; 0.21 % and
        // 1.6 % at high. Limits: 1.5 to 2 times those.
        if (rel > tolerance && ++failed <= 8)
          std::printf("  pixel (%d, %d) on box %d: %.5g, reference %.5g (%.1f %%)\n", x, y, b, got, want, 100 * rel);
      }
    std::printf("[ %s ] %d body pixels (%d lit by the wash): mean %.2f %%, worst %.2f %%\n",
                q == Quality::High ? "high" : "default", interior, lit, 100 * sumRel / std::max(interior, 1), 100 * worst);
    EXPECT_GT(interior, 300) << "the body should fill a good part of the image";
    EXPECT_GT(lit, 100) << "the wash should light the faces the camera sees";
    EXPECT_EQ(failed, 0) << failed << " of " << interior << " body pixels off by more than " << 100 * tolerance << " %";
    EXPECT_LT(sumRel / std::max(interior, 1), meanLimit);
  }
}

TEST_F(BodyVsReference, WithoutBodiesTheFloorShowsThere) {
  const Venue venue = floorVenue(16.0f, 0.3f);
  FrameState with = bodyFrame();
  FrameState without = with;
  without.bodies.clear();
  const ImageRGB a = gpu(venue, with, Quality::Draft), b = gpu(venue, without, Quality::Draft);
  ASSERT_EQ(a.width, kW);
  ASSERT_EQ(b.width, kW);
  // Where a body is, the image changes; elsewhere (away from the body) nothing does.
  int changedOnBody = 0, onBody = 0, changedElsewhere = 0, elsewhere = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float d = glm::length(a.at(x, y) - b.at(x, y)) / std::max(glm::length(b.at(x, y)), 1e-3f);
      bool near = false;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) near = near || bodyAt(with, x + 0.5f + dx, y + 0.5f + dy) >= 0;
      if (bodyAt(with, x + 0.5f, y + 0.5f) >= 0) {
        ++onBody;
        changedOnBody += d > 0.05f;
      } else if (!near) {
        ++elsewhere;
        changedElsewhere += d > 0.05f;
      }
    }
  std::printf("body pixels changed %d of %d; elsewhere %d of %d\n", changedOnBody, onBody, changedElsewhere, elsewhere);
  EXPECT_GT(changedOnBody, onBody * 9 / 10);
  // Elsewhere the beams' in-scattering is the same; draft quality's noise is frame to frame
  // deterministic (one jittered frame, the same seed), so nothing away from the body moves.
  EXPECT_EQ(changedElsewhere, 0);
}

// ---- GDTF meshes: the BMFL's base, yoke and head models ----

const Body& bmflBody() {
  static const Body body = [] {
    auto g = loadGdtf(test::dataFile("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf"));
    EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error().str());
    return g.ok() ? g->profile->housing() : Body{};
  }();
  return body;
}

FrameState meshFrame(float tiltDeg) {
  FrameState f = bodyFrame();
  f.bodies.clear();
  const glm::vec3 pivot(0.0f, 4.0f, 0.0f), rotation(0.0f);
  f.beams[0].pose = beamPose(pivot, rotation, 30.0f, tiltDeg, glm::vec3(0.0f, -0.33f, 0.0f));
  f.camera.position = pivot + glm::vec3(2.2f, -0.5f, 1.8f);
  f.camera.target = pivot + glm::vec3(0.0f, 0.1f, 0.0f);
  poseBody(bmflBody(), pivot, rotation, 30.0f, tiltDeg, f.bodies, &f.bodyMeshes);
  return f;
}

// The posed meshes' triangles in world space, one primitive per part, for the test's own rays.
Venue meshVenue(const FrameState& f) {
  Venue v;
  v.materials.emplace_back();
  for (const BodyMesh& m : f.bodyMeshes) {
    Primitive p;
    for (const glm::vec3& q : m.mesh->positions) p.positions.push_back(m.originM + m.axes * q);
    for (const glm::vec3& n : m.mesh->normals) p.normals.push_back(m.axes * n);
    p.indices = m.mesh->indices;
    v.primitives.push_back(std::move(p));
  }
  return v;
}

TEST_F(BodyVsReference, GdtfMeshPixelsMatchTheReference) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  ASSERT_TRUE(bmflBody().head.mesh);
  const Venue venue = floorVenue(16.0f, 0.3f);
  const FrameState f = meshFrame(40.0f);
  ASSERT_EQ(f.bodyMeshes.size(), 3u);
  const Venue parts = meshVenue(f);
  const Bvh partsBvh(parts);
  // A pixel away from silhouettes and creases: its centre and corners end on one part, on faces
  // that all face the same way.
  auto interiorPart = [&](int x, int y) {
    const glm::vec3 e = f.camera.position;
    const RayHit c = partsBvh.closestHit(e, cameraRayDirection(f.camera, kW, kH, x + 0.5f, y + 0.5f), 0.0f, 100.0f);
    if (!c.hit()) return -1;
    const glm::vec3 n = partsBvh.surfaceAt(c).geometricNormal;
    for (float dx : {0.0f, 1.0f})
      for (float dy : {0.0f, 1.0f}) {
        const RayHit h = partsBvh.closestHit(e, cameraRayDirection(f.camera, kW, kH, x + dx, y + dy), 0.0f, 100.0f);
        if (!h.hit() || h.primitive != c.primitive) return -1;
        if (std::fabs(glm::dot(partsBvh.surfaceAt(h).geometricNormal, n)) < 0.98f) return -1;
      }
    return c.primitive;
  };
  const Bvh bvh(venue);
  const ReferenceImages ref = renderReferenceImages(bvh, f, kW, kH);
  const ImageRGB img = gpu(venue, f, Quality::High);
  ASSERT_EQ(img.width, kW);
  int interior = 0, failed = 0, lit = 0;
  double worst = 0.0, sumRel = 0.0, sumRelAgreeing = 0.0;
  for (int y = 1; y < kH - 1; ++y)
    for (int x = 1; x < kW - 1; ++x) {
      const int part = interiorPart(x, y);
      if (part < 0) continue;
      const PixelRadiance px = radianceAtPixel(bvh, f, kW, kH, x, y);
      if (px.hitLens) continue;
      ++interior;
      const double want = ref.total.at(x, y).r, got = img.at(x, y).r;
      if (ref.surface.at(x, y).r > 0.5) ++lit;
      const double rel = std::abs(got - want) / std::max(want, 1e-6);
      worst = std::max(worst, rel);
      sumRel += rel;
      if (rel <= 0.05) sumRelAgreeing += rel;
      if (rel > 0.05 && ++failed <= 8)
        std::printf("  pixel (%d, %d) on part %d: %.5g, reference %.5g (%.1f %%)\n", x, y, part, got, want, 100 * rel);
    }
  if (failed > interior / 20) writeDiagnostics("body_mesh", img, ref.total);
  const double meanAgreeing = sumRelAgreeing / std::max(interior - failed, 1);
  std::printf("[ mesh ] %d body pixels (%d lit by the wash): mean %.2f %%, worst %.2f %%; %d off by more than 5 %%, "
              "the others' mean %.2f %%\n", interior, lit, 100 * sumRel / std::max(interior, 1), 100 * worst, failed,
              100 * meanAgreeing);
  EXPECT_GT(interior, 300) << "the BMFL should fill a good part of the image";
  EXPECT_GT(lit, 100) << "the wash should light the faces the camera sees";
  // Measured: 74 of 2087 pixels (3.5 %) off by more than 5 %, in clusters on the top of the base
  // where the model's faces meet at creases the test's four-corner check does not see (not
  // understood further); the other pixels' mean 0.38 %. Limits: 5 % of the pixels, and a mean
  // of 0.6 % over the others.
  EXPECT_LE(failed, interior / 20) << failed << " of " << interior << " mesh pixels off by more than 5 %";
  EXPECT_LT(meanAgreeing, 0.006);
}

TEST_F(BodyVsReference, AMeshHeadTurnsWithTilt) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  ASSERT_TRUE(bmflBody().head.mesh);
  const Venue venue = floorVenue(16.0f, 0.3f);
  // The head's silhouette: where a frame with the head's mesh differs from one without (the base
  // and yoke, which do not tilt, left out).
  auto silhouette = [&](float tilt) {
    FrameState with = meshFrame(tilt), without = with;
    with.bodyMeshes.erase(with.bodyMeshes.begin(), with.bodyMeshes.end() - 1);
    without.bodies.clear();
    without.bodyMeshes.clear();
    const ImageRGB a = gpu(venue, with, Quality::Draft), b = gpu(venue, without, Quality::Draft);
    std::vector<bool> mask(static_cast<size_t>(kW) * kH, false);
    if (a.width != kW || b.width != kW) return mask;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        mask[static_cast<size_t>(y) * kW + x] =
            glm::length(a.at(x, y) - b.at(x, y)) / std::max(glm::length(b.at(x, y)), 1e-3f) > 0.05f;
    return mask;
  };
  const std::vector<bool> s0 = silhouette(0.0f), s1 = silhouette(70.0f);
  int area0 = 0, area1 = 0, moved = 0;
  for (size_t i = 0; i < s0.size(); ++i) {
    area0 += s0[i];
    area1 += s1[i];
    moved += s0[i] != s1[i];
  }
  std::printf("silhouette at tilt 0: %d pixels, at tilt 70: %d, changed %d\n", area0, area1, moved);
  EXPECT_GT(area0, 300);
  EXPECT_GT(area1, 300);
  EXPECT_GT(moved, std::min(area0, area1) / 2) << "the head should have swung to another place in the image";
}

// The culling of body meshes (RenderSettings::cullBodies: parts outside the camera's frustum
// skipped, the BMFL's closed meshes back-face culled) leaves the picture as it was: the nearest
// surface on each ray is the same. A second BMFL behind the camera is not drawn at all.
// Measured: one pixel of 19200 differs, by 0.02 % (on a silhouette, where the back face that
// is no longer drawn rasterised a hair in front of the front face); limits: no pixel off by
// more than 0.1 %, and at most 0.05 % of them off at all.
TEST_F(BodyVsReference, CullingTheMeshesChangesNoPixel) {
  HAZE_NEED_DATA("gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf");
  ASSERT_TRUE(bmflBody().head.mesh);
  const Venue venue = floorVenue(16.0f, 0.3f);
  FrameState f = meshFrame(40.0f);
  const glm::vec3 behind = f.camera.position + glm::normalize(f.camera.position - f.camera.target) * 3.0f;
  poseBody(bmflBody(), behind, glm::vec3(0.0f), 0.0f, 0.0f, f.bodies, &f.bodyMeshes);
  ASSERT_EQ(f.bodyMeshes.size(), 6u);
  ImageRGB images[2];
  int drawn[2] = {0, 0};
  for (int cull = 0; cull < 2; ++cull) {
    RenderSettings s = renderSettingsFor(Quality::Default, kW, kH);
    s.cullBodies = cull == 1;
    auto r = Renderer::create(venue, s);
    ASSERT_TRUE(r.ok()) << r.error().str();
    (*r)->render(f);
    images[cull] = (*r)->readRadiance();
    drawn[cull] = (*r)->lastTimes().bodyMeshesDrawn;
  }
  ASSERT_EQ(images[0].pixels.size(), images[1].pixels.size());
  int differ = 0;
  float worst = 0.0f;
  for (size_t i = 0; i < images[0].pixels.size(); ++i) {
    worst = std::max(worst, glm::length(images[1].pixels[i] - images[0].pixels[i]) /
                                std::max(glm::length(images[0].pixels[i]), 1e-6f));
    if (images[0].pixels[i] != images[1].pixels[i] && ++differ <= 4)
      std::printf("  pixel (%zu, %zu): %g %g %g whole, %g %g %g culled\n", i % kW, i / kW, images[0].pixels[i].r,
                  images[0].pixels[i].g, images[0].pixels[i].b, images[1].pixels[i].r, images[1].pixels[i].g,
                  images[1].pixels[i].b);
  }
  std::printf("[ culling ] meshes drawn %d of 6 (whole: %d); pixels that differ %d, worst by %.4f %%\n", drawn[1],
              drawn[0], differ, 100 * worst);
  EXPECT_EQ(drawn[1], 3) << "the BMFL behind the camera should be skipped";
  EXPECT_LE(differ, kW * kH / 2000);
  EXPECT_LT(worst, 0.001f);
}

}  // namespace
}  // namespace haze::test
