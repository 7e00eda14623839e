// The venue on the GPU: one vertex buffer and one index buffer for every primitive (world
// space, so shadow and surface passes share them), the indices grouped by material: one draw
// per material for the G-buffer pass, one draw of everything for the depth-only passes (a venue of
// thousands of meshes costs a handful of draw calls, not thousands per shadow map). The
// depth-only passes' copy of the indices is sorted into spatial chunks with bounds, so that a
// beam's shadow map draws only the chunks its frustum reaches.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "renderer/gl/objects.h"
#include "shows/scene/venue.h"

namespace haze {

// One vertex as venue.vert.glsl reads it; fixture bodies (gpu_bodies.h) use the same layout.
struct VenueVertex {
  glm::vec3 position;
  glm::vec3 normal;
  float u, v;
};
// Sets vao's attribute formats to VenueVertex and attaches buffer as its vertex buffer.
void setVenueVertexLayout(GLuint vao, GLuint buffer);

class GpuVenue {
 public:
  // cullChunks false: drawInside draws every chunk (the same depths, for tests).
  explicit GpuVenue(const Venue& venue, bool cullChunks = true);

  struct Draw {
    GLsizei indexCount;
    size_t firstIndexBytes;
    GLint baseVertex;
    int material;
  };
  struct GpuMaterial {
    glm::vec4 baseColor;
    glm::vec3 emissive;
    int baseColorTexture;  // index into textures(), -1 none
    int emissiveTexture;
  };

  // Binds the vertex array; then issue draw(d) for each material's range, or drawAll().
  void bind() const;
  void draw(const Draw& d) const;
  void drawAll() const;
  // Depth only: binds the chunked vertex array and draws the chunks whose bounds are not wholly
  // outside viewProj's clip volume (what the others would draw is clipped away anyway, so the
  // depths are the same). Returns the triangles drawn.
  size_t drawInside(const glm::mat4& viewProj) const;
  // What drawInside would draw, without drawing.
  size_t trianglesInside(const glm::mat4& viewProj) const;
  size_t triangleCount() const { return static_cast<size_t>(indexCount_) / 3; }
  const std::vector<Draw>& draws() const { return draws_; }
  const std::vector<GpuMaterial>& materials() const { return materials_; }
  const gl::Texture& texture(int i) const { return textures_[static_cast<size_t>(i)]; }
  glm::vec3 boundsMin() const { return boundsMin_; }
  glm::vec3 boundsMax() const { return boundsMax_; }

 private:
  gl::Buffer vertices_{"venue_vertices"};
  gl::Buffer indices_{"venue_indices"};
  gl::VertexArray vao_{"venue_vao"};
  struct Chunk {
    GLsizei indexCount;
    size_t firstIndex;
    glm::vec3 boundsMin, boundsMax;
  };
  gl::Buffer chunkIndices_{"venue_chunk_indices"};
  gl::VertexArray chunkVao_{"venue_chunk_vao"};
  std::vector<Chunk> chunks_;
  // The index ranges of the chunks drawInside draws (adjacent ones merged); returns their triangles.
  size_t rangesInside(const glm::mat4& viewProj, std::vector<GLsizei>& counts, std::vector<const void*>& offsets) const;
  void makeChunks(const std::vector<VenueVertex>& verts, const std::vector<uint32_t>& idx);
  bool cullChunks_ = true;
  std::vector<Draw> draws_;  // one per material that has triangles
  GLsizei indexCount_ = 0;
  std::vector<GpuMaterial> materials_;
  std::vector<gl::Texture> textures_;
  glm::vec3 boundsMin_{0.0f}, boundsMax_{0.0f};
};

}  // namespace haze
