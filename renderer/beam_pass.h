// In-scattering by virtual planes (docs/architecture.md, "Rendering shafts of light"): per beam, planes
// parallel to the screen at equal view-depth steps over only that beam's depth range and screen
// footprint; each plane samples the light map, the shadow map, the phase function and both
// attenuations, and adds into a float scattering buffer (optionally at lower resolution),
// which is then upsampled (depth-aware) onto the radiance target.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "fixtures/core/result.h"
#include "renderer/beam_footprint.h"
#include "renderer/beam_resources.h"
#include "renderer/density_resources.h"
#include "renderer/gl/objects.h"
#include "renderer/gl/program.h"
#include "shows/scene/frame_state.h"
#include "renderer/sun_pass.h"

namespace haze {

struct BeamPassSettings {
  int planes = 48;          // per beam, over its depth range
  int scatterDivisor = 1;   // 1 full resolution, 2 half (depth-aware upsample), ...
  // With scatterDivisor > 1: pixels where the low-resolution in-scattering has detail at the
  // texel scale (relative curvature above this, refine_mask.frag.glsl) are rendered again at
  // full resolution. 0 = off.
  float refineCurvature = 0.0f;
  // ... and only where the neighbourhood's brightest value is above this fraction of the frame's
  // mean in-scattering (the faint ends of beams are left to the upsample).
  float refineFloor = 0.0f;
  int frames = 1;           // jittered frames accumulated per render
  bool jitter = true;       // per-pixel plane offsets; off = plane centres (the paper's slicing)
  // One fragment per pixel walks the planes its ray crosses inside the cone (the planes clipped
  // to the light volume per pixel), instead of one fragment per pixel and plane. Same samples.
  bool fused = true;
  // Fused only: where a ray's chord through the cone spans fewer planes than this, the plane
  // lattice is refined by halving for that ray, so thin-looking beams keep their detail.
  int minSamplesPerChord = 8;
  // > 0: the paper's lattice mode: each plane is evaluated at the corners of a lattice x
  // lattice grid over the beam's footprint and interpolated by the rasteriser (no jitter, not
  // fused). For the accuracy study against the reference.
  int lattice = 0;
  // The frame's density field, soft shadows and phase function compiled into the planes'
  // program (renderer/shader_features.h); off, read from uniforms (same image, for tests).
  bool staticFeatures = true;
};

class BeamPass {
 public:
  static Result<BeamPass> create(int width, int height, const BeamPassSettings& settings);
  // For a new target size: the scattering buffers are made again, the programs kept.
  void resize(int width, int height);

  // Adds in-scattering into radianceFbo (whose depth texture is sceneDepth). With
  // accumulate, the scattering of earlier calls is kept and this call's frames (jittered on
  // from frame number firstFrame) are added: progressive refinement while nothing moves.
  // Returns the plane fragments rasterised (footprint pixels times planes), for the bench.
  // The sun's in-scattering (sun, when lit) is added into the same buffer, frame by frame.
  uint64_t render(const FrameState& frame, const BeamResources& beams, const DensityResources& density,
                  GLuint sceneDepth, GLuint radianceFbo,
                  bool accumulate = false, const SunPass* sun = nullptr);
  const BeamPassSettings& settings() const { return settings_; }
  int accumulatedFrames() const { return accumulated_; }
  // Beams whose in-scattering the last render drew (lit, drawn, footprint in view).
  int beamsDrawn() const { return beamsDrawn_; }
  // Of the last render's plane fragments, those that added light (inside a cone, in front of
  // the scene); the rest were spent on footprint pixels the cones do not cover.
  uint64_t scatteringFragments() const;
  // Pixels the last render refined at full resolution (0 without refinement).
  uint64_t refinedPixels() const;

 private:
  BeamPassSettings settings_;
  int width_ = 0, height_ = 0, lowW_ = 0, lowH_ = 0;
  bool refining() const { return settings_.scatterDivisor > 1 && settings_.refineCurvature > 0.0f; }
  uint64_t drawBeams(GLuint program, float frameJitter, const FrameState& frame,
                     const std::vector<BeamFootprint>& footprints, int targetW, int targetH);
  void markRefinedPixels();

  gl::Program planes_, planesFine_, composite_, scatterDepth_, refineMask_;
  gl::ProgramVariants planesStatic_, planesFineStatic_;  // per ShaderFeatures
  gl::Texture scatter_, lowDepth_;
  gl::Framebuffer scatterFbo_, lowDepthFbo_;
  // Refinement: the full-resolution scattering of the marked pixels, the mask, and the stencil
  // that keeps the full-resolution beam pass to them.
  gl::Texture fine_, mask_;
  gl::Renderbuffer stencil_;
  gl::Framebuffer fineFbo_, maskFbo_;
  gl::VertexArray vao_;
  gl::SamplesQuery scattered_, refined_;
  int scatterLevels_ = 1;
  int accumulated_ = 0;
  int beamsDrawn_ = 0;
};

}  // namespace haze
