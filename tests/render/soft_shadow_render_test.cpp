// Soft shadows (docs/physics.md, "Soft shadows"; docs/rendering.md, "Soft shadows"): a spot
// with a large lens (r_lens 0.09 m) and a sphere in its beam. The GPU's PCSS against the CPU
// reference's visible fraction of the lens disc: the in-scattering seen from the side (the
// shadow shaft and its penumbra), and the floor pool's shadow edge seen from above, whose
// penumbra must span the width that similar triangles give. The hard-shadow image must fail
// where the soft one passes, so the test sees the difference.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/render_session.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/bvh.h"
#include "shows/scene/image_compare.h"

namespace haze::test {
namespace {

constexpr float kLensRadiusM = 0.09f;
constexpr float kLensHeightM = 7.0f;
const glm::vec3 kSphereCentre{0.0f, 4.0f, 0.0f};
constexpr float kSphereRadiusM = 0.5f;

Venue sphereVenue(bool withSphere, glm::vec3 centre = kSphereCentre, float radiusM = kSphereRadiusM) {
  Venue venue = floorVenue(16.0f, 0.4f);
  if (withSphere) addSphere(venue, centre, radiusM, 96, 48);
  return venue;
}

FrameState spotFrame(float beamDeg, float fieldDeg) {
  FrameState frame;
  frame.softShadows = true;
  frame.medium.scattering = 0.05f;
  frame.beams.push_back(makeBeam({0.0f, kLensHeightM, 0.0f}, {0.0f, -1.0f, 0.0f}, beamDeg, fieldDeg, 50000.0f));
  frame.beams.back().optics.lensRadiusM = kLensRadiusM;
  return frame;
}

// The reference's options: HAZE_TEST_DISC_SAMPLES, HAZE_TEST_SURFACE_DISC_SAMPLES and
// HAZE_TEST_DISC_PROBE=0 measure its
// convergence (docs/reference.md, "Soft shadows").
ReferenceOptions referenceOptions() {
  ReferenceOptions o;
  if (const char* n = std::getenv("HAZE_TEST_DISC_SAMPLES")) o.lensDiscSamples = std::atoi(n);
  if (const char* n = std::getenv("HAZE_TEST_SURFACE_DISC_SAMPLES")) o.surfaceDiscSamples = std::atoi(n);
  if (const char* p = std::getenv("HAZE_TEST_DISC_PROBE")) o.lensDiscProbe = std::atoi(p) != 0;
  return o;
}

// The GPU's L_in: its image less the same frame without in-scattering (beams_vs_reference_test.cpp).
ImageRGB gpuInScattered(Renderer& r, const FrameState& frame) {
  FrameState dry = frame;
  dry.medium.absorption = frame.medium.extinction();
  dry.medium.scattering = 0.0f;
  r.render(dry);
  ImageRGB gpu = r.readRadiance();
  r.render(frame);
  const ImageRGB wet = r.readRadiance();
  for (size_t i = 0; i < gpu.pixels.size(); ++i) gpu.pixels[i] = wet.pixels[i] - gpu.pixels[i];
  return gpu;
}

double meanRelativeError(const ImageRGB& a, const ImageRGB& ref, const std::vector<size_t>& pixels) {
  double sum = 0.0;
  for (size_t i : pixels) sum += std::abs(a.pixels[i].g - ref.pixels[i].g) / ref.pixels[i].g;
  return pixels.empty() ? 0.0 : sum / static_cast<double>(pixels.size());
}

// The GPU's radiance of each frame over the venue with the blocker (`shaded`), and of the first
// frame over the venue without it: a floor's V is the one over the other. Empty when a renderer
// cannot be made (the test fails).
struct FloorImages {
  ImageRGB open;
  std::vector<ImageRGB> shaded;
};
FloorImages renderFloor(const Venue& shaded, const Venue& open, Quality q, int w, int h, const std::vector<FrameState>& frames) {
  FloorImages out;
  const RenderSettings settings = renderSettingsFor(q, w, h);
  auto rs = Renderer::create(shaded, settings);
  auto ro = Renderer::create(open, settings);
  EXPECT_TRUE(rs.ok() && ro.ok());
  if (!rs.ok() || !ro.ok()) return out;
  (*ro)->render(frames.front());
  out.open = (*ro)->readRadiance();
  for (const FrameState& f : frames) {
    (*rs)->render(f);
    out.shaded.push_back((*rs)->readRadiance());
  }
  return out;
}

class SoftShadow : public GlTest {};

// The shaft under the sphere seen from the side: every ray crosses lit haze, the penumbra, the
// umbra (high up) and the penumbra again. Limits: the measured errors (docs/rendering.md,
// "Soft shadows") with a margin, within 5 % at high and 10 % at default.
TEST_F(SoftShadow, ShaftPenumbraInHazeMatchesTheReference) {
  // The sphere 1.5 m below the lens (its shadow 11.5 degrees off the axis, the penumbra about
  // 3 degrees wide at the floor), so that the penumbra takes a good part of each chord.
  const Venue venue = sphereVenue(true, {0.0f, 5.5f, 0.0f}, 0.3f);
  FrameState frame = spotFrame(30.0f, 40.0f);
  frame.camera.position = {9.0f, 3.0f, 0.0f};
  frame.camera.target = {0.0f, 3.0f, 0.0f};
  frame.camera.fovYDeg = 50.0f;
  constexpr int kW = 200, kH = 150;
  const Bvh bvh(venue);
  const ReferenceImages ref = renderReferenceImages(bvh, frame, kW, kH, referenceOptions());

  struct Case {
    Quality quality;
    const char* label;
    double core, wide, penumbra;
  };
  // Measured on llvmpipe (cores / wide / penumbra): high 0.0110 / 0.0237 / 0.0197, default
  // 0.0248 / 0.0324 / 0.0391 (0.0208 and 0.0408 since the shadow taps became loops); the limits
  // are those times 1.5. Hard shadows measured against the same reference: high 0.0208 / 0.0319
  // / 0.0425, default 0.0342 / 0.0388 / 0.0600, each failing the penumbra's limit, and at high
  // the cores' too (checked below). At default the hard image's cores were 0.0521 until hard
  // shadows walked twice the chords that cross an edge (planes.frag.glsl): what is left between
  // hard and soft there is the penumbra, which the penumbra's limit sees.
  for (const Case& c : {Case{Quality::High, "high", 0.0165, 0.0356, 0.0296},
                        Case{Quality::Default, "default", 0.0372, 0.0486, 0.0587}}) {
    auto r = Renderer::create(venue, renderSettingsFor(c.quality, kW, kH));
    ASSERT_TRUE(r.ok()) << r.error().str();
    const ImageRGB soft = gpuInScattered(**r, frame);
    FrameState hardFrame = frame;
    hardFrame.softShadows = false;
    const ImageRGB hard = gpuInScattered(**r, hardFrame);
    const auto s = compareBeams(soft, ref.inScattered);
    const auto h = compareBeams(hard, ref.inScattered);
    ASSERT_TRUE(s.ok() && h.ok());
    // The penumbra: where the GPU's soft and hard images differ by more than 2 % (of the
    // reference) among the reference's lit values (above 1 % of its largest).
    float maxRef = 0.0f;
    for (const glm::vec3& p : ref.inScattered.pixels) maxRef = std::max(maxRef, p.g);
    std::vector<size_t> penumbra;
    for (size_t i = 0; i < soft.pixels.size(); ++i)
      if (ref.inScattered.pixels[i].g > 0.01f * maxRef &&
          std::abs(soft.pixels[i].g - hard.pixels[i].g) > 0.02f * ref.inScattered.pixels[i].g)
        penumbra.push_back(i);
    const double softPen = meanRelativeError(soft, ref.inScattered, penumbra);
    const double hardPen = meanRelativeError(hard, ref.inScattered, penumbra);
    std::printf("[ soft_shaft_%s ] soft: cores %.4f over %zu, wide %.4f over %zu; hard: cores %.4f, wide %.4f; "
                "penumbra (%zu pixels): soft %.4f, hard %.4f\n",
                c.label, s->coreError, s->coreValues, s->wideError, s->wideValues, h->coreError, h->wideError,
                penumbra.size(), softPen, hardPen);
    EXPECT_GE(s->coreValues, 2000u);
    EXPECT_GE(penumbra.size(), 300u) << "too few penumbra pixels to measure";
    EXPECT_LT(s->coreError, c.core) << c.label;
    EXPECT_LT(s->wideError, c.wide) << c.label;
    EXPECT_LT(softPen, c.penumbra) << c.label << ": the penumbra";
    // Teeth: hard shadows against the soft reference fail the same limits.
    if (c.quality == Quality::High) {
      EXPECT_GT(h->coreError, c.core) << c.label << ": hard shadows pass the cores' limit";
    }
    EXPECT_GT(hardPen, c.penumbra) << c.label << ": hard shadows pass the penumbra's limit";
    // And so does the soft image made 10 % brighter.
    ImageRGB brighter = soft;
    for (glm::vec3& p : brighter.pixels) p *= 1.1f;
    const auto b = compareBeams(brighter, ref.inScattered);
    ASSERT_TRUE(b.ok());
    EXPECT_GT(b->coreError, c.core) << c.label << ": the limits pass the image scaled by 1.1";
    if (HasFailure() || std::getenv("HAZE_TEST_IMAGES")) {
      for (const auto& f : writeDiagnostics(std::string("soft_shaft_") + c.label, soft, ref.inScattered))
        std::printf("[ soft_shaft_%s ] wrote %s\n", c.label, f.c_str());
    }
  }
}

// The radius on the floor (y = 0) where the line from the lens point at radial offset lensX
// (in the plane through the axis) grazes the sphere on the +x side.
double tangentFloorRadius(double lensX) {
  const double px = lensX, py = kLensHeightM;
  const double cx = kSphereCentre.x, cy = kSphereCentre.y, a = kSphereRadiusM;
  const double dx = cx - px, dy = cy - py, d = std::sqrt(dx * dx + dy * dy);
  // The tangent direction: the centre's direction turned away from the axis by asin(a / d).
  const double toCentre = std::atan2(dy, dx), half = std::asin(a / d);
  const double dir = toCentre + half;  // towards +x (dy < 0: the angle is below the horizon)
  const double t = -py / std::sin(dir);
  return px + t * std::cos(dir);
}

// Where V, along the image's middle row from its centre outwards, first reaches `level`:
// a fractional pixel index by linear interpolation.
double crossing(const std::vector<double>& v, double level) {
  for (size_t i = 1; i < v.size(); ++i)
    if (v[i - 1] < level && v[i] >= level) return double(i - 1) + (level - v[i - 1]) / (v[i] - v[i - 1]);
  return -1.0;
}

// The floor pool from straight above, below the sphere (no haze): V = the image with the sphere
// over the image without it. The penumbra runs from the umbra's edge (the line from the near
// rim of the lens grazing the sphere) to its outer edge (from the far rim), similar triangles.
TEST_F(SoftShadow, FloorPenumbraHasTheWidthOfSimilarTriangles) {
  // Wide enough that the shadow's edge (about 10 degrees off the axis) lies where I_eff is flat.
  FrameState frame = spotFrame(40.0f, 50.0f);
  frame.medium.scattering = 0.0f;
  constexpr float kCameraHeightM = 3.2f, kFovDeg = 60.0f;
  frame.camera.position = {0.0f, kCameraHeightM, 0.0f};
  frame.camera.target = {0.0f, 0.0f, 0.0f};
  frame.camera.up = {0.0f, 0.0f, -1.0f};
  frame.camera.fovYDeg = kFovDeg;
  constexpr int kW = 241, kH = 161;  // odd: the middle row and column pass through the axis
  // Metres on the floor per pixel.
  const double mPerPx = 2.0 * kCameraHeightM * std::tan(glm::radians(kFovDeg) / 2.0) / kH;
  const double umbra = tangentFloorRadius(kLensRadiusM), outer = tangentFloorRadius(-kLensRadiusM);
  const double hardEdge = tangentFloorRadius(0.0);

  const Venue shaded = sphereVenue(true), open = sphereVenue(false);
  const Bvh shadedBvh(shaded), openBvh(open);
  const ImageRGB refShaded = renderReferenceImages(shadedBvh, frame, kW, kH, referenceOptions()).total;
  const ImageRGB refOpen = renderReferenceImages(openBvh, frame, kW, kH, referenceOptions()).total;
  // V along the middle row, from the centre to the right (+x on the floor).
  auto profile = [&](const ImageRGB& withSphere, const ImageRGB& without) {
    std::vector<double> v;
    const int row = kH / 2;
    for (int i = kW / 2; i < kW; ++i) {
      const size_t k = static_cast<size_t>(row) * kW + i;
      v.push_back(withSphere.pixels[k].g / std::max(without.pixels[k].g, 1e-12f));
    }
    return v;
  };
  const std::vector<double> refV = profile(refShaded, refOpen);
  std::printf("[ soft_floor ] predicted: umbra %.4f m, outer %.4f m (hard edge %.4f m); %.2f px wide at %.4f m/px\n",
              umbra, outer, hardEdge, (outer - umbra) / mPerPx, mPerPx);

  for (Quality q : {Quality::High, Quality::Default}) {
    const char* label = q == Quality::High ? "high" : "default";
    FrameState hardFrame = frame;
    hardFrame.softShadows = false;
    const FloorImages gpu = renderFloor(shaded, open, q, kW, kH, {frame, hardFrame});
    ASSERT_EQ(gpu.shaded.size(), 2u);
    const ImageRGB& gpuOpen = gpu.open;
    const ImageRGB& gpuSoft = gpu.shaded[0];
    const ImageRGB& gpuHard = gpu.shaded[1];
    for (const auto& [name, v] : {std::pair{"reference", refV}, std::pair{"gpu soft", profile(gpuSoft, gpuOpen)},
                                  std::pair{"gpu hard", profile(gpuHard, gpuOpen)}}) {
      const double inner = crossing(v, 0.02), outerPx = crossing(v, 0.98);
      std::printf("[ soft_floor_%s ] %s: V 0.02 at %.2f px (predicted %.2f), 0.98 at %.2f px (predicted %.2f)\n",
                  label, name, inner, umbra / mPerPx, outerPx, outer / mPerPx);
      // Profile index j is centred j pixels from the axis (the middle column is on it).
      const bool isHard = std::string(name) == "gpu hard";
      const double tol = 2.0;
      if (isHard) {
        EXPECT_LT(outerPx - inner, 0.5 * (outer - umbra) / mPerPx) << label << ": the hard shadow has a penumbra";
      } else {
        EXPECT_NEAR(inner, umbra / mPerPx, tol) << label << " " << name << ": the umbra's edge";
        EXPECT_NEAR(outerPx, outer / mPerPx, tol) << label << " " << name << ": the penumbra's outer edge";
      }
    }
    // And the floor's V against the reference's across the penumbra.
    const std::vector<double> gpuV = profile(gpuSoft, gpuOpen);
    double err = 0.0;
    int n = 0;
    for (size_t i = 0; i < refV.size(); ++i)
      if (refV[i] > 0.02 && refV[i] < 0.98) {
        err += std::abs(gpuV[i] - refV[i]);
        ++n;
      }
    std::printf("[ soft_floor_%s ] mean |V_gpu - V_ref| over %d penumbra pixels: %.4f\n", label, n, n ? err / n : 0.0);
    EXPECT_GE(n, 8);
    // Measured 0.0389 at high and 0.0385 at default (the PCSS blocker depth is a mean over a curved
    // blocker); the limit is 1.5 times that.
    EXPECT_LT(err / std::max(n, 1), 0.062) << label;
  }
}


// The same sphere's shadow on the floor from a spot 45 degrees off the vertical: the floor is
// slanted to the lens, so half of each blocker search around a floor point looks at floor that
// is nearer to the lens than the point. Counted as blockers, that floor pulls the penumbra's
// blocker depth towards the floor and the penumbra in towards a hard edge; compared against
// the receiver's own plane, it is not a blocker (docs/rendering.md, "Soft shadows"). V on the
// floor from above, against the reference's, over the penumbra.
TEST_F(SoftShadow, SlantedFloorPenumbraMatchesTheReference) {
  const glm::vec3 lens{-5.0f, 5.0f, 0.0f}, aim = glm::normalize(glm::vec3{1.0f, -1.0f, 0.0f});
  const glm::vec3 centre = lens + 3.2f * aim;  // 3.2 m down the axis, 3.9 m above the pool's centre
  FrameState frame;
  frame.softShadows = true;
  frame.medium.scattering = 0.0f;
  frame.beams.push_back(makeBeam(lens, aim, 40.0f, 50.0f, 50000.0f));
  frame.beams.back().optics.lensRadiusM = kLensRadiusM;
  frame.camera.position = {0.6f, 3.0f, 0.0f};
  frame.camera.target = {0.6f, 0.0f, 0.0f};
  frame.camera.up = {0.0f, 0.0f, -1.0f};
  frame.camera.fovYDeg = 60.0f;
  constexpr int kW = 241, kH = 161;
  const Venue shaded = sphereVenue(true, centre, 0.35f), open = sphereVenue(false);
  const Bvh shadedBvh(shaded), openBvh(open);
  const ImageRGB refShaded = renderReferenceImages(shadedBvh, frame, kW, kH, referenceOptions()).total;
  const ImageRGB refOpen = renderReferenceImages(openBvh, frame, kW, kH, referenceOptions()).total;
  auto visibility = [](const ImageRGB& with, const ImageRGB& without) {
    std::vector<double> v(with.pixels.size());
    for (size_t i = 0; i < v.size(); ++i) v[i] = with.pixels[i].g / std::max(without.pixels[i].g, 1e-12f);
    return v;
  };
  const std::vector<double> refV = visibility(refShaded, refOpen);
  std::vector<size_t> penumbra;
  for (size_t i = 0; i < refV.size(); ++i)
    if (refOpen.pixels[i].g > 0.0f && refV[i] > 0.05 && refV[i] < 0.95) penumbra.push_back(i);
  for (Quality q : {Quality::High, Quality::Default}) {
    const char* label = q == Quality::High ? "high" : "default";
    const FloorImages gpu = renderFloor(shaded, open, q, kW, kH, {frame});
    ASSERT_EQ(gpu.shaded.size(), 1u);
    const std::vector<double> gpuV = visibility(gpu.shaded[0], gpu.open);
    double err = 0.0, bias = 0.0;
    for (size_t i : penumbra) {
      err += std::abs(gpuV[i] - refV[i]);
      bias += gpuV[i] - refV[i];
    }
    const double n = static_cast<double>(std::max<size_t>(penumbra.size(), 1));
    std::printf("[ slanted_floor_%s ] %zu penumbra pixels: mean |V_gpu - V_ref| %.4f, mean signed %.4f\n", label,
                penumbra.size(), err / n, bias / n);
    EXPECT_GE(penumbra.size(), 200u);
    // Measured 0.0394 at high and 0.0383 at default (0.110 and 0.088, biased dark, with the floor
    // counted as its own blocker); the limit is 1.5 times the larger.
    EXPECT_LT(err / n, 0.06) << label;
  }
}

}  // namespace
}  // namespace haze::test
