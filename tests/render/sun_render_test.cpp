// The sun on the GPU (docs/rendering.md, "The sun") against the CPU reference: a closed room
// with one window, the sun shining in through it, seen from the side of the shaft, in haze. The
// shaft's in-scattering (compareBeams on L_in, the wet image less the dry one) and the surfaces
// (the dry image against the reference's surface part) at high and default, with limits from the
// measured errors plus a margin; the limits are checked to fail the sun moved by 3 degrees and
// the shaft 10 % brighter. The same room through uneven haze (a density field), which the
// uniform medium fails. Without a sun nothing of it runs: the other render tests are its
// "unchanged" check.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "app/render_session.h"
#include "render_test_util.h"
#include "shows/scene/image.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/bvh.h"
#include "shows/scene/image_compare.h"
#include "shows/scene/physics.h"
#include "shows/scene/scene_builder.h"

namespace haze::test {
namespace {

constexpr int kW = 240, kH = 180;

// An 8 x 8 x 4 m room, closed but for a 2 x 1.5 m window in its west wall (x = -4), 1.5 m up.
Venue windowRoom() {
  Venue v = emptyVenue();
  const int grey = addMaterial(v, "walls", glm::vec3(0.5f));
  addFloor(v, 0.0f, 4.0f, grey);
  addQuad(v, {-4, 4, -4}, {4, 4, -4}, {4, 4, 4}, {-4, 4, 4}, grey);   // roof
  addQuad(v, {4, 0, -4}, {4, 4, -4}, {4, 4, 4}, {4, 0, 4}, grey);     // east
  addQuad(v, {-4, 0, 4}, {4, 0, 4}, {4, 4, 4}, {-4, 4, 4}, grey);     // south
  addQuad(v, {-4, 0, -4}, {4, 0, -4}, {4, 4, -4}, {-4, 4, -4}, grey); // north
  // The west wall around the window (z -1..1, y 1.5..3).
  addQuad(v, {-4, 0, -4}, {-4, 1.5f, -4}, {-4, 1.5f, 4}, {-4, 0, 4}, grey);
  addQuad(v, {-4, 3, -4}, {-4, 4, -4}, {-4, 4, 4}, {-4, 3, 4}, grey);
  addQuad(v, {-4, 1.5f, -4}, {-4, 3, -4}, {-4, 3, -1}, {-4, 1.5f, -1}, grey);
  addQuad(v, {-4, 1.5f, 1}, {-4, 3, 1}, {-4, 3, 4}, {-4, 1.5f, 4}, grey);
  return v;
}

FrameState sunFrame(float azimuthDeg, float elevationDeg) {
  FrameState f;
  f.camera.position = {0.8f, 1.6f, 3.6f};
  f.camera.target = {-0.8f, 1.3f, 0.0f};
  f.camera.fovYDeg = 70.0f;
  f.medium.scattering = 0.06f;
  f.medium.absorption = 0.01f;
  f.medium.ambient = glm::vec3(0.05f);
  f.sun.on = true;
  f.sun.direction = sunDirection(azimuthDeg, elevationDeg);
  f.sun.illuminance = glm::vec3(30000.0f, 27000.0f, 22000.0f);
  return f;
}

// Haze at 0.4 of nominal, a ground layer of 3 below 0.8 m and a thick patch (2.5) in the
// shaft's upper part near the window: every path of the sun crosses changes of D.
std::shared_ptr<const DensityField> unevenAir(const Venue& venue) {
  auto f = std::make_shared<DensityField>(DensityField::filled(32, 16, 32, venue.boundsMin, venue.boundsMax, 0.4f));
  const glm::vec3 cell = (f->maxM - f->minM) / glm::vec3(32, 16, 32);
  for (int z = 0; z < 32; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 32; ++x) {
        const glm::vec3 c = f->minM + (glm::vec3(x, y, z) + 0.5f) * cell;
        float& d = f->values[(static_cast<size_t>(z) * 16 + y) * 32 + x];
        if (c.y < 0.8f) d = 3.0f;
        if (c.x > -3.5f && c.x < -2.0f && c.y > 1.5f && c.y < 2.8f) d = 2.5f;
      }
  return f;
}

// The reference's parts, kept as PFMs under HAZE_TEST_REFERENCE_CACHE between runs.
ReferenceImages reference(const std::string& name, const Venue& venue, const FrameState& frame) {
  const char* cache = std::getenv("HAZE_TEST_REFERENCE_CACHE");
  const std::filesystem::path base = cache ? std::filesystem::path(cache) / name : "";
  if (cache) {
    auto in = readPfm(base.string() + ".in.pfm"), surface = readPfm(base.string() + ".surface.pfm");
    if (in.ok() && surface.ok() && in->width == kW && in->height == kH) {
      ReferenceImages r;
      r.inScattered = std::move(*in);
      r.surface = std::move(*surface);
      return r;
    }
  }
  const Bvh bvh(venue);
  ReferenceImages r = renderReferenceImages(bvh, frame, kW, kH);
  if (cache) {
    std::error_code ec;
    std::filesystem::create_directories(cache, ec);
    EXPECT_TRUE(writePfm(r.inScattered, base.string() + ".in.pfm").ok());
    EXPECT_TRUE(writePfm(r.surface, base.string() + ".surface.pfm").ok());
  }
  return r;
}

struct Parts {
  ImageRGB dry, in;  // the surfaces without scattering, and the in-scattering alone
};

Parts renderParts(Renderer& r, const FrameState& frame) {
  FrameState dry = frame;
  dry.medium.absorption = frame.medium.extinction();
  dry.medium.scattering = 0.0f;
  r.render(dry);
  Parts p{r.readRadiance(), {}};
  r.render(frame);
  p.in = r.readRadiance();
  for (size_t i = 0; i < p.in.pixels.size(); ++i) p.in.pixels[i] -= p.dry.pixels[i];
  return p;
}

// The mean relative error of the red channel over the pixels above 1 % of the reference's largest.
double surfaceError(const ImageRGB& gpu, const ImageRGB& ref, size_t& count) {
  float peak = 0.0f;
  for (const glm::vec3& p : ref.pixels) peak = std::max(peak, p.r);
  double sum = 0.0;
  count = 0;
  for (size_t i = 0; i < gpu.pixels.size(); ++i)
    if (ref.pixels[i].r > 0.01f * peak) {
      sum += std::fabs(gpu.pixels[i].r - ref.pixels[i].r) / ref.pixels[i].r;
      ++count;
    }
  return count ? sum / count : 1.0;
}

class SunRender : public GlTest {};

void check(const std::string& name, const Venue& venue, const ReferenceImages& ref, const RenderSettings& settings,
           double coreLimit, double wideLimit, double surfaceLimit,
           std::shared_ptr<const DensityField> field = nullptr) {
  auto r = Renderer::create(venue, settings);
  ASSERT_TRUE(r.ok()) << r.error().str();
  FrameState frame = sunFrame(270.0f, 30.0f);
  frame.medium.density = field;
  const Parts gpu = renderParts(**r, frame);
  size_t count = 0;
  const double surf = surfaceError(gpu.dry, ref.surface, count);
  const auto c = compareBeams(gpu.in, ref.inScattered);
  ASSERT_TRUE(c.ok()) << c.error().str();
  std::printf("[ %s ] L_in: %.4f over %zu core values, %.4f over %zu wide; leak %.5f; surfaces %.4f over %zu px\n",
              name.c_str(), c->coreError, c->coreValues, c->wideError, c->wideValues, c->leak(), surf, count);
  EXPECT_GE(c->coreValues, 2000u);
  EXPECT_GE(count, 2000u);  // the sunlit patch on the floor (the rest is ambient, under 1 %)
  EXPECT_LT(c->coreError, coreLimit) << name;
  EXPECT_LT(c->wideError, wideLimit) << name;
  EXPECT_LT(surf, surfaceLimit) << name;
  // The limits see a wrong sun: moved by 3 degrees, and 10 % too bright.
  FrameState movedFrame = sunFrame(273.0f, 30.0f);
  movedFrame.medium.density = field;
  const Parts moved = renderParts(**r, movedFrame);
  const auto m = compareBeams(moved.in, ref.inScattered);
  ASSERT_TRUE(m.ok());
  size_t movedCount = 0;
  const double movedSurf = surfaceError(moved.dry, ref.surface, movedCount);
  std::printf("[ %s ] the sun 3 degrees off: %.4f / %.4f, surfaces %.4f\n", name.c_str(), m->coreError, m->wideError,
              movedSurf);
  EXPECT_FALSE(m->coreError < coreLimit && m->wideError < wideLimit) << name << ": the limits pass a moved sun";
  EXPECT_FALSE(movedSurf < surfaceLimit) << name << ": the surface limit passes a moved sun";
  if (field) {  // and they see the field: the uniform medium fails them
    const Parts uniform = renderParts(**r, sunFrame(270.0f, 30.0f));
    const auto u = compareBeams(uniform.in, ref.inScattered);
    ASSERT_TRUE(u.ok());
    std::printf("[ %s ] the uniform medium instead: %.4f / %.4f\n", name.c_str(), u->coreError, u->wideError);
    EXPECT_FALSE(u->coreError < coreLimit && u->wideError < wideLimit) << name << ": the limits pass the uniform medium";
  }
  ImageRGB brighter = gpu.in;
  for (glm::vec3& p : brighter.pixels) p *= 1.1f;
  const auto b = compareBeams(brighter, ref.inScattered);
  ASSERT_TRUE(b.ok());
  EXPECT_FALSE(b->coreError < coreLimit && b->wideError < wideLimit) << name << ": the limits pass a 10 % error";
  if (std::getenv("HAZE_TEST_IMAGES") || c->coreError >= coreLimit || c->wideError >= wideLimit) {
    for (const auto& file : writeDiagnostics(name, gpu.in, ref.inScattered)) std::printf("[ %s ] wrote %s\n", name.c_str(), file.c_str());
    for (const auto& file : writeDiagnostics(name + "_surfaces", gpu.dry, ref.surface))
      std::printf("[ %s ] wrote %s\n", name.c_str(), file.c_str());
  }
}

TEST_F(SunRender, AShaftThroughAWindowMatchesTheReference) {
  const Venue venue = windowRoom();
  const ReferenceImages ref = reference("sun_window", venue, sunFrame(270.0f, 30.0f));
  // Measured (L_in cores / wide / sunlit surfaces): high 0.79 % / 0.81 % / 0.48 %, default
  // 3.18 % / 3.27 % / 1.05 % (96 steps and one frame: noise across the shaft's edges). The
  // limits are those times about 1.5, rounded up, and never above 8 % / 5 % at default; the sun
  // 3 degrees off measures 27 % / 6 %, and the shaft 10 % brighter fails them too.
  check("sun_window_high", venue, ref, renderSettingsFor(Quality::High, kW, kH), 0.013, 0.013, 0.008);
  check("sun_window_default", venue, ref, renderSettingsFor(Quality::Default, kW, kH), 0.048, 0.049, 0.017);
  // The default preset as it is from 1280 px wide: the scattering at half resolution, the
  // depth-aware upsample and the refinement, which the sun's march shares with the beams.
  RenderSettings half = renderSettingsFor(Quality::Default, kW, kH);
  half.scatterDivisor = 2;
  // Measured 4.28 % / 4.39 % / 1.05 %: 1.5 times that is above the 8 % / 5 % wanted at default,
  // so the limits are those.
  check("sun_window_default_half", venue, ref, half, 0.064, 0.05, 0.017);
}

TEST_F(SunRender, AShaftThroughUnevenHazeMatchesTheReference) {
  const Venue venue = windowRoom();
  FrameState frame = sunFrame(270.0f, 30.0f);
  frame.medium.density = unevenAir(venue);
  const ReferenceImages ref = reference("sun_window_field", venue, frame);
  // Measured (L_in cores / wide / sunlit surfaces): high 0.89 % / 0.91 % / 3.3 %, default
  // 3.04 % / 3.10 % / 3.8 % (96 steps). The surfaces' error is the sun's path map, trilinear between the
  // cell centres of the field's grid, across the ground layer's step from 3 to 0.4 that the
  // sun crosses on its way to the floor. Limits about 1.5 times these; the sun 3 degrees off
  // measures 29 % / 9 %, the uniform medium 64 %.
  check("sun_field_high", venue, ref, renderSettingsFor(Quality::High, kW, kH), 0.015, 0.015, 0.055,
        frame.medium.density);
  check("sun_field_default", venue, ref, renderSettingsFor(Quality::Default, kW, kH), 0.046, 0.047, 0.06,
        frame.medium.density);
}

}  // namespace
}  // namespace haze::test
