// Helpers for GL render tests: a debug headless context per test (any GL error fails the test),
// scenes built in code, and the actual/expected/difference PFMs a failed image comparison leaves
// in the build folder (the comparison itself is shows/scene/image_compare.h).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fixtures/beam_optics.h"
#include "renderer/context.h"
#include "renderer/renderer.h"
#include "renderer/gl/debug.h"
#include "shows/scene/frame_state.h"
#include "shows/scene/image.h"
#include "shows/scene/venue.h"

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

// One frame rendered by a new renderer with these settings, its radiance read back (empty, and
// the test failed, when the renderer cannot be made).
ImageRGB renderRadiance(const Venue& venue, const FrameState& frame, const RenderSettings& settings);

// An axis-aligned rectangle at height y, facing +Y, sizeM square, with one material of albedo.
Venue floorVenue(float sizeM, float albedo);
// Adds an axis-aligned box (12 triangles) to a venue, with the venue's last material.
void addBox(Venue& v, glm::vec3 lo, glm::vec3 hi);
// Adds a UV sphere (segments around, rings top to bottom) with the venue's last material.
void addSphere(Venue& v, glm::vec3 centre, float radiusM, int segments = 32, int rings = 16);
// A beam of a parametric distribution (beam/field angles, peak cd) at pos, aimed along dir.
BeamState makeBeam(glm::vec3 lensPos, glm::vec3 dir, float beamDeg, float fieldDeg, float peakCd,
                   glm::vec3 color = glm::vec3(1.0f));
// A beam of a photometric file (.ies or .ldt) under the test data's photometry/ folder
// (tests/test_data.h), unzoomed, its lens the file's luminous opening (or the default when the
// file gives none).
BeamState fileBeam(const std::string& relativePath, glm::vec3 lensPos, glm::vec3 dir);

// An n x n gobo, half opaque and half open: the rows j < n / 2 opaque (`opaqueRows`), or the
// columns i < n / 2.
std::shared_ptr<GoboImage> halfOpaqueGobo(int n, bool opaqueRows);

// Writes <name>.actual.pfm, <name>.expected.pfm and <name>.diff.pfm into HAZE_TEST_OUTPUT_DIR
// (the build tree's test-output/, never the source tree) and returns the files written.
std::vector<std::filesystem::path> writeDiagnostics(const std::string& name, const ImageRGB& actual,
                                                    const ImageRGB& reference);

}  // namespace haze::test
