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
  // With a camera (the surfaces' G-buffer pass), parts wholly outside its frustum are
  // skipped and a closed mesh seen from outside its bound has its back faces culled: the
  // nearest surface on every ray is the same, so the picture is.
  struct Camera {
    glm::mat4 viewProj;
    glm::vec3 eye;
  };
  void drawMeshes(GLuint program, GLint baseColorLocation, const Camera* camera = nullptr) const;
  // Parts drawn by the last drawMeshes with a camera (the others were outside its frustum).
  int meshesDrawn() const { return meshesDrawn_; }
  // Depth only: the listed boxes and meshes (indices into update()'s lists) with `program`, the
  // casters of one beam's shadow map (shows/scene/body_shadow.h).
  void drawCasters(GLuint program, const std::vector<int>& boxes, const std::vector<int>& meshes) const;

 private:
  struct MeshBuffers {
    std::weak_ptr<const TriangleMesh> mesh;  // to free the buffers when the mesh is gone
    gl::Buffer vertices{"body_mesh_vertices"};
    gl::Buffer indices{"body_mesh_indices"};
    gl::VertexArray vao{"body_mesh_vao"};
    GLsizei indexCount = 0;
    // Every edge shared by exactly two triangles that run it both ways (a closed, consistently
    // wound shell); outward: counter-clockwise seen from outside (positive signed volume).
    bool closed = false;
    bool outward = true;
    glm::vec3 center{0.0f};  // bounding sphere in the part's frame
    float radius = 0.0f;
  };
  struct MeshDraw {
    const MeshBuffers* buffers;
    glm::mat4 model;
    glm::vec3 albedo;
    bool mirrored;  // the axes flip handedness: the winding seen on screen flips too
  };

  gl::Buffer vertices_{"body_vertices"};
  gl::VertexArray vao_{"body_vao"};
  GLsizeiptr capacityBytes_ = 0;
  GLsizei vertexCount_ = 0;
  std::vector<Draw> draws_;
  std::map<const TriangleMesh*, std::unique_ptr<MeshBuffers>> meshBuffers_;
  std::vector<MeshDraw> meshDraws_;
  std::vector<GLint> boxFirst_;    // per box of update(): its first vertex
  std::vector<int> meshDrawOf_;    // per mesh of update(): its meshDraws_ entry, -1 for none
  mutable int meshesDrawn_ = 0;
};

}  // namespace haze
