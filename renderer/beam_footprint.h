// Where a beam's light cone falls on screen: the convex polygon that holds the projection of the
// cone from its lens to its reach, clipped to the screen, and its view-depth range. The planes
// pass rasterises this polygon, so pixels the cone cannot cover cost nothing. Pure geometry.
#pragma once

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "shows/scene/frame_state.h"
#include "shaders/interface.h"

namespace haze {

struct BeamFootprint {
  static constexpr int kMaxVertices = HAZE_FOOTPRINT_MAX_VERTICES;  // the planes shader's array
  bool visible = false;
  glm::vec4 rectNdc{-1, -1, 1, 1};        // the polygon's bounding rectangle
  std::array<glm::vec2, kMaxVertices> polygonNdc{};  // counter-clockwise, convex
  int vertexCount = 0;
  float zNear = 0, zFar = 0;              // view depths the cone spans, within the camera's
  float areaNdc() const;                  // of the polygon, in NDC units (the screen is 4)
};

// The cone of `beam` up to coneLengthM along its axis, seen by `camera` with this aspect ratio.
// When the cone reaches behind the camera's near plane the footprint is the whole screen.
BeamFootprint beamFootprint(const BeamState& beam, const CameraState& camera, float aspect, float coneLengthM);

}  // namespace haze
