#include "renderer/gpu_bodies.h"

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "renderer/gpu_venue.h"
#include "shaders/interface.h"

namespace haze {
namespace {

// Whether every edge (positions welded exactly) is shared by two triangles running it in
// opposite directions, and the signed volume's sign (true: outward, counter-clockwise).
std::pair<bool, bool> closedShell(const TriangleMesh& m) {
  std::map<std::tuple<float, float, float>, uint32_t> weld;
  std::vector<uint32_t> id(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3& p = m.positions[i];
    id[i] = weld.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<uint32_t>(weld.size())).first->second;
  }
  std::map<std::pair<uint32_t, uint32_t>, int> edges;  // directed edge -> count
  double volume = 0.0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const uint32_t a = id[m.indices[t]], b = id[m.indices[t + 1]], c = id[m.indices[t + 2]];
    if (a == b || b == c || c == a) continue;  // degenerate: no area, no edge
    for (auto e : {std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a)}) ++edges[e];
    const glm::dvec3 p0(m.positions[m.indices[t]]), p1(m.positions[m.indices[t + 1]]), p2(m.positions[m.indices[t + 2]]);
    volume += glm::dot(p0, glm::cross(p1, p2));
  }
  if (edges.empty()) return {false, true};
  for (const auto& [e, n] : edges) {
    if (n != 1) return {false, true};
    auto back = edges.find({e.second, e.first});
    if (back == edges.end() || back->second != 1) return {false, true};
  }
  return {true, volume > 0.0};
}

}  // namespace

void GpuBodies::update(const std::vector<BodyBox>& boxes, const std::vector<BodyMesh>& meshes) {
  // Meshes: each distinct one uploaded once, in its part's frame.
  meshDraws_.clear();
  meshDrawOf_.assign(meshes.size(), -1);
  for (const BodyMesh& bm : meshes) {
    if (!bm.mesh || bm.mesh->indices.empty()) continue;
    meshDrawOf_[static_cast<size_t>(&bm - meshes.data())] = static_cast<int>(meshDraws_.size());
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
      std::tie(slot->closed, slot->outward) = closedShell(m);
      slot->center = 0.5f * (m.boundsMin + m.boundsMax);
      slot->radius = 0.5f * glm::length(m.boundsMax - m.boundsMin);
    }
    glm::mat4 model(bm.axes);
    model[3] = glm::vec4(bm.originM, 1.0f);
    meshDraws_.push_back({slot.get(), model, bm.albedo, glm::determinant(bm.axes) < 0.0f});
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
  boxFirst_.assign(boxes.size(), 0);
  for (const BodyBox* b : sorted) {
    const GLint first = static_cast<GLint>(positions.size());
    boxFirst_[static_cast<size_t>(b - boxes.data())] = first;
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

void GpuBodies::drawCasters(GLuint program, const std::vector<int>& boxes, const std::vector<int>& meshes) const {
  if (!boxes.empty() && vertexCount_ > 0) {
    bind();
    for (int k : boxes) glDrawArrays(GL_TRIANGLES, boxFirst_[static_cast<size_t>(k)], 36);
  }
  bool placed = false;
  for (int k : meshes) {
    const int d = meshDrawOf_[static_cast<size_t>(k)];
    if (d < 0) continue;
    const MeshDraw& draw = meshDraws_[static_cast<size_t>(d)];
    glProgramUniformMatrix4fv(program, HAZE_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(draw.model));
    glBindVertexArray(draw.buffers->vao.id());
    glDrawElements(GL_TRIANGLES, draw.buffers->indexCount, GL_UNSIGNED_INT, nullptr);
    placed = true;
  }
  if (placed) {
    const glm::mat4 identity(1.0f);
    glProgramUniformMatrix4fv(program, HAZE_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(identity));
  }
}

void GpuBodies::drawMeshes(GLuint program, GLint baseColorLocation, const Camera* camera) const {
  meshesDrawn_ = 0;
  if (meshDraws_.empty()) return;
  // The frustum's planes (Gribb and Hartmann): a sphere wholly on the outside of one is unseen.
  glm::vec4 planes[6];
  if (camera) {
    const glm::mat4 t = glm::transpose(camera->viewProj);
    for (int i = 0; i < 3; ++i) {
      planes[2 * i] = t[3] + t[i];
      planes[2 * i + 1] = t[3] - t[i];
    }
    for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
  }
  bool culling = false;
  for (const MeshDraw& d : meshDraws_) {
    bool cull = false;
    if (camera) {
      const glm::vec3 c(d.model * glm::vec4(d.buffers->center, 1.0f));
      const float r = d.buffers->radius;
      bool outside = false;
      for (const glm::vec4& p : planes) outside = outside || glm::dot(glm::vec3(p), c) + p.w < -r;
      if (outside) continue;
      cull = d.buffers->closed && glm::length(camera->eye - c) > r;
    }
    if (cull != culling) {
      (cull ? glEnable : glDisable)(GL_CULL_FACE);
      culling = cull;
    }
    if (cull) glCullFace(d.buffers->outward != d.mirrored ? GL_BACK : GL_FRONT);
    ++meshesDrawn_;
    glProgramUniformMatrix4fv(program, HAZE_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(d.model));
    if (baseColorLocation >= 0) {
      const glm::vec4 albedo(d.albedo, 1.0f);
      glProgramUniform4fv(program, baseColorLocation, 1, glm::value_ptr(albedo));
    }
    glBindVertexArray(d.buffers->vao.id());
    glDrawElements(GL_TRIANGLES, d.buffers->indexCount, GL_UNSIGNED_INT, nullptr);
  }
  if (culling) glDisable(GL_CULL_FACE);  // surfaces are two-sided (docs/physics.md)
  const glm::mat4 identity(1.0f);
  glProgramUniformMatrix4fv(program, HAZE_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(identity));
}

}  // namespace haze
