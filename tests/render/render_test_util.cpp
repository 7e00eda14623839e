#include "render_test_util.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "fixtures/photometry.h"
#include "renderer/scene/scene_builder.h"

namespace haze::test {

Venue floorVenue(float sizeM, float albedo) {
  Venue v = emptyVenue();
  addFloor(v, 0.0f, sizeM * 0.5f, haze::addMaterial(v, "floor", glm::vec3(albedo)));
  return v;
}

void addBox(Venue& v, glm::vec3 lo, glm::vec3 hi) {
  haze::addBox(v, lo, hi, static_cast<int>(v.materials.size()) - 1);
}

void addSphere(Venue& v, glm::vec3 centre, float radiusM, int segments, int rings) {
  addUvSphere(v, centre, radiusM, rings, segments, static_cast<int>(v.materials.size()) - 1);
}

BeamState makeBeam(glm::vec3 lensPos, glm::vec3 dir, float beamDeg, float fieldDeg, float peakCd, glm::vec3 color) {
  BeamState b;
  b.pose = beamAlong(lensPos, dir);
  auto dist = parametricDistribution(beamDeg, fieldDeg, peakCd);
  EXPECT_TRUE(dist.ok()) << (dist.ok() ? "" : dist.error().str());
  b.optics.distribution = std::make_shared<Distribution>(std::move(*dist));
  b.optics.profileFieldAngleDeg = fieldDeg;
  b.optics.fieldAngleDeg = fieldDeg;
  b.optics.color = color;
  b.optics.dimmer = 1.0f;
  b.poseKey = 1;
  b.opticsKey = 1;
  return b;
}

Comparison compare(const ImageRGB& actual, const ImageRGB& reference, float threshold) {
  Comparison c;
  float maxL = 0.0f;
  for (const glm::vec3& p : reference.pixels) maxL = std::max(maxL, std::max({p.r, p.g, p.b}));
  double sum = 0.0;
  for (size_t i = 0; i < reference.pixels.size() && i < actual.pixels.size(); ++i) {
    for (int ch = 0; ch < 3; ++ch) {
      const float r = reference.pixels[i][ch];
      if (r <= threshold * maxL) continue;
      const double e = std::abs(actual.pixels[i][ch] - r) / r;
      sum += e;
      c.maxRelError = std::max(c.maxRelError, e);
      ++c.pixels;
    }
  }
  c.meanRelError = c.pixels ? sum / static_cast<double>(c.pixels) : 0.0;
  return c;
}

void writeDiagnostics(const std::string& name, const ImageRGB& actual, const ImageRGB& reference) {
  ImageRGB diff = actual;
  for (size_t i = 0; i < diff.pixels.size() && i < reference.pixels.size(); ++i)
    diff.pixels[i] = glm::abs(actual.pixels[i] - reference.pixels[i]);
  (void)writePfm(actual, name + ".actual.pfm");
  (void)writePfm(reference, name + ".expected.pfm");
  (void)writePfm(diff, name + ".diff.pfm");
}

}  // namespace haze::test
