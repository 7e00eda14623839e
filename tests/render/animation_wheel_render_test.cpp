// The animation wheel on a top-down floor render: a disc whose top half is opaque stands in the
// gate, and the pool is dark exactly where docs/physics.md's disc geometry puts the opaque half
// (computed here from the geometry, not by the code under test), on the GPU and in the CPU
// reference, at two angles of the disc; turning the disc moves the edge across the pool, not
// about the beam's axis. The frame builder turns a spinning disc to rotation + spin * clock.
#include <cmath>
#include <cstdio>

#include <glm/trigonometric.hpp>

#include "shows/frame/frame_builder.h"
#include "app/render_session.h"
#include "fixtures/animation_wheel.h"
#include "fixtures/attributes.h"
#include "fixtures/profile.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/image_compare.h"

namespace haze::test {
namespace {

constexpr int kSize = 160;
constexpr float kLensHeightM = 4.0f;
constexpr float kFieldDeg = 30.0f;
constexpr float kCameraHeightM = 10.0f;
constexpr float kCameraFovDeg = 20.0f;
constexpr float kInnerGate = 0.87f;  // gate radius inside which the pool is checked

FrameState floorFrame(float discAngleDeg) {
  FrameState f;
  f.camera.position = {0.0f, kCameraHeightM, 0.0f};
  f.camera.target = {0.0f, 0.0f, 0.0f};
  f.camera.up = {0.0f, 0.0f, -1.0f};
  f.camera.fovYDeg = kCameraFovDeg;
  BeamState b = makeBeam({0.0f, kLensHeightM, 0.0f}, {0.0f, -1.0f, 0.0f}, 24.0f, kFieldDeg, 20000.0f);
  b.pose = beamFrame({0.0f, kLensHeightM, 0.0f}, {0.0f, -1.0f, 0.0f}, {1.0f, 0.0f, 0.0f});
  // The top half (t > 0.5, +y of the disc) opaque: 1024 pixels across the disc's six gate radii,
  // so the bilinear edge is 0.006 gate radii wide, a third of a pixel here.
  b.optics.animation = halfOpaqueGobo(1024, true);
  b.optics.animationAngleDeg = discAngleDeg;
  f.beams.push_back(b);
  return f;
}

// What the geometry says for pixel (i, j): +1 lit, -1 dark inside the gate, -2 outside it, 0 too
// close to an edge to say.
// The camera looks straight down with +X to the right and -Z up; the beam's x_b is +X and
// y_b = x_b x z_b = -Z, so the gate's (u, v) runs along the picture's right and up.
int expected(int i, int j, float discAngleDeg) {
  const float halfM = kCameraHeightM * std::tan(glm::radians(kCameraFovDeg * 0.5f));
  const float x = ((static_cast<float>(i) + 0.5f) / kSize * 2.0f - 1.0f) * halfM;
  const float up = (1.0f - (static_cast<float>(j) + 0.5f) / kSize * 2.0f) * halfM;
  const float gateM = kLensHeightM * std::tan(glm::radians(kFieldDeg * 0.5f));  // the gate's rim on the floor
  const float u = x / gateM, v = up / gateM;
  const float pixelGate = 2.0f * halfM / kSize / gateM;  // one pixel in gate units
  const float margin = 1.5f * pixelGate;
  const float r = std::sqrt(u * u + v * v);
  if (r > 1.0f + margin) return -2;  // outside the gate
  if (r > kInnerGate) return 0;  // the rim and the beam's own falloff near it
  // The lens's dark back face hides the pool's centre from a camera straight above it: 5 cm of
  // lens 6 m away, seen against the floor 10 m away, covers 0.083 m of floor.
  if (r < 0.083f / gateM + margin) return 0;
  // The disc's own y at this gate point: the disc centred at (2, 0), turned by the angle. The
  // edge is the line through the centre where that y is 0.
  const float a = glm::radians(discAngleDeg);
  const float discY = -std::sin(a) * (u - 2.0f) + std::cos(a) * v;
  if (std::abs(discY) < margin) return 0;
  return discY > 0.0f ? -1 : 1;
}

class AnimationWheelRender : public GlTest {};

TEST_F(AnimationWheelRender, TheDiscCutsThePoolWhereItsGeometrySaysOnGpuAndReference) {
  Venue venue = floorVenue(16.0f, 0.5f);
  auto r = Renderer::create(venue, renderSettingsFor(Quality::High, kSize, kSize));
  ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  double litFraction[2] = {0, 0};
  int angleIndex = 0;
  for (float angle : {0.0f, 20.0f}) {
    const FrameState frame = floorFrame(angle);
    (*r)->render(frame);
    const ImageRGB gpu = (*r)->readRadiance();
    const ImageRGB ref = renderReference(venue, frame, kSize, kSize);
    float peak = 0.0f;
    for (const glm::vec3& v : ref.pixels) peak = std::max(peak, v.g);
    ASSERT_GT(peak, 0.0f);
    int checked = 0, lit = 0, inside = 0, wrongGpu = 0, wrongRef = 0;
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i) {
        const int e = expected(i, j, angle);
        if (e == 0) continue;
        ++checked;
        lit += e > 0;
        inside += e != -2;
        wrongRef += (ref.at(i, j).g > 0.02f * peak) != (e > 0);
        wrongGpu += (gpu.at(i, j).g > 0.02f * peak) != (e > 0);
      }
    std::printf("[ animation %g deg ] %d pixels checked (%d lit by the geometry); wrong: reference %d, GPU %d\n", angle,
                checked, lit, wrongRef, wrongGpu);
    EXPECT_GT(lit, 100);
    EXPECT_EQ(wrongRef, 0);
    EXPECT_EQ(wrongGpu, 0);
    const auto c = compareImages(gpu, ref);
    ASSERT_TRUE(c.ok());
    std::printf("[ animation %g deg ] GPU against reference: mean relative error %.4f over %zu values\n", angle, c->meanRelError,
                c->values);
    EXPECT_LT(c->meanRelError, 0.03);
    litFraction[angleIndex++] = static_cast<double>(lit) / inside;
  }
  // At 0 degrees the edge runs through the gate's centre (half the pool lit); turned by 20
  // degrees about a centre two gate radii away it is the line v = tan(20) (u - 2), 2 sin(20) =
  // 0.684 gate radii from the centre: within the checked radius R the lit circular segment is
  // (acos x - x sqrt(1 - x^2)) / pi of the disc, x = 0.684 / R (less the uncounted edge pixels).
  const double x = 2.0 * std::sin(glm::radians(20.0)) / kInnerGate;
  const double segment = (std::acos(x) - x * std::sqrt(1.0 - x * x)) / 3.14159265358979;
  std::printf("[ animation ] lit fraction %.3f at 0 deg, %.3f at 20 deg\n", litFraction[0], litFraction[1]);
  EXPECT_NEAR(litFraction[0], 0.5, 0.03);
  std::printf("[ animation ] the circular segment at 20 deg: %.3f\n", segment);
  EXPECT_NEAR(litFraction[1], segment, 0.015);
}

TEST(AnimationWheelFrame, ASpinningDiscStandsAtRotationPlusSpinTimesTheClock) {
  Attributes a;
  a.animation = "Flames";
  a.animationRotationDeg = 10.0f;
  a.animationSpinDegS = 15.0f;
  EXPECT_FLOAT_EQ(spunAt(a, 2.0).animationRotationDeg, 40.0f);
  EXPECT_FLOAT_EQ(spunAt(a, 0.0).animationRotationDeg, 10.0f);
  // The profile draws the slot's disc (its own image, or the default when it has none) at that angle.
  Profile p;
  Wheel w;
  w.name = "Animation";
  w.slots.push_back(WheelSlot{"Open", std::nullopt, "", nullptr});
  w.slots.push_back(WheelSlot{"Flames", std::nullopt, "", nullptr});
  p.animationWheels.push_back(w);
  const BeamOptics o = p.optics(spunAt(a, 2.0));
  ASSERT_NE(o.animation, nullptr);
  EXPECT_EQ(o.animation, defaultAnimationDisc());
  EXPECT_FLOAT_EQ(o.animationAngleDeg, 40.0f);
  a.animation = "Open";
  EXPECT_EQ(p.optics(a).animation, nullptr);
}

}  // namespace
}  // namespace haze::test
