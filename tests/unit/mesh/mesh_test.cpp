// The shared mesh loader (fixtures/mesh): the seeds of its fuzz corpus, the real GDTF models of
// test data (a BMFL's .3ds in mm, a BlenderDMX PAR's .glb in m), and its refusals.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <vector>

#include "fixtures/core/zip_archive.h"
#include "fixtures/mesh/mesh.h"
#include "test_data.h"

namespace haze {
namespace {

std::vector<std::uint8_t> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> fromGdtf(const std::string& gdtf, const std::string& entry) {
  auto zip = ZipArchive::open(test::dataFile("gdtf/" + gdtf).string());
  if (!zip) return {};
  auto bytes = zip->read(entry);
  return bytes ? *bytes : std::vector<std::uint8_t>{};
}

TEST(Mesh, CubeSeedIn3dsIsTurnedYUp) {
  const auto bytes = readFile(std::string(HAZE_SOURCE_DIR) + "/tests/fuzz/corpus/mesh/ok-cube.3ds");
  ASSERT_FALSE(bytes.empty());
  auto m = loadMesh(bytes.data(), bytes.size(), "cube.3ds");
  ASSERT_TRUE(m.ok()) << m.error().str();
  EXPECT_EQ(m->triangleCount(), 12u);
  EXPECT_EQ(m->positions.size(), m->normals.size());
  // The file's z in 0..100 (Z-up) is assimp's y; its y in -50..50 is -z.
  EXPECT_NEAR(m->boundsMin.y, 0.0f, 1e-4f);
  EXPECT_NEAR(m->boundsMax.y, 100.0f, 1e-4f);
  EXPECT_NEAR(m->boundsMin.x, -50.0f, 1e-4f);
  EXPECT_NEAR(m->boundsMax.z, 50.0f, 1e-4f);
  for (std::uint32_t i : m->indices) EXPECT_LT(i, m->positions.size());
}

TEST(Mesh, RealGdtfModelIn3dsIsInMillimetres) {
  const std::string bmfl = "Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf";
  HAZE_NEED_DATA("gdtf/" + bmfl);
  for (const char* part : {"models/3ds/base.3ds", "models/3ds/yoke.3ds", "models/3ds/head.3ds"}) {
    const auto bytes = fromGdtf(bmfl, part);
    ASSERT_FALSE(bytes.empty()) << part;
    auto m = loadMesh(bytes.data(), bytes.size(), part);
    ASSERT_TRUE(m.ok()) << m.error().str();
    EXPECT_GT(m->triangleCount(), 10u) << part;
    // Millimetres: a BMFL part is tens of centimetres.
    const glm::vec3 size = m->boundsMax - m->boundsMin;
    EXPECT_GT(std::max({size.x, size.y, size.z}), 50.0f) << part;
    EXPECT_LT(std::max({size.x, size.y, size.z}), 1000.0f) << part;
  }
}

TEST(Mesh, RealGdtfModelInGlbIsInMetres) {
  const auto body = fromGdtf("BlenderDMX@LED_PAR_64_RGBW@v0.3.gdtf", "models/gltf/Body.glb");
  ASSERT_FALSE(body.empty());
  auto m = loadMesh(body.data(), body.size(), "Body.glb");
  ASSERT_TRUE(m.ok()) << m.error().str();
  const glm::vec3 size = m->boundsMax - m->boundsMin;
  EXPECT_GT(std::max({size.x, size.y, size.z}), 0.1f);  // metres
  EXPECT_LT(std::max({size.x, size.y, size.z}), 1.0f);
}

TEST(Mesh, RefusalsNameTheFile) {
  const std::vector<std::uint8_t> junk = {'n', 'o', 't', ' ', 'a', ' ', 'm', 'e', 's', 'h'};
  auto a = loadMesh(junk.data(), junk.size(), "models/3ds/head.3ds");
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.error().str().find("models/3ds/head.3ds"), std::string::npos) << a.error().str();
  EXPECT_EQ(a.error().str().find('\n'), std::string::npos);
  auto b = loadMesh(junk.data(), junk.size(), "head.obj");
  EXPECT_FALSE(b.ok());
  auto c = loadMesh(junk.data(), 0, "head.glb");
  EXPECT_FALSE(c.ok());
  const auto bytes = readFile(std::string(HAZE_SOURCE_DIR) + "/tests/fuzz/corpus/mesh/ok-cube.3ds");
  auto d = loadMesh(bytes.data(), bytes.size(), "cube.3ds", MeshLimits{.maxTriangles = 5});
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().message.find("triangles"), std::string::npos);
  auto e = loadMesh(bytes.data(), bytes.size(), "cube.3ds", MeshLimits{.maxFileBytes = 10});
  EXPECT_FALSE(e.ok());
}

}  // namespace
}  // namespace haze
