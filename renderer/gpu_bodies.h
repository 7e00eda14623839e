// The fixtures' bodies on the GPU (docs/rendering.md, "Fixture bodies"): each frame's boxes as
// world-space triangles in the venue's vertex layout, so the venue's depth and surface programs
// draw them unchanged; one draw per albedo. Parts with a mesh of their own are uploaded once per
// distinct mesh (in the part's frame) and drawn per posed part with its model matrix.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fixtures/body.h"
#include "renderer/gl/objects.h"

namespace haze {

class GpuBodies {
 public:
  // Replaces the triangles with these boxes' (a few hundred bytes per fixture), and the mesh
  // draws with these (a mesh not seen before is uploaded; one no frame uses any more is freed).
  void update(const std::vector<BodyBox>& boxes, const std::vector<BodyMesh>& meshes = {});

  struct Draw {
    GLint first;
    GLsizei count;
    glm::vec3 albedo;
  };
  bool empty() const { return vertexCount_ == 0; }
  bool hasMeshes() const { return !meshDraws_.empty(); }
  // Binds the vertex array; then draw(d) per albedo, or drawAll() for depth.
  void bind() const;
  void draw(const Draw& d) const;
  void drawAll() const;
  const std::vector<Draw>& draws() const { return draws_; }
  // Every posed mesh with `program` (venue.vert.glsl): its model matrix per draw, and with
  // baseColorLocation >= 0 its albedo there; the model matrix is the identity again afterwards.
  void drawMeshes(GLuint program, GLint baseColorLocation) const;

 private:
  struct MeshBuffers {
    std::weak_ptr<const TriangleMesh> mesh;  // to free the buffers when the mesh is gone
    gl::Buffer vertices{"body_mesh_vertices"};
    gl::Buffer indices{"body_mesh_indices"};
    gl::VertexArray vao{"body_mesh_vao"};
    GLsizei indexCount = 0;
  };
  struct MeshDraw {
    const MeshBuffers* buffers;
    glm::mat4 model;
    glm::vec3 albedo;
  };

  gl::Buffer vertices_{"body_vertices"};
  gl::VertexArray vao_{"body_vao"};
  GLsizeiptr capacityBytes_ = 0;
  GLsizei vertexCount_ = 0;
  std::vector<Draw> draws_;
  std::map<const TriangleMesh*, std::unique_ptr<MeshBuffers>> meshBuffers_;
  std::vector<MeshDraw> meshDraws_;
};

}  // namespace haze
