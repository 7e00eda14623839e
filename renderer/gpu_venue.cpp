#include "renderer/gpu_venue.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include "shaders/interface.h"

namespace haze {
namespace {

static_assert(sizeof(VenueVertex) == 32, "venue vertex layout is read by venue.vert.glsl");

// The vertex array's one buffer binding point (a C++-side slot, not a shader interface).
constexpr GLuint kVertexBufferBinding = 0;

}  // namespace

void setVenueVertexLayout(GLuint vao, GLuint buffer) {
  glVertexArrayVertexBuffer(vao, kVertexBufferBinding, buffer, 0, sizeof(VenueVertex));
  struct Attribute {
    GLuint location;
    GLint size;
    GLuint offset;
  };
  const Attribute attributes[] = {{HAZE_ATTR_POSITION, 3, offsetof(VenueVertex, position)},
                                  {HAZE_ATTR_NORMAL, 3, offsetof(VenueVertex, normal)},
                                  {HAZE_ATTR_UV, 2, offsetof(VenueVertex, u)}};
  for (const Attribute& a : attributes) {
    glEnableVertexArrayAttrib(vao, a.location);
    glVertexArrayAttribFormat(vao, a.location, a.size, GL_FLOAT, GL_FALSE, a.offset);
    glVertexArrayAttribBinding(vao, a.location, kVertexBufferBinding);
  }
}

GpuVenue::GpuVenue(const Venue& venue, bool cullChunks)
    : cullChunks_(cullChunks), boundsMin_(venue.boundsMin), boundsMax_(venue.boundsMax) {
  std::vector<VenueVertex> verts;
  std::vector<uint32_t> idx;
  std::vector<std::vector<uint32_t>> byMaterial(std::max<size_t>(venue.materials.size(), 1));
  for (const Primitive& p : venue.primitives) {
    const uint32_t base = static_cast<uint32_t>(verts.size());
    for (size_t i = 0; i < p.positions.size(); ++i) {
      const glm::vec2 uv = p.uvs.empty() ? glm::vec2(0.0f) : p.uvs[i];
      verts.push_back({p.positions[i], p.normals[i], uv.x, uv.y});
    }
    const size_t m = p.material >= 0 && static_cast<size_t>(p.material) < venue.materials.size()
                         ? static_cast<size_t>(p.material)
                         : 0;  // the default material
    for (uint32_t i : p.indices) byMaterial[m].push_back(base + i);
  }
  for (size_t m = 0; m < byMaterial.size(); ++m) {
    if (byMaterial[m].empty()) continue;
    draws_.push_back({static_cast<GLsizei>(byMaterial[m].size()), idx.size() * sizeof(uint32_t), 0, static_cast<int>(m)});
    idx.insert(idx.end(), byMaterial[m].begin(), byMaterial[m].end());
  }
  indexCount_ = static_cast<GLsizei>(idx.size());
  glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(verts.size() * sizeof(VenueVertex)), verts.data(), 0);
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(idx.size() * sizeof(uint32_t)), idx.data(), 0);
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  setVenueVertexLayout(vao_.id(), vertices_.id());
  makeChunks(verts, idx);

  for (const Texture& t : venue.textures) {
    gl::Texture tex(GL_TEXTURE_2D, "venue_texture " + t.name);
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(t.width, t.height))));
    glTextureStorage2D(tex.id(), levels, t.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, t.width, t.height);
    glTextureSubImage2D(tex.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba8.data());
    glGenerateTextureMipmap(tex.id());
    glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    textures_.push_back(std::move(tex));
  }
  for (const Material& m : venue.materials)
    materials_.push_back({m.baseColor, m.emissive, m.baseColorTexture, m.emissiveTexture});
}

