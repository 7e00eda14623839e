// The CPU reference integrator: docs/physics.md's "What a pixel is", computed by brute force with
// exact shadow rays (against a Bvh of the venue's triangles) and exact I_eff lookups. It is the
// oracle every fast path of the GPU renderer is measured against; docs/reference.md says how it
// marches and how converged it is.
#pragma once

#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "shows/scene/bvh.h"
#include "shows/scene/frame_state.h"
#include "shows/scene/image.h"
#include "shows/scene/venue.h"

namespace haze {

struct ReferenceOptions {
  // The march steps uniformly in the angle that the step subtends at the beam's lens (the
  // beam's own angular resolution; it also absorbs the 1/r^2 peak near the lens). This is the
  // largest such step [rad]; the default 0.1 degree resolves a 2-degree beam with 20 steps.
  float maxStepAngleRad = 0.1f * 3.14159265358979f / 180.0f;
  // At least this many steps over each beam's chord, however narrow it looks from the lens.
  int minStepsPerChord = 64;
  // Shadow edges along the ray are found by bisection (12 halvings of the step) instead of
  // being left to the midpoint rule: a hard edge then costs ~1/4096 of a step, not up to 1/2.
  bool refineShadowEdges = true;
  // Steps across which I_eff jumps by more than 20 % (gobo edges, a photometric file's cut-off)
  // are sampled 16 times instead of once.
  bool refineIntensityEdges = true;
  // Geometry closer than this to a beam's lens casts no shadow (the GPU's shadow-map near
  // plane, or a fixture's own housing in the venue). 0 = every triangle counts.
  float lensClearanceM = 0.0f;
  // Soft shadows (FrameState::softShadows): V(x) is the fraction of the lens disc seen from x,
  // counted over this many stratified points of the disc (docs/reference.md, "Soft shadows"):
  // in the haze, where the march averages V over many steps, and on surfaces, one V per pixel.
  int lensDiscSamples = 64;
  int surfaceDiscSamples = 256;
  // Test the centre and eight rim points first and sample the whole disc only where they
  // disagree (the penumbra); false: always the whole disc.
  bool lensDiscProbe = true;
  // The sun's in-scattering is marched in steps of at most this length along the eye ray
  // (its integrand is smooth but for shadow edges, which are bisected).
  float sunStepM = 0.02f;
  // Worker threads; 0 = one per hardware thread.
  int threads = 0;
  // Called on the calling thread after each row it finishes, with the rows done by all threads
  // so far (a progress report; renders take minutes).
  std::function<void(int rowsDone, int rows)> onRows;
};

// One pixel's radiance, in parts (cd/m^2 per linear RGB channel).
struct PixelRadiance {
  glm::vec3 surface{0.0f};      // L_surf * exp(-sigma_t T), 0 where no surface is hit
  glm::vec3 inScattered{0.0f};  // L_in over [0, T]
  glm::vec3 background{0.0f};   // background * exp(-sigma_t T) where no surface is hit
  float depthM = 0.0f;          // T
  bool hitSurface = false;
  bool hitLens = false;         // T ends on a lens disc (front: surface is its L_lens, back: 0)
  glm::vec3 total() const { return surface + inScattered + background; }
};

// L_lens of docs/physics.md ("The lens") seen from eye, before attenuation: I_eff towards the
// eye over the disc's projected area, 0 from behind.
glm::vec3 lensLuminance(const BeamState& beam, const glm::vec3& eye);

// The unit direction of pixel (i, j)'s ray through its centre, j = 0 the top row
// (docs/physics.md's pinhole camera). Fractional pixel coordinates are allowed: (i, j) = (0, 0) is
// the top-left corner of the image, (W / 2, H / 2) the centre.
glm::vec3 cameraRayDirection(const CameraState& camera, int width, int height, float pixelX,
                             float pixelY);

// The radiance along one ray (dir unit) from origin, through the frame's medium and beams,
// stopping at the first surface or camera.farM.
PixelRadiance radianceAlongRay(const Bvh& bvh, const FrameState& frame, const glm::vec3& origin,
                               const glm::vec3& dir, const ReferenceOptions& options = {});

// Pixel (i, j) of a width x height image of the frame's camera, exactly as the image has it.
PixelRadiance radianceAtPixel(const Bvh& bvh, const FrameState& frame, int width, int height,
                              int i, int j, const ReferenceOptions& options = {});

// The whole image, with L_surf and L_in apart (the accuracy metric of docs/physics.md looks at the
// pixels where L_in is above 1 % of its maximum).
struct ReferenceImages {
  ImageRGB total;
  ImageRGB surface;      // PixelRadiance::surface + background
  ImageRGB inScattered;  // PixelRadiance::inScattered
  std::vector<float> depthM;  // T per pixel, row-major like the images
};
// width and height must be positive (the caller validates user input).
ReferenceImages renderReferenceImages(const Bvh& bvh, const FrameState& frame, int width,
                                      int height, const ReferenceOptions& options = {});

// The oracle's image: L per pixel. Builds a Bvh of the venue each call; keep a Bvh and call
// renderReferenceImages to render many frames of one venue.
ImageRGB renderReference(const Venue& venue, const FrameState& frame, int width, int height,
                         const ReferenceOptions& options = {});

}  // namespace haze
