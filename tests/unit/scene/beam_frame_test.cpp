// The beam frame pinned from the standards' side, not from haze's own output. IES LM-63 type C
// and EULUMDAT both count C-planes counterclockwise seen from above a luminaire that points down,
// starting at C0; a gobo reads as drawn to someone standing behind the fixture. The expected
// directions below are worked out from those sentences with plain coordinates, never from
// BeamPose's axes, so a mirrored frame (y_b = z_b x x_b) fails every test here.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <glm/geometric.hpp>

#include "fixtures/photometry.h"
#include "fixtures/pose.h"
#include "shows/scene/physics.h"
#include "unit/fixtures/photometry_writers.h"

namespace haze {
namespace {

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("haze_beam_frame_" + name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// 1000 cd in the C90 half-plane's neighbourhood, 100 cd elsewhere, at every gamma up to 60.
double c90Lobe(double /*gamma*/, double c) {
  const double d = std::fabs(std::remainder(c - 90.0, 360.0));
  return d < 30.0 ? 1000.0 : 100.0;
}

BeamState downlightAtRest(std::shared_ptr<const Distribution> dist) {
  BeamState b;
  // Rotation 0, pan 0, tilt 0: the fixture hangs at 5 m and points straight down (-Y), with
  // its reference axis (C0) along +X.
  b.pose = beamPose({0, 5, 0}, {0, 0, 0}, 0, 0, {0, 0, 0});
  b.optics.distribution = std::move(dist);
  b.optics.profileFieldAngleDeg = 120;
  b.optics.fieldAngleDeg = 120;
  b.optics.dimmer = 1;
  b.optics.color = glm::vec3(1);
  return b;
}

// Seen from above (from +Y looking down, +X to the right), counterclockwise is a positive turn
// about +Y, which takes +X through -Z: C90 lies towards -Z, C270 towards +Z.
void expectC90TowardsMinusZ(const BeamState& b) {
  const float c0 = beamIntensityTowards(b, {2, 0, 0}).r;
  const float c90 = beamIntensityTowards(b, {0, 0, -2}).r;
  const float c180 = beamIntensityTowards(b, {-2, 0, 0}).r;
  const float c270 = beamIntensityTowards(b, {0, 0, 2}).r;
  EXPECT_NEAR(c90, 1000.0f, 5.0f);
  EXPECT_NEAR(c270, 100.0f, 1.0f);
  EXPECT_NEAR(c0, 100.0f, 1.0f);
  EXPECT_NEAR(c180, 100.0f, 1.0f);
}

TEST(BeamFrame, IesC90IsCounterclockwiseFromAbove) {
  const auto file = writeTemp("c90.ies", test::iesText(c90Lobe, test::steps(0, 90, 5), test::steps(0, 360, 10)));
  Result<Distribution> d = loadIes(file);
  ASSERT_TRUE(d.ok()) << d.error().str();
  expectC90TowardsMinusZ(downlightAtRest(std::make_shared<Distribution>(std::move(*d))));
}

TEST(BeamFrame, EulumdatC90IsCounterclockwiseFromAbove) {
  const auto file = writeTemp("c90.ldt", test::ldtText(c90Lobe, test::steps(0, 90, 5), 36, 0));
  Result<Distribution> d = loadLdt(file);
  ASSERT_TRUE(d.ok()) << d.error().str();
  // EULUMDAT stores cd/klm; the writer's 1000 lm lamp makes the file's numbers candela again.
  expectC90TowardsMinusZ(downlightAtRest(std::make_shared<Distribution>(std::move(*d))));
}

TEST(BeamFrame, AGoboReadsAsDrawnFromBehindTheFixture) {
  // A gobo open only in its top-left quadrant (row 0 is the image's top).
  auto gobo = std::make_shared<GoboImage>();
  gobo->width = gobo->height = 8;
  gobo->transmittance.assign(64, 0.0f);
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) gobo->transmittance[static_cast<size_t>(row * 8 + col)] = 1.0f;
  Result<Distribution> d = parametricDistribution(36, 40, 1000);
  ASSERT_TRUE(d.ok());
  BeamState b;
  // Tilted 90 degrees: the beam turns from -Y to -Z, towards a wall at z = -10. Someone behind the
  // fixture looks along -Z with +Y up, so their right is +X (-Z x +Y).
  b.pose = beamPose({0, 2, 0}, {0, 0, 0}, 0, 90, {0, 0, 0});
  ASSERT_NEAR(glm::dot(b.pose.zb, glm::vec3(0, 0, -1)), 1.0f, 1e-5f);
  b.optics.distribution = std::make_shared<Distribution>(std::move(*d));
  b.optics.profileFieldAngleDeg = b.optics.fieldAngleDeg = 40;
  b.optics.dimmer = 1;
  b.optics.color = glm::vec3(1);
  b.optics.gobo = gobo;
  const float a = 1.5f;  // well inside the 40 degree gate at 10 m (radius 3.6 m)
  const auto at = [&](float right, float up) { return beamIntensityTowards(b, {right, 2 + up, -10}).r; };
  EXPECT_GT(at(-a, a), 100.0f) << "the image's top-left must land up and to the viewer's left";
  EXPECT_EQ(at(a, a), 0.0f) << "top-right is closed";
  EXPECT_EQ(at(-a, -a), 0.0f) << "bottom-left is closed";
  EXPECT_EQ(at(a, -a), 0.0f) << "bottom-right is closed";
}

TEST(BeamFrame, FrameIsRightHandedWithYbEqualToXbCrossZb) {
  const BeamPose p = beamPose({1, 2, 3}, {10, 20, 30}, 40, 50, {0, 0.1f, 0});
  EXPECT_NEAR(glm::length(glm::cross(p.xb, p.zb) - p.yb), 0.0f, 1e-5f);
  // Seen along the beam, x_b right and y_b up: right x up points back at the viewer (-z_b).
  EXPECT_NEAR(glm::length(glm::cross(p.xb, p.yb) + p.zb), 0.0f, 1e-5f);
  // The downlight at rest of the spec: y_b = -Z.
  EXPECT_NEAR(glm::length(beamPose({0, 0, 0}, {0, 0, 0}, 0, 0, {0, 0, 0}).yb - glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace haze
