// The fixtures' bodies on the GPU (docs/rendering.md, "Fixture bodies"): each frame's boxes as
// world-space triangles in the venue's vertex layout, so the venue's depth and surface programs
// draw them unchanged; one draw per albedo.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "fixtures/body.h"
#include "renderer/gl/objects.h"

namespace haze {

class GpuBodies {
 public:
  // Replaces the triangles with these boxes' (a few hundred bytes per fixture).
  void update(const std::vector<BodyBox>& boxes);

  struct Draw {
    GLint first;
    GLsizei count;
    glm::vec3 albedo;
  };
  bool empty() const { return vertexCount_ == 0; }
  // Binds the vertex array; then draw(d) per albedo, or drawAll() for depth.
  void bind() const;
  void draw(const Draw& d) const;
  void drawAll() const;
  const std::vector<Draw>& draws() const { return draws_; }

 private:
  gl::Buffer vertices_{"body_vertices"};
  gl::VertexArray vao_{"body_vao"};
  GLsizeiptr capacityBytes_ = 0;
  GLsizei vertexCount_ = 0;
  std::vector<Draw> draws_;
};

}  // namespace haze
