#include "renderer/gpu_bodies.h"

#include <algorithm>
#include <cstddef>
#include <tuple>

#include <glm/gtc/type_ptr.hpp>

#include "renderer/gpu_venue.h"
#include "shaders/interface.h"

namespace haze {

void GpuBodies::update(const std::vector<BodyBox>& boxes, const std::vector<BodyMesh>& meshes) {
  // Meshes: each distinct one uploaded once, in its part's frame.
  meshDraws_.clear();
  for (const BodyMesh& bm : meshes) {
    if (!bm.mesh || bm.mesh->indices.empty()) continue;
    auto& slot = meshBuffers_[bm.mesh.get()];
    if (!slot || slot->mesh.expired()) {
      slot = std::make_unique<MeshBuffers>();
      slot->mesh = bm.mesh;
      const TriangleMesh& m = *bm.mesh;
      std::vector<VenueVertex> verts(m.positions.size());
      for (size_t i = 0; i < verts.size(); ++i) verts[i] = {m.positions[i], m.normals[i], 0.0f, 0.0f};
      glNamedBufferStorage(slot->vertices.id(), static_cast<GLsizeiptr>(verts.size() * sizeof(VenueVertex)),
                           verts.data(), 0);
      glNamedBufferStorage(slot->indices.id(), static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)),
                           m.indices.data(), 0);
      setVenueVertexLayout(slot->vao.id(), slot->vertices.id());
      glVertexArrayElementBuffer(slot->vao.id(), slot->indices.id());
      slot->indexCount = static_cast<GLsizei>(m.indices.size());
    }
    glm::mat4 model(bm.axes);
    model[3] = glm::vec4(bm.originM, 1.0f);
    meshDraws_.push_back({slot.get(), model, bm.albedo});
  }
  // Buffers of meshes no profile holds any more.
  for (auto it = meshBuffers_.begin(); it != meshBuffers_.end();)
    it = it->second->mesh.expired() ? meshBuffers_.erase(it) : std::next(it);

  std::vector<const BodyBox*> sorted;
  sorted.reserve(boxes.size());
  for (const BodyBox& b : boxes) sorted.push_back(&b);
  auto key = [](const BodyBox* b) { return std::tie(b->albedo.x, b->albedo.y, b->albedo.z); };
  std::stable_sort(sorted.begin(), sorted.end(), [&](const BodyBox* a, const BodyBox* b) { return key(a) < key(b); });
  std::vector<glm::vec3> positions, normals;
  draws_.clear();
  for (const BodyBox* b : sorted) {
    const GLint first = static_cast<GLint>(positions.size());
    boxTriangles(*b, positions, normals);
    if (!draws_.empty() && draws_.back().albedo == b->albedo)
      draws_.back().count += static_cast<GLsizei>(positions.size()) - first;
    else
      draws_.push_back({first, static_cast<GLsizei>(positions.size()) - first, b->albedo});
  }
  std::vector<VenueVertex> verts(positions.size());
  for (size_t i = 0; i < verts.size(); ++i) verts[i] = {positions[i], normals[i], 0.0f, 0.0f};
  vertexCount_ = static_cast<GLsizei>(verts.size());
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(verts.size() * sizeof(VenueVertex));
  if (bytes == 0) return;
  if (bytes > capacityBytes_) {
    // A new buffer (of the next power of two) only when the rig grows: moving heads rewrite it.
    capacityBytes_ = std::max<GLsizeiptr>(bytes, 2 * capacityBytes_);
    vertices_ = gl::Buffer("body_vertices");
    glNamedBufferStorage(vertices_.id(), capacityBytes_, nullptr, GL_DYNAMIC_STORAGE_BIT);
    setVenueVertexLayout(vao_.id(), vertices_.id());
  }
  glNamedBufferSubData(vertices_.id(), 0, bytes, verts.data());
}

void GpuBodies::bind() const { glBindVertexArray(vao_.id()); }
void GpuBodies::draw(const Draw& d) const { glDrawArrays(GL_TRIANGLES, d.first, d.count); }
void GpuBodies::drawAll() const { glDrawArrays(GL_TRIANGLES, 0, vertexCount_); }

void GpuBodies::drawMeshes(GLuint program, GLint baseColorLocation) const {
  if (meshDraws_.empty()) return;
  for (const MeshDraw& d : meshDraws_) {
    glProgramUniformMatrix4fv(program, HAZE_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(d.model));
    if (baseColorLocation >= 0) {
      const glm::vec4 albedo(d.albedo, 1.0f);
      glProgramUniform4fv(program, baseColorLocation, 1, glm::value_ptr(albedo));
    }
    glBindVertexArray(d.buffers->vao.id());
    glDrawElements(GL_TRIANGLES, d.buffers->indexCount, GL_UNSIGNED_INT, nullptr);
  }
  const glm::mat4 identity(1.0f);
  glProgramUniformMatrix4fv(program, HAZE_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(identity));
}

}  // namespace haze
