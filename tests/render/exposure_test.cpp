// Auto exposure on a bright scene: a wide 400 kcd spot makes a pool of about 1800 cd/m^2 that
// the fixed manual key (EV 0: 50 cd/m^2 maps to 1) blows out to white; the meter brings it back
// under the clip. Exposure is display only: the radiometric image is the same in both modes.
#include "render_test_util.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class ExposureTest : public GlTest {};

struct Shares {
  double clipped = 0, lit = 0;
};

Shares sharesOf(const std::vector<unsigned char>& rgb) {
  Shares s;
  const size_t n = rgb.size() / 3;
  for (size_t i = 0; i < n; ++i) {
    const unsigned char r = rgb[3 * i], g = rgb[3 * i + 1], b = rgb[3 * i + 2];
    if (r >= 250 && g >= 250 && b >= 250) s.clipped += 1;
    if (0.2126 * r + 0.7152 * g + 0.0722 * b >= 5) s.lit += 1;
  }
  s.clipped /= static_cast<double>(n);
  s.lit /= static_cast<double>(n);
  return s;
}

TEST_F(ExposureTest, AutoKeepsABrightPoolUnderTheClipAndLeavesRadianceAlone) {
  Venue venue = floorVenue(20.0f, 0.5f);
  FrameState frame;
  frame.camera.position = glm::vec3(0.0f, 8.0f, 0.01f);
  frame.camera.target = glm::vec3(0.0f);
  frame.camera.fovYDeg = 60.0f;
  frame.beams.push_back(makeBeam({0.0f, 6.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 40.0f, 50.0f, 400000.0f));
  auto r = Renderer::create(venue, {.width = 160, .height = 160});
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(frame);
  const ImageRGB before = (*r)->readRadiance();

  const Shares manual = sharesOf((*r)->readDisplay({.exposureEv = 0.0f}));
  EXPECT_GT(manual.clipped, 0.15) << "the fixed key blows the pool out";

  const Metering m = (*r)->meter();
  EXPECT_GT(m.highlightNits, 500.0f);
  EXPECT_LT(m.ev, -3.0f) << "a bright scene is metered down";
  const Shares metered = sharesOf((*r)->readDisplay({.exposureEv = exposureEvFor({}, m.ev)}));
  EXPECT_LT(metered.clipped, 0.02) << "auto clips " << metered.clipped;
  EXPECT_GT(metered.lit, 0.2) << "and still shows the pool: " << metered.lit;

  const ImageRGB after = (*r)->readRadiance();
  ASSERT_EQ(before.pixels, after.pixels) << "metering or display changed the radiometric image";
}

TEST_F(ExposureTest, MeteringAFaintSceneBrightensIt) {
  Venue venue = floorVenue(20.0f, 0.5f);
  FrameState frame;
  frame.camera.position = glm::vec3(0.0f, 8.0f, 0.01f);
  frame.camera.target = glm::vec3(0.0f);
  frame.camera.fovYDeg = 60.0f;
  frame.beams.push_back(makeBeam({0.0f, 6.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 40.0f, 50.0f, 200.0f));
  auto r = Renderer::create(venue, {.width = 96, .height = 96});
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(frame);
  const Metering m = (*r)->meter();
  EXPECT_GT(m.ev, 0.0f) << "a pool of about 1 cd/m^2 is metered up";
  EXPECT_GT(sharesOf((*r)->readDisplay({.exposureEv = m.ev})).lit, 0.2);
}

}  // namespace
}  // namespace haze::test
