#include "renderer/gpu_bodies.h"

#include <algorithm>
#include <cstddef>
#include <tuple>

#include "renderer/gpu_venue.h"

namespace haze {

void GpuBodies::update(const std::vector<BodyBox>& boxes) {
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

}  // namespace haze
