// MVR -> haze placement rules, each checked against answers worked out by hand: mm -> m with
// (x, y, z) -> (x, z, -y), {u}{v}{w}{o} matrices, Euler angles that put a GDTF beam (-Z) where
// the MVR matrix points it, absolute and UNIVERSE.ADDRESS patch forms.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>

#include "shows/import/mvr_import.h"

namespace haze {
namespace {

glm::dvec3 hazeBeam(const glm::vec3& rotationDeg) {
  const glm::mat4 r = glm::eulerAngleZYX(glm::radians(rotationDeg.z), glm::radians(rotationDeg.y), glm::radians(rotationDeg.x));
  return glm::dvec3(glm::mat3(r) * glm::vec3(0, -1, 0));
}

TEST(MvrFrame, PointsGoFromZUpMillimetresToYUpMetres) {
  const glm::vec3 p = mvrPointToHazeM({1000.0, 2000.0, 3000.0});
  EXPECT_FLOAT_EQ(p.x, 1.0f);
  EXPECT_FLOAT_EQ(p.y, 3.0f);   // MVR height Z is haze's Y
  EXPECT_FLOAT_EQ(p.z, -2.0f);  // MVR +Y (upstage) is haze -Z
}

TEST(MvrFrame, ParsesMatrixAsAxesAndOrigin) {
  auto m = parseMvrMatrix("{0,-1,0}{1,0,0}{0,0,1}{-14198.6,7189.12,8026.4}");
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_DOUBLE_EQ((*m)[0][1], -1.0);  // u = local X in world = column 0
  EXPECT_DOUBLE_EQ((*m)[1][0], 1.0);
  EXPECT_DOUBLE_EQ((*m)[2][2], 1.0);
  EXPECT_DOUBLE_EQ((*m)[3][0], -14198.6);
  EXPECT_DOUBLE_EQ((*m)[3][2], 8026.4);
  EXPECT_DOUBLE_EQ((*m)[3][3], 1.0);
  // A point at local (1, 0, 0) lands at origin + u.
  const glm::dvec4 p = *m * glm::dvec4(1, 0, 0, 1);
  EXPECT_DOUBLE_EQ(p.y, 7189.12 - 1.0);
}

TEST(MvrFrame, RejectsBrokenMatrices) {
  for (const char* bad : {"", "{1,0,0}{0,1,0}{0,0,1}", "{1,0,0}{0,1,0}{0,0,1}{0,0,nan}", "{1,0,0}{0,1,0}{0,0,1}{0,0}",
                          "{1 0 0}{0,1,0}{0,0,1}{0,0,0}", "{1,0,0}{0,1,0}{0,0,1}{0,0,0}x", "{1e300,0,0}{0,1,0}{0,0,1}{0,0,0}"}) {
    auto m = parseMvrMatrix(bad);
    EXPECT_FALSE(m.ok()) << bad;
    if (!m.ok()) {
      EXPECT_NE(m.error().message.find("Matrix"), std::string::npos);
    }
  }
}

TEST(MvrFrame, IdentityHangsTheBeamDown) {
  const glm::vec3 r = mvrRotationToHazeDeg(glm::dmat3(1.0));
  EXPECT_EQ(r, glm::vec3(0.0f));
}

TEST(MvrFrame, QuarterTurnsGiveExactAngles) {
  // MVR: local Z turned to world +X (rotation of +90 degrees about MVR Y): u=(0,0,-1), w=(1,0,0).
  // The beam (-w) then points to MVR -X = haze -X.
  const glm::dmat3 m(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));
  const glm::vec3 r = mvrRotationToHazeDeg(m);
  const glm::dvec3 beam = hazeBeam(r);
  EXPECT_NEAR(beam.x, -1.0, 1e-6);
  EXPECT_NEAR(beam.y, 0.0, 1e-6);
  EXPECT_NEAR(beam.z, 0.0, 1e-6);
  // MVR Y is haze -Z, so a turn about MVR +Y is a turn about haze -Z: rz = -90.
  EXPECT_NEAR(r.z, -90.0f, 1e-4);
  EXPECT_NEAR(r.x, 0.0f, 1e-4);
  EXPECT_NEAR(r.y, 0.0f, 1e-4);
}

TEST(MvrFrame, RandomRotationsKeepBeamAndReferenceAxis) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
  for (int i = 0; i < 500; ++i) {
    const glm::dmat3 m = glm::dmat3(glm::eulerAngleXYZ(angle(rng), angle(rng), angle(rng)));
    const glm::vec3 r = mvrRotationToHazeDeg(m);
    const glm::mat3 hr = glm::mat3(glm::eulerAngleZYX(glm::radians(r.z), glm::radians(r.y), glm::radians(r.x)));
    // Independently: the GDTF beam -w and reference axis u in MVR world, then (x, y, z) -> (x, z, -y).
    const glm::dvec3 w = m[2], u = m[0];
    const glm::dvec3 beamExpected(-w.x, -w.z, w.y), refExpected(u.x, u.z, -u.y);
    const glm::dvec3 beam(hr * glm::vec3(0, -1, 0)), ref(hr * glm::vec3(1, 0, 0));
    EXPECT_LT(glm::length(beam - beamExpected), 2e-4) << i;
    EXPECT_LT(glm::length(ref - refExpected), 2e-4) << i;
  }
  // Gimbal lock (ry = +-90): beam straight along haze X.
  for (double s : {1.0, -1.0}) {
    const glm::dmat3 m(glm::dvec3(0, s, 0), glm::dvec3(-s, 0, 0), glm::dvec3(0, 0, 1));  // about MVR Z
    const glm::dmat3 tilted = glm::dmat3(glm::eulerAngleY(s * 1.5707963267948966)) * m;
    const glm::vec3 r = mvrRotationToHazeDeg(tilted);
    const glm::mat3 hr = glm::mat3(glm::eulerAngleZYX(glm::radians(r.z), glm::radians(r.y), glm::radians(r.x)));
    const glm::dvec3 w = tilted[2], u = tilted[0];
    EXPECT_LT(glm::length(glm::dvec3(hr * glm::vec3(0, -1, 0)) - glm::dvec3(-w.x, -w.z, w.y)), 2e-4);
    EXPECT_LT(glm::length(glm::dvec3(hr * glm::vec3(1, 0, 0)) - glm::dvec3(u.x, u.z, -u.y)), 2e-4);
  }
}

TEST(MvrFrame, AbsoluteAndDottedAddresses) {
  struct Case { const char* text; int universe, address; };
  for (const Case& c : {Case{"1", 1, 1}, Case{"512", 1, 512}, Case{"513", 2, 1}, Case{"1025", 3, 1},
                        Case{" 545 ", 2, 33}, Case{"3.1", 3, 1}, Case{"12.512", 12, 512}, Case{"0", 0, 0}}) {
    auto p = parseMvrAddress(c.text);
    ASSERT_TRUE(p.ok()) << c.text << ": " << p.error().message;
    EXPECT_EQ(p->universe, c.universe) << c.text;
    EXPECT_EQ(p->address, c.address) << c.text;
  }
  for (const char* bad : {"", "x", "-5", "1.0", "0.5", "1.513", "1.", ".1", "99999999999", "1e3", "1.2.3"}) {
    auto p = parseMvrAddress(bad);
    EXPECT_FALSE(p.ok()) << bad;
    if (!p.ok()) {
      EXPECT_NE(p.error().message.find("expected"), std::string::npos) << bad;
    }
  }
}

}  // namespace
}  // namespace haze
