#include "render_test_util.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "fixtures/photometry.h"

namespace haze::test {

Venue floorVenue(float sizeM, float albedo) {
  Venue v;
  v.materials.push_back(Material{.name = "default"});
  v.materials.push_back(Material{.name = "floor", .baseColor = glm::vec4(albedo, albedo, albedo, 1.0f)});
  Primitive p;
  p.name = "floor";
  const float h = sizeM * 0.5f;
  p.positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
  p.normals.assign(4, glm::vec3(0, 1, 0));
  p.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.indices = {0, 2, 1, 0, 3, 2};
  p.material = 1;
  v.primitives.push_back(p);
  v.boundsMin = glm::vec3(-h, 0, -h);
  v.boundsMax = glm::vec3(h, 0, h);
  return v;
}

void addBox(Venue& v, glm::vec3 lo, glm::vec3 hi) {
  Primitive p;
  p.name = "box";
  p.material = static_cast<int>(v.materials.size()) - 1;
  const glm::vec3 n[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& nn : n) {
    // Four corners of the face with normal nn.
    glm::vec3 a = glm::abs(nn);
    glm::vec3 u = a.x > 0 ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    glm::vec3 w = glm::cross(a, u);
    glm::vec3 c = (lo + hi) * 0.5f + nn * (hi - lo) * 0.5f;
    glm::vec3 hu = u * (hi - lo) * 0.5f, hw = w * (hi - lo) * 0.5f;
    const uint32_t base = static_cast<uint32_t>(p.positions.size());
    for (glm::vec3 q : {c - hu - hw, c + hu - hw, c + hu + hw, c - hu + hw}) {
      p.positions.push_back(q);
      p.normals.push_back(nn);
      p.uvs.push_back(glm::vec2(0));
    }
    p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  v.primitives.push_back(p);
  v.boundsMin = glm::min(v.boundsMin, lo);
  v.boundsMax = glm::max(v.boundsMax, hi);
}

void addSphere(Venue& v, glm::vec3 centre, float radiusM, int segments, int rings) {
  Primitive p;
  p.name = "sphere";
  p.material = static_cast<int>(v.materials.size()) - 1;
  for (int j = 0; j <= rings; ++j) {
    const float th = 3.14159265f * static_cast<float>(j) / static_cast<float>(rings);
    for (int i = 0; i <= segments; ++i) {
      const float ph = 2.0f * 3.14159265f * static_cast<float>(i) / static_cast<float>(segments);
      const glm::vec3 n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
      p.positions.push_back(centre + radiusM * n);
      p.normals.push_back(n);
      p.uvs.push_back(glm::vec2(0));
    }
  }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const uint32_t a = static_cast<uint32_t>(j * (segments + 1) + i), b = a + 1,
                     c = a + static_cast<uint32_t>(segments + 1), d = c + 1;
      p.indices.insert(p.indices.end(), {a, c, b, b, c, d});
    }
  v.primitives.push_back(p);
  v.boundsMin = glm::min(v.boundsMin, centre - glm::vec3(radiusM));
  v.boundsMax = glm::max(v.boundsMax, centre + glm::vec3(radiusM));
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
