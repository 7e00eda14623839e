// Helpers for GL render tests: a debug headless context per test (any GL error fails the test),
// scenes built in code, and float-image comparisons that write actual/expected/difference PFMs
// into the build folder when they fail.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "fixtures/beam_optics.h"
#include "renderer/context.h"
#include "renderer/gl/debug.h"
#include "renderer/scene/frame_state.h"
#include "renderer/scene/image.h"
#include "renderer/scene/venue.h"

namespace haze::test {

// Owns the context for one test and checks the GL debug log at the end.
class GlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto ctx = createHeadlessContext({.debug = true});
    ASSERT_TRUE(ctx.ok()) << ctx.error().str();
    context_ = std::move(*ctx);
    gl::resetDebugErrors();
  }
  void TearDown() override {
    EXPECT_EQ(gl::debugErrorCount(), 0) << "GL error: " << gl::lastDebugError();
    context_.reset();
  }
  std::unique_ptr<GlContext> context_;
};

// An axis-aligned rectangle at height y, facing +Y, sizeM square, with one material of albedo.
Venue floorVenue(float sizeM, float albedo);
// Adds an axis-aligned box (12 triangles) to a venue, with the venue's last material.
void addBox(Venue& v, glm::vec3 lo, glm::vec3 hi);
// Adds a UV sphere (segments around, rings top to bottom) with the venue's last material.
void addSphere(Venue& v, glm::vec3 centre, float radiusM, int segments = 32, int rings = 16);
// A beam of a parametric distribution (beam/field angles, peak cd) at pos, aimed along dir.
BeamState makeBeam(glm::vec3 lensPos, glm::vec3 dir, float beamDeg, float fieldDeg, float peakCd,
                   glm::vec3 color = glm::vec3(1.0f));

// Mean relative error over pixels where the reference is above threshold * its maximum
// (physics.md "Accuracy"); also counts those pixels.
struct Comparison {
  double meanRelError = 0;
  double maxRelError = 0;
  size_t pixels = 0;
};
Comparison compare(const ImageRGB& actual, const ImageRGB& reference, float threshold = 0.01f);
// Writes <name>.actual.pfm, <name>.expected.pfm and <name>.diff.pfm in the working folder.
void writeDiagnostics(const std::string& name, const ImageRGB& actual, const ImageRGB& reference);

}  // namespace haze::test
