#include "render_test_util.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "fixtures/photometry.h"
#include "shows/scene/scene_builder.h"
#include "test_data.h"

namespace haze::test {

ImageRGB renderRadiance(const Venue& venue, const FrameState& frame, const RenderSettings& settings) {
  auto r = Renderer::create(venue, settings);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(frame);
  return (*r)->readRadiance();
}

std::shared_ptr<GoboImage> halfOpaqueGobo(int n, bool opaqueRows) {
  auto g = std::make_shared<GoboImage>();
  g->width = g->height = n;
  g->transmittance.resize(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) g->transmittance[static_cast<size_t>(j) * n + i] = (opaqueRows ? j : i) < n / 2 ? 0.0f : 1.0f;
  return g;
}

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
  // Distinct per beam: the renderer shares a light map between beams of equal optics keys.
  static uint64_t nextOpticsKey = 1;
  b.opticsKey = nextOpticsKey++;
  return b;
}

BeamState fileBeam(const std::string& relativePath, glm::vec3 lensPos, glm::vec3 dir) {
  BeamState b;
  b.pose = beamAlong(lensPos, dir);
  const std::filesystem::path file = test::dataFile("photometry/" + relativePath);
  auto dist = file.extension() == ".ldt" ? loadLdt(file) : loadIes(file);
  EXPECT_TRUE(dist.ok()) << (dist.ok() ? "" : dist.error().str());
  if (!dist.ok()) return b;
  if (dist->luminousRadiusM > 0.0f) b.optics.lensRadiusM = dist->luminousRadiusM;
  b.optics.distribution = std::make_shared<Distribution>(std::move(*dist));
  b.optics.color = glm::vec3(1.0f);
  b.optics.dimmer = 1.0f;
  b.poseKey = 1;
  b.opticsKey = 1;
  return b;
}

std::vector<std::filesystem::path> writeDiagnostics(const std::string& name, const ImageRGB& actual,
                                                    const ImageRGB& reference) {
  const std::filesystem::path dir = HAZE_TEST_OUTPUT_DIR;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  ImageRGB diff = actual;
  for (size_t i = 0; i < diff.pixels.size() && i < reference.pixels.size(); ++i)
    diff.pixels[i] = glm::abs(actual.pixels[i] - reference.pixels[i]);
  std::vector<std::filesystem::path> written;
  for (const auto& [suffix, image] : {std::pair{".actual.pfm", &actual}, std::pair{".expected.pfm", &reference},
                                      std::pair{".diff.pfm", static_cast<const ImageRGB*>(&diff)}}) {
    const std::filesystem::path file = dir / (name + suffix);
    const Status st = writePfm(*image, file);
    if (st.ok()) written.push_back(file);
    else ADD_FAILURE() << "diagnostic image not written: " << st.error().str();
  }
  return written;
}

}  // namespace haze::test
