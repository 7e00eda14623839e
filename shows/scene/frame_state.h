// FrameState: everything the renderer (GPU or CPU reference) needs for one frame, as plain data:
// the camera, the medium, and each fixture's beam (pose and optics). Built by app/ from a show
// and its playback state; the renderer never sees shows or profiles.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "atmosphere/density_field.h"
#include "fixtures/beam_optics.h"
#include "fixtures/body.h"
#include "fixtures/pose.h"
#include "shows/scene/particles.h"
#include "shaders/interface.h"

namespace haze {

struct CameraState {
  glm::vec3 position{0.0f, 2.0f, 10.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDeg = 40.0f;
  float farM = 100.0f;   // where a ray that hits nothing stops
  float nearM = 0.05f;
};

enum class Phase { Hazy, Isotropic, HenyeyGreenstein };
// The renderer passes a Phase to shaders/phase.glsl as its integer value.
static_assert(static_cast<int>(Phase::Hazy) == HAZE_PHASE_HAZY);
static_assert(static_cast<int>(Phase::Isotropic) == HAZE_PHASE_ISOTROPIC);
static_assert(static_cast<int>(Phase::HenyeyGreenstein) == HAZE_PHASE_HENYEY_GREENSTEIN);

struct MediumState {
  float scattering = 0.0f;  // sigma_s [1/m]
  float absorption = 0.0f;  // sigma_a [1/m]
  Phase phase = Phase::Hazy;
  float g = 0.0f;           // HG asymmetry
  glm::vec3 ambient{0.0f};
  glm::vec3 background{0.0f};
  // D(x), multiplying sigma_s and sigma_a (docs/physics.md, "A medium that is not uniform");
  // none: D = 1 everywhere, the uniform medium.
  std::shared_ptr<const DensityField> density;
  float extinction() const { return scattering + absorption; }
};

// The sun (docs/physics.md, "The sun"): light of illuminance E arriving along one direction
// everywhere, through the venue's openings. sunDirection (shows/scene/physics.h) turns a
// show's azimuth and elevation into `direction`.
struct SunState {
  bool on = false;
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit, the way the light travels (from the sun)
  glm::vec3 illuminance{0.0f};             // c * E [lux per linear RGB channel]
  bool lit() const { return on && (illuminance.r > 0.0f || illuminance.g > 0.0f || illuminance.b > 0.0f); }
};

struct BeamState {
  int fixtureId = 0;
  int cell = -1;  // the cell of a multi-cell fixture this beam is (docs/cells.md); -1: the fixture's one beam
  BeamPose pose;
  BeamOptics optics;
  // Changes whenever pose or optics change: the GPU renderer keys its shadow-map and
  // light-map caches on it (equal keys promise equal beams).
  uint64_t poseKey = 0;
  uint64_t opticsKey = 0;
};

struct FrameState {
  CameraState camera;
  MediumState medium;
  std::vector<BeamState> beams;
  SunState sun;
  // The fixtures' housings (docs/rendering.md, "Fixture bodies"): seen by the camera, lit by
  // the beams, and shadowing every beam but their own fixture's (BodyBox::fixtureId).
  std::vector<BodyBox> bodies;
  // The parts that have a model of their own (a GDTF's mesh): its triangles, placed.
  std::vector<BodyMesh> bodyMeshes;
  // Soft shadows (docs/physics.md, "Soft shadows"): V(x) is the fraction of each beam's lens
  // disc (BeamOptics::lensRadiusM) seen from x, an area light's penumbra; false: the point
  // test from the lens centre. Off here so that hand-built frames (tests) keep point lights;
  // shows turn it on unless they ask for "shadows": "hard" (shows/frame/frame_builder.cpp).
  bool softShadows = false;
  // Visible dust in the beams (docs/rendering.md, "Particles"): a display option, drawn only
  // when particles.settings.enabled; off, the image is the radiometric one.
  ParticleState particles;
};

}  // namespace haze
