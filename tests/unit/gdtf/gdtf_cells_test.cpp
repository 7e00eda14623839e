// Multi-cell GDTFs (docs/cells.md): the test washes of tests/data/gdtf import with one cell per
// Beam at the Beam's place, and DMX drives each cell through the channels on its geometry, also
// through GeometryReference instances shifted by their Breaks.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fixtures/dmx_decode.h"
#include "fixtures/gdtf.h"
#include "unit/gdtf/zip_builder.h"

namespace haze {
namespace {

using test::TempDir;

Result<GdtfImport> importTestFixture(const TempDir& dir, const std::string& xmlName) {
  const auto xml = test::readFile(std::filesystem::path(HAZE_SOURCE_DIR) / "tests/data/gdtf" / xmlName);
  EXPECT_FALSE(xml.empty()) << xmlName;
  EXPECT_TRUE(test::writeZip(dir / "t.gdtf", {{"description.xml", xml}}));
  return loadGdtf(dir / "t.gdtf");
}

// The hex grid the XML files were written with: the centre, six at 6 cm, twelve on the next ring.
std::vector<glm::vec2> hexGrid(int n) {
  std::vector<glm::vec2> p{{0.0f, 0.0f}};
  for (int k = 0; k < 6 && n > 1; ++k) p.push_back(0.06f * glm::vec2(static_cast<float>(std::cos(k * M_PI / 3)), static_cast<float>(std::sin(k * M_PI / 3))));
  for (int k = 0; k < 12 && n > 7; ++k) {
    const float r = k % 2 == 0 ? 0.12f : 0.12f * std::cos(static_cast<float>(M_PI / 6));
    p.push_back(r * glm::vec2(static_cast<float>(std::cos(k * M_PI / 6)), static_cast<float>(std::sin(k * M_PI / 6))));
  }
  p.resize(static_cast<size_t>(n));
  return p;
}

void expectCellsOnTheGrid(const Profile& p, int n) {
  ASSERT_EQ(p.cells.size(), static_cast<size_t>(n));
  const auto grid = hexGrid(n);
  for (int k = 0; k < n; ++k) {
    const Cell& c = p.cells[static_cast<size_t>(k)];
    // GDTF (x, y, z) -> haze (x, z, -y); the Beams hang 5 cm below the head's pivot.
    EXPECT_NEAR(c.lensOffset.x, grid[static_cast<size_t>(k)].x, 1e-5f) << k;
    EXPECT_NEAR(c.lensOffset.y, -0.05f, 1e-5f) << k;
    EXPECT_NEAR(c.lensOffset.z, -grid[static_cast<size_t>(k)].y, 1e-5f) << k;
    EXPECT_FLOAT_EQ(c.fieldAngleDeg, 20.0f);
    EXPECT_FLOAT_EQ(c.lensRadiusM, 0.02f);
    EXPECT_EQ(c.distribution, p.cells[0].distribution) << "cells of one photometry share it";
  }
}

TEST(GdtfCells, SevenBeamsAreSevenCellsEachWithItsChannels) {
  TempDir dir("hex7");
  auto g = importTestFixture(dir, "hex7_wash.xml");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  expectCellsOnTheGrid(p, 7);
  EXPECT_EQ(p.cells[3].name, "Cell4");
  const DmxMode* mode = p.findMode("Cells");
  ASSERT_NE(mode, nullptr);
  ASSERT_EQ(mode->footprint(), 33);
  EXPECT_TRUE(mode->channels[4].cells.empty()) << "the master dimmer on the Head drives the fixture";
  // Cell 1 red at full, cell 2 green at 128 and dimmer 128, cell 4 blue, the rest dark.
  std::vector<uint8_t> dmx(33, 0);
  dmx[0] = dmx[2] = 128;
  dmx[4] = 255;
  const auto cell = [&](int k, uint8_t dim, uint8_t r, uint8_t gr, uint8_t b) {
    const size_t o = 5 + 4 * static_cast<size_t>(k);
    dmx[o] = dim, dmx[o + 1] = r, dmx[o + 2] = gr, dmx[o + 3] = b;
  };
  cell(0, 255, 255, 0, 0);
  cell(1, 128, 0, 255, 0);
  cell(3, 255, 0, 0, 255);
  const Attributes a = decodeDmx(p, *mode, dmx);
  EXPECT_FLOAT_EQ(a.intensity, 1.0f);
  EXPECT_EQ(a.color, glm::vec3(1.0f));
  ASSERT_EQ(a.cells.size(), 7u);
  EXPECT_FLOAT_EQ(a.cells[0].intensity, 1.0f);
  EXPECT_EQ(a.cells[0].color, glm::vec3(1, 0, 0));
  EXPECT_NEAR(a.cells[1].intensity, 128.0f / 255.0f, 1e-6f);
  EXPECT_EQ(a.cells[1].color, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(a.cells[2].intensity, 0.0f);
  EXPECT_EQ(a.cells[3].color, glm::vec3(0, 0, 1));
  // The cell's beam: the fixture's dimmer and colour times the cell's.
  const BeamOptics o = cellOptics(p, a, 1);
  EXPECT_NEAR(o.dimmer, 128.0f / 255.0f, 1e-6f);
  EXPECT_EQ(o.color, glm::vec3(0, 1, 0));
  EXPECT_EQ(o.distribution, p.cells[1].distribution);
  // The Single mode has no cell channels: every cell follows the fixture.
  const DmxMode* single = p.findMode("Single");
  ASSERT_NE(single, nullptr);
  std::vector<uint8_t> one{128, 0, 128, 0, 255, 255, 0, 255};
  const Attributes s = decodeDmx(p, *single, one);
  EXPECT_TRUE(s.cells.empty());
  EXPECT_EQ(cellOptics(p, s, 5).color, glm::vec3(1, 0, 1));
}

TEST(GdtfCells, GeometryReferencesInstanceTheirChannelsAtTheirBreaks) {
  TempDir dir("hex19");
  auto g = importTestFixture(dir, "hex19_wash.xml");
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Profile& p = *g->profile;
  expectCellsOnTheGrid(p, 19);
  EXPECT_EQ(p.cells[12].name, "Pixel13") << "instanced Beams take their reference's name";
  const DmxMode* mode = p.findMode("Cells");
  ASSERT_NE(mode, nullptr);
  ASSERT_EQ(mode->footprint(), 5 + 4 * 19);
  for (int k = 0; k < 19; ++k) {
    const DmxChannel& dim = mode->channels[5 + 4 * static_cast<size_t>(k)];
    EXPECT_EQ(dim.attribute, DmxAttribute::Intensity) << k;
    EXPECT_EQ(dim.cells, std::vector<int>{k}) << k;
  }
  std::vector<uint8_t> dmx(81, 0);
  dmx[4] = 255;
  dmx[5 + 4 * 12] = 51;        // cell 13 at 0.2
  dmx[5 + 4 * 12 + 2] = 255;   // green
  const Attributes a = decodeDmx(p, *mode, dmx);
  ASSERT_EQ(a.cells.size(), 19u);
  EXPECT_NEAR(a.cells[12].intensity, 0.2f, 1e-6f);
  EXPECT_EQ(a.cells[12].color, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(a.cells[11].intensity, 0.0f);
}

}  // namespace
}  // namespace haze