void GpuVenue::makeChunks(const std::vector<VenueVertex>& verts, const std::vector<uint32_t>& idx) {
  // Triangles by the cell of a kCells^3 grid over their centroids' bounds that holds their centroid.
  constexpr int kCells = 8;
  const size_t triangles = idx.size() / 3;
  if (triangles == 0) return;
  auto centroid = [&](size_t t) {
    return (verts[idx[3 * t]].position + verts[idx[3 * t + 1]].position + verts[idx[3 * t + 2]].position) / 3.0f;
  };
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (size_t t = 0; t < triangles; ++t) {
    lo = glm::min(lo, centroid(t));
    hi = glm::max(hi, centroid(t));
  }
  const glm::vec3 extent = glm::max(hi - lo, glm::vec3(1e-6f));
  std::vector<std::vector<uint32_t>> cells(kCells * kCells * kCells);
  for (size_t t = 0; t < triangles; ++t) {
    const glm::ivec3 c = glm::clamp(glm::ivec3((centroid(t) - lo) / extent * static_cast<float>(kCells)), 0, kCells - 1);
    std::vector<uint32_t>& cell = cells[static_cast<size_t>((c.z * kCells + c.y) * kCells + c.x)];
    cell.insert(cell.end(), idx.begin() + static_cast<std::ptrdiff_t>(3 * t), idx.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  std::vector<uint32_t> sorted;
  sorted.reserve(idx.size());
  for (const std::vector<uint32_t>& cell : cells) {
    if (cell.empty()) continue;
    Chunk chunk{static_cast<GLsizei>(cell.size()), sorted.size(), glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (uint32_t i : cell) {
      chunk.boundsMin = glm::min(chunk.boundsMin, verts[i].position);
      chunk.boundsMax = glm::max(chunk.boundsMax, verts[i].position);
    }
    chunks_.push_back(chunk);
    sorted.insert(sorted.end(), cell.begin(), cell.end());
  }
  glNamedBufferStorage(chunkIndices_.id(), static_cast<GLsizeiptr>(sorted.size() * sizeof(uint32_t)), sorted.data(), 0);
  glVertexArrayElementBuffer(chunkVao_.id(), chunkIndices_.id());
  setVenueVertexLayout(chunkVao_.id(), vertices_.id());
}

size_t GpuVenue::drawInside(const glm::mat4& viewProj) const {
  glBindVertexArray(chunkVao_.id());
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  const size_t drawn = rangesInside(viewProj, counts, offsets);
  if (!counts.empty())
    glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), static_cast<GLsizei>(counts.size()));
  return drawn;
}

size_t GpuVenue::trianglesInside(const glm::mat4& viewProj) const {
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  return rangesInside(viewProj, counts, offsets);
}

size_t GpuVenue::rangesInside(const glm::mat4& viewProj, std::vector<GLsizei>& counts,
                              std::vector<const void*>& offsets) const {
  size_t indices = 0;
  for (const Chunk& c : chunks_) {
    if (cullChunks_) {
      // Outside when all eight corners lie beyond one clip plane.
      int outside[6] = {0, 0, 0, 0, 0, 0};
      for (int k = 0; k < 8; ++k) {
        const glm::vec4 p = viewProj * glm::vec4((k & 1) ? c.boundsMax.x : c.boundsMin.x,
                                                 (k & 2) ? c.boundsMax.y : c.boundsMin.y,
                                                 (k & 4) ? c.boundsMax.z : c.boundsMin.z, 1.0f);
        outside[0] += p.x < -p.w;
        outside[1] += p.x > p.w;
        outside[2] += p.y < -p.w;
        outside[3] += p.y > p.w;
        outside[4] += p.z < -p.w;
        outside[5] += p.z > p.w;
      }
      if (std::find(std::begin(outside), std::end(outside), 8) != std::end(outside)) continue;
    }
    const void* offset = reinterpret_cast<const void*>(c.firstIndex * sizeof(uint32_t));
    // Chunks that follow each other in the buffer become one range.
    if (!counts.empty() && reinterpret_cast<size_t>(offsets.back()) + static_cast<size_t>(counts.back()) * sizeof(uint32_t) ==
                               c.firstIndex * sizeof(uint32_t))
      counts.back() += c.indexCount;
    else {
      counts.push_back(c.indexCount);
      offsets.push_back(offset);
    }
    indices += static_cast<size_t>(c.indexCount);
  }
  return indices / 3;
}

void GpuVenue::bind() const { glBindVertexArray(vao_.id()); }

void GpuVenue::drawAll() const {
  if (indexCount_ > 0) glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

void GpuVenue::draw(const Draw& d) const {
  glDrawElementsBaseVertex(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(d.firstIndexBytes), d.baseVertex);
}

}  // namespace haze
